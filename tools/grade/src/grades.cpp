#include "aula/grade/grades.hpp"

#include "aula/grade/student_page.hpp"
#include "similarity_sources.hpp"

#include <aula/version.hpp>

#include <aula/config/paths.hpp>
#include <aula/grade/grade_plan.hpp>
#include <aula/grade/grade_runner.hpp>
#include <aula/grade/lms_export.hpp>
#include <aula/grade/report_html.hpp>
#include <aula/grade/run_page.hpp>
#include <aula/grade/similarity.hpp>
#include <aula/grade/submission_build.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <unistd.h>

namespace aula::grade {
namespace fs = std::filesystem;

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c == '\n' ? ' ' : c;
  }
  return quoted + "\"";
}

std::string gradedWorldOf(const nlohmann::json& result) {
  return fs::path(result.value("graded_world", result.value("world", std::string("?")))).stem().string();
}

std::string twoDecimals(double value) {
  if (!std::isfinite(value)) return "";  // no run measured it
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::vector<nlohmann::json> readResults(const std::string& out_dir, const std::string& folder) {
  std::vector<fs::path> files;
  const fs::path runs = fs::path(out_dir) / folder;
  if (fs::is_directory(runs)) {
    for (auto it = fs::recursive_directory_iterator(runs); it != fs::recursive_directory_iterator(); ++it) {
      const fs::directory_entry& entry = *it;
      const std::string name = entry.path().filename().string();
      if (folder == "known" && it.depth() == 0 && entry.is_directory() && name == "build") {
        it.disable_recursion_pending();  // OUT/known/build: the teacher's solutions' builds, not runs
        continue;
      }
      const bool result = entry.is_regular_file() && entry.path().extension() == ".json" &&
                          name.find(".report.json") == std::string::npos && name.find(".trace.json") == std::string::npos;
      if (result) files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<nlohmann::json> results;
  for (const auto& file : files) {
    // A half-written file cannot exist (results are renamed into place): one that does not read is
    // damaged, and a grade without it would be silently short of a run.
    try {
      results.push_back(nlohmann::json::parse(config::readSmallFile(file.string(), 64u << 20, "run result")));
    } catch (const nlohmann::json::exception& e) {
      throw config::ConfigError("run result " + file.string() + ": not a result (" + e.what() +
                                "); remove it and resume the grade to run it again");
    }
  }
  return results;
}

namespace {

// One student's runs, as they are read.
struct Runs {
  std::string language;
  std::vector<double> marks;
  std::map<std::string, std::vector<double>> by_world;
  std::map<std::string, std::vector<double>> by_measure;
  std::map<std::string, int> failures;
  std::map<std::string, int> retries;  // why runs were tried again
  std::vector<std::string> incomplete;
  int failed = 0;
  int tampered = 0;
  int retried = 0;
};

// "reason (x2); other reason", the reasons sorted.
std::string counted(const std::map<std::string, int>& reasons) {
  std::string text;
  for (const auto& [reason, count] : reasons) {
    text += (text.empty() ? "" : "; ") + reason + (count > 1 ? " (x" + std::to_string(count) + ")" : "");
  }
  return text;
}

// Adds result `r` to its student's runs; new worlds and measures (as the reports name them, first
// seen first) join the lists.
void addRun(const nlohmann::json& r, Runs& runs, std::set<std::string>& worlds, std::vector<std::string>& measures) {
  const double mark = r.value("mark", 0.0);
  const std::string world = gradedWorldOf(r);
  if (runs.language.empty()) runs.language = r.value("language", std::string());
  worlds.insert(world);
  if (r.contains("retried_because") && r["retried_because"].is_array()) {
    ++runs.retried;
    for (const auto& why : r["retried_because"]) {
      if (why.is_string()) ++runs.retries[why.get<std::string>()];
    }
  }
  // Never completed, for the machine's reason on every try: no mark, no 0 in the medians.
  if (!machineFailureOf(r).empty()) {
    runs.incomplete.push_back(world + " seed " + std::to_string(r.value("seed", 0LL)));
    return;
  }
  runs.marks.push_back(mark);
  runs.by_world[world].push_back(mark);
  if (r.contains("measures") && r["measures"].is_array()) {
    for (const auto& name : r["measures"]) {
      if (!name.is_string()) continue;
      const std::string measure = name.get<std::string>();
      if (std::find(measures.begin(), measures.end(), measure) == measures.end()) measures.push_back(measure);
      if (r.contains(measure) && r[measure].is_number()) runs.by_measure[measure].push_back(r[measure].get<double>());
    }
  }
  if (!tamperingOf(r).empty()) ++runs.tampered;
  const std::string failure = failureOf(r);
  if (failure.empty()) return;
  ++runs.failed;
  ++runs.failures[failure];
}

StudentGrade gradeOf(const std::string& student, Runs& runs, const std::set<std::string>& worlds,
                     const std::vector<std::string>& measures) {
  StudentGrade g;
  g.student = student;
  g.language = runs.language;
  g.median = median(runs.marks);
  g.min = runs.marks.empty() ? 0.0 : *std::min_element(runs.marks.begin(), runs.marks.end());
  g.max = runs.marks.empty() ? 0.0 : *std::max_element(runs.marks.begin(), runs.marks.end());
  for (const std::string& world : worlds) {
    const auto it = runs.by_world.find(world);
    g.world_medians.emplace_back(world, it == runs.by_world.end() ? 0.0 : median(it->second));
  }
  for (const std::string& measure : measures) {
    const auto it = runs.by_measure.find(measure);
    g.measure_medians.emplace_back(measure, it == runs.by_measure.end() ? std::nan("") : median(it->second));
  }
  g.runs = static_cast<int>(runs.marks.size());
  g.runs_failed = runs.failed;
  g.runs_tampered = runs.tampered;
  g.runs_retried = runs.retried;
  g.runs_incomplete = static_cast<int>(runs.incomplete.size());
  g.failures = counted(runs.failures);
  g.retries = counted(runs.retries);
  for (const std::string& run : runs.incomplete) g.incomplete += (g.incomplete.empty() ? "" : "; ") + run;
  return g;
}

}  // namespace

std::vector<StudentGrade> gradeStudents(const std::vector<nlohmann::json>& results) {
  std::map<std::string, Runs> students;
  std::set<std::string> worlds;
  std::vector<std::string> measures;
  for (const auto& r : results) addRun(r, students[r.value("student", "?")], worlds, measures);
  std::vector<StudentGrade> grades;
  for (auto& [student, runs] : students) grades.push_back(gradeOf(student, runs, worlds, measures));
  return grades;
}

std::string gradesCsv(const std::vector<StudentGrade>& grades) {
  std::string csv = "student,lms_id,median,min,max";
  if (!grades.empty()) {
    for (const auto& [world, value] : grades.front().world_medians) csv += ",median_" + csvField(world);
    for (const auto& [measure, value] : grades.front().measure_medians) csv += ",median_" + csvField(measure);
  }
  csv += ",runs,runs_failed,runs_tampered,runs_retried,runs_incomplete,failures,retries,incomplete,language,hand_in,aula_version\n";
  for (const StudentGrade& g : grades) {
    csv += csvField(g.name.empty() ? g.student : g.name) + "," + csvField(g.lms_id);
    csv += "," + twoDecimals(g.median) + "," + twoDecimals(g.min) + "," + twoDecimals(g.max);
    for (const auto& [world, value] : g.world_medians) csv += "," + twoDecimals(value);
    for (const auto& [measure, value] : g.measure_medians) csv += "," + twoDecimals(value);
    csv += "," + std::to_string(g.runs) + "," + std::to_string(g.runs_failed) + "," + std::to_string(g.runs_tampered) + "," +
           std::to_string(g.runs_retried) + "," + std::to_string(g.runs_incomplete) + "," + csvField(g.failures) + "," +
           csvField(g.retries) + "," + csvField(g.incomplete) + "," + csvField(g.language) + "," + csvField(g.hand_in) + "," +
           kVersion + "\n";
  }
  return csv;
}

std::vector<StudentGrade> collect(const std::string& out_dir, const std::vector<std::string>& submissions,
                                  const std::string& exercise, const SimilarityRules& rules,
                                  const std::vector<std::string>& known) {
  auto results = readResults(out_dir);
  auto grades = gradeStudents(results);
  // Who each folder is, as the LMS's export named them: the rows, the pages and the report say it.
  const auto students = loadStudents(out_dir);
  for (StudentGrade& g : grades) {
    const auto s = students.find(g.student);
    if (s == students.end()) continue;
    g.name = s->second.name;
    g.lms_id = s->second.lms_id;
    g.hand_in = s->second.hand_in;
  }
  for (auto& r : results) {
    const auto s = students.find(r.value("student", std::string()));
    if (s == students.end()) continue;
    r["student_name"] = s->second.name;
    if (!s->second.hand_in.empty()) r["hand_in"] = s->second.hand_in;
  }
  // The grades first: on a disk with little room left, they are what matters most.
  config::writeFileAtomically((fs::path(out_dir) / "grades.csv").string(), gradesCsv(grades), "the grades");
  const std::string similar = submissions.empty() ? "" : compareSubmissions(out_dir, submissions, exercise, results, rules, known);
  config::writeFileAtomically((fs::path(out_dir) / "report.html").string(), reportHtml(grades, results, similar), "the class report");
  // A page per run, beside its result, for the teacher to hand to that student alone: with only
  // what is theirs (student_page.hpp: no quote of the world, no teacher's folder, their text capped).
  const WorldTexts world_texts(out_dir);
  for (const auto& r : results) {
    if (!r.contains("log") || !r["log"].is_string()) continue;
    fs::path page = r["log"].get<std::string>();
    page.replace_extension(".html");
    // The picture in the palette of its 256 most frequent colours, at zlib's best, once: the
    // class report shows it, the page links it (or inlines it, when it has no run to play).
    const std::string png = fs::path(page).replace_extension(".png").string();
    if (fs::is_regular_file(png)) {
      const std::string picture = config::readSmallFile(png, 64u << 20, "the run's picture");
      const std::string smaller = palettePng(picture);
      if (smaller.size() < picture.size()) config::writeFileAtomically(png, smaller, "the run's picture");
    }
    const RunFiles referees = runFilesOf(r);
    const RunFiles theirs = forTheStudent(referees, world_texts.ofRun(r["log"].get<std::string>()));
    config::writeFileAtomically(page.string(), runPageHtml(theirs), "the run's page");
    // One copy of the trace: the page's, when it is the referee's byte for byte (run_page.hpp).
    keepOneTrace(fs::path(page).replace_extension().string(),
                 !referees.trace_json.empty() && withoutPaths(theirs.trace_json) == referees.trace_json);
  }
  // The known algorithms' runs have no page: their traces kept compact for the comparison.
  if (!submissions.empty()) {
    for (const auto& r : readResults(out_dir, "known")) {
      if (r.contains("log") && r["log"].is_string()) keepOneTrace(fs::path(r["log"].get<std::string>()).replace_extension().string(), false);
    }
  }
  writeLmsFiles(out_dir, grades);  // after the pages: Moodle's feedback zip holds them
  return grades;
}

}  // namespace aula::grade
