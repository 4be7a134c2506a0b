#include "aula/grade/report_html.hpp"

#include "report_parts.hpp"

#include "report_page_assets.hpp"

#include <aula/grade/calibration.hpp>

#include <aula/grade/grade_runner.hpp>
#include <aula/grade/run_page.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace aula::grade {
namespace fs = std::filesystem;

namespace {

// "coverage_percent 63.21, ..." for one run: the raw measures its report names.
std::string measuresOf(const nlohmann::json& result) {
  std::string out;
  if (!result.contains("measures") || !result["measures"].is_array()) return out;
  for (const auto& name : result["measures"]) {
    if (!name.is_string() || !result.contains(name.get<std::string>())) continue;
    const auto& value = result[name.get<std::string>()];
    if (!value.is_number()) continue;
    out += (out.empty() ? "" : ", ") + name.get<std::string>() + " " + twoDecimals(value.get<double>());
  }
  return out;
}

// The rubric presets the reports were graded with ("default"; "default, original" if mixed).
std::string presetsOf(const std::vector<nlohmann::json>& results) {
  std::set<std::string> presets;
  for (const auto& r : results) {
    if (r.contains("rubric") && r["rubric"].is_object()) presets.insert(r["rubric"].value("preset", "?"));
  }
  std::string out;
  for (const std::string& p : presets) out += (out.empty() ? "" : ", ") + p;
  return out;
}

// A world's calibration as its runs' reports name it: the file, and the measure's values that are
// worth a 5 (the baseline's median) and a 10 (the anchor's), as (mark, label) lines.
std::pair<std::string, std::vector<std::pair<double, std::string>>> calibrationOf(const nlohmann::json& r) {
  std::pair<std::string, std::vector<std::pair<double, std::string>>> c;
  const auto spec = calibrationSpecOf(r.value("exercise", std::string()));
  if (!spec || !r.contains("rubric") || !r["rubric"].contains("calibration")) return c;
  c.first = r["rubric"]["calibration"].get<std::string>();
  const size_t anchor = spec->baseline.empty() ? 0 : 1;  // a scale of one point is the anchor's
  for (size_t i = 0; i < spec->rubric_keys.size(); ++i) {
    const auto& value = r["rubric"].value(spec->rubric_keys[i], nlohmann::json());
    const std::string role = i == anchor ? "10: the anchor's median, " : "5: the baseline's median, ";
    if (value.is_number()) c.second.emplace_back(i == anchor ? 10.0 : 5.0, role + spec->measure + " " + twoDecimals(value.get<double>()));
  }
  return c;
}

// A run's id in the page ("alice/vacuum-seed3"): its card, its data block, `#run=`.
std::string runId(const nlohmann::json& r) {
  return r.value("student", std::string("?")) + "/" + gradedWorldOf(r) + "-seed" +
         std::to_string(r.value("seed", 0LL));
}

// Flagged: anything the report says went wrong or was refused (runDiagnostics), not only a failure.
bool flagged(const nlohmann::json& r) { return !runDiagnostics(r).empty(); }

// The run's files beside report.html (the layout collect writes: runs/<student>/<world>-seed<k>.*),
// relative to it: "runs/alice/vacuum-seed1" for a result whose log is ".../runs/alice/vacuum-seed1.log".
std::string relativeStem(const nlohmann::json& r) {
  if (!r.contains("log") || !r["log"].is_string()) return "";
  fs::path log = r["log"].get<std::string>();
  log.replace_extension();
  return "runs/" + log.parent_path().filename().string() + "/" + log.filename().string();
}

// The page's head and its first paragraph: how many students, runs, failures and forgeries.
void writeHead(std::ostringstream& html, const std::vector<StudentGrade>& grades, const std::vector<nlohmann::json>& results) {
  std::string exercise;  // from any referee's report (a run that never started has none)
  int failed = 0;
  int tampered = 0;
  int diagnosed = 0;
  for (const auto& r : results) {
    diagnosed += flagged(r) ? 1 : 0;
    if (exercise.empty()) exercise = r.value("exercise", "");
    failed += failureOf(r).empty() ? 0 : 1;
    tampered += tamperingOf(r).empty() ? 0 : 1;
  }
  html << "<!DOCTYPE html>\n<html lang='en'><head><meta charset='utf-8'>"
       << "<meta name='viewport' content='width=device-width, initial-scale=1'>" << noNetworkPolicy() << "<title>Aula grades: "
       << escapeHtml(exercise) << "</title><style>" << kStyle << "</style></head><body>\n"
       << "<h1>Aula grades: " << escapeHtml(exercise) << "</h1>\n<p>" << grades.size() << " students, " << results.size()
       << " runs, " << failed << " failed"
       << (tampered > 0 ? ", " + std::to_string(tampered) + " with tampering (forged messages or forbidden system calls, refused)" : "")
       << ", " << diagnosed << " flagged (any diagnostic: a failure, non-finite commands, tampering, lost messages...)"
       << ". The mark of a student is the median over every world and seed"
       << (presetsOf(results).empty() ? std::string() : "; the referee's rubric: " + escapeHtml(presetsOf(results)))
       << ". Beside it, the median of each raw measure. Open a run to watch it and see where its points went.</p>\n";
}

// The overview: the class's medians, then each world's marks over all its runs.
void writeOverview(std::ostringstream& html, const std::vector<StudentGrade>& grades, const std::vector<nlohmann::json>& results) {
  std::vector<double> medians;
  for (const auto& g : grades) medians.push_back(g.median);
  std::map<std::string, std::vector<double>> by_world;
  std::map<std::string, nlohmann::json> a_run_of;  // its calibration, as the runs' reports name it
  for (const auto& r : results) {
    const std::string world = gradedWorldOf(r);
    by_world[world].push_back(r.value("mark", 0.0));
    a_run_of.emplace(world, r);
  }
  html << "<h2>Overview</h2>\n<div class='worlds'><div><b>the class</b><br>" << histogramSvg(medians, "median mark of a student")
       << "</div>";
  for (const auto& [world, marks] : by_world) {
    const auto [file, lines] = calibrationOf(a_run_of[world]);
    html << "<div><b>" << escapeHtml(world) << "</b>: " << marks.size() << " runs, median " << twoDecimals(median(marks))
         << (file.empty() ? std::string() : ", calibrated (" + escapeHtml(file) + ")") << "<br>"
         << histogramSvg(marks, "mark of a run", lines) << "</div>";
  }
  html << "</div>\n";
}

// Each student's runs' diagnostic kinds ("failed, non-finite commands"): the table's flags.
std::map<std::string, std::string> flagsByStudent(const std::vector<nlohmann::json>& results) {
  std::map<std::string, std::set<std::string>> kinds;
  for (const auto& r : results) {
    for (const Diagnostic& d : runDiagnostics(r)) kinds[r.value("student", std::string("?"))].insert(d.kind);
  }
  std::map<std::string, std::string> out;
  for (const auto& [student, set] : kinds) {
    for (const std::string& kind : set) out[student] += (out[student].empty() ? "" : ", ") + kind;
  }
  return out;
}

// The students' table, sortable and filtered in the page.
void writeStudents(std::ostringstream& html, const std::vector<StudentGrade>& grades, const std::vector<nlohmann::json>& results) {
  const auto flags = flagsByStudent(results);
  html << "<div class='filter'><label>student <input id='filter-text' type='search' placeholder='name'></label> "
       << "<label><input id='filter-flagged' type='checkbox'> flagged only (failed, tampered, or any other diagnostic)</label></div>\n"
       << "<div class='table-box'><table class='sortable students'><thead><tr><th>student</th><th>median</th><th>spread</th><th>min</th><th>max</th>";
  if (!grades.empty()) {
    for (const auto& [world, value] : grades.front().world_medians) html << "<th>" << escapeHtml(world) << "</th>";
    for (const auto& [measure, value] : grades.front().measure_medians) html << "<th>" << escapeHtml(measure) << "</th>";
  }
  html << "<th>language</th><th>runs</th><th>failed</th><th>tampered</th><th>flags</th><th>why</th></tr></thead><tbody>\n";
  for (const auto& g : grades) {
    const auto flag = flags.find(g.student);
    const bool is_flagged = g.runs_failed > 0 || g.runs_tampered > 0 || flag != flags.end();
    html << "<tr data-student='" << escapeHtml(g.student) << "'" << (is_flagged ? " class='flagged'" : "")
         << "><td class='name'><a href='#" << escapeHtml(g.student) << "'>" << escapeHtml(g.name.empty() ? g.student : g.name)
         << "</a></td><td>"
         << twoDecimals(g.median) << "</td><td>" << twoDecimals(g.max - g.min) << "</td><td>" << twoDecimals(g.min) << "</td><td>"
         << twoDecimals(g.max) << "</td>";
    for (const auto& [world, value] : g.world_medians) html << "<td>" << twoDecimals(value) << "</td>";
    for (const auto& [measure, value] : g.measure_medians) html << "<td>" << twoDecimals(value) << "</td>";
    html << "<td>" << escapeHtml(g.language) << "</td><td>" << g.runs << "</td><td>" << g.runs_failed << "</td><td" << (g.runs_tampered > 0 ? " class='failed'" : "")
         << ">" << g.runs_tampered << "</td><td class='why'>" << whyCell(flag == flags.end() ? "" : flag->second)
         << "</td><td class='why'>" << whyCell(g.failures) << "</td></tr>\n";
  }
  html << "</tbody></table></div>\n";
}

// The flagged runs, each a link to its card.
void writeFlagged(std::ostringstream& html, const std::vector<nlohmann::json>& results) {
  std::vector<const nlohmann::json*> flagged_runs;
  for (const auto& r : results) {
    if (flagged(r)) flagged_runs.push_back(&r);
  }
  html << "<h3>Flagged runs (" << flagged_runs.size() << ")</h3>\n<ul class='flagged-runs'>";
  for (const nlohmann::json* r : flagged_runs) {
    std::string reason;
    for (const Diagnostic& d : runDiagnostics(*r)) reason += (reason.empty() ? "" : "; ") + d.text;
    html << "<li><a href='#card-" << escapeHtml(runId(*r)) << "'>" << escapeHtml(runId(*r)) << "</a>: " << escapeHtml(reason) << "</li>";
  }
  html << "</ul>\n";
}

// One run's card: its mark, measures, diagnostics, its player (its own page in a frame, made when
// opened), a link to that page and the referee's still picture, both files beside report.html
// (the picture loaded when its card comes near the screen, after the page's load). Neither is inlined: a class's pictures and
// traces would be most of the page, and each run's page has its trace already.
void writeCard(std::ostringstream& html, const nlohmann::json& r) {
  const std::string id = runId(r);
  const RunFiles files = runFilesOf(r);
  html << "<div class='run' id='card-" << escapeHtml(id) << "'><b>" << escapeHtml(gradedWorldOf(r))
       << ", seed " << r.value("seed", 0LL) << ": " << twoDecimals(r.value("mark", 0.0)) << "</b>";
  const std::string measures = measuresOf(r);
  if (!measures.empty()) html << "<div>" << escapeHtml(measures) << "</div>";
  html << diagnosticsHtml(runDiagnostics(r));
  const std::string stem = relativeStem(r);
  if (!files.trace_json.empty() && !stem.empty()) {
    html << "<div><button type='button' class='open-run' data-run='" << escapeHtml(id) << "' data-page='"
         << escapeHtml(urlPath(stem + ".html")) << "'>Watch the run</button></div>";
  }
  html << "<div class='watch'></div>";
  if (!stem.empty()) {
    html << "<div class='files'><a href='" << escapeHtml(urlPath(stem + ".html")) << "'>its page</a></div>";
    if (!files.picture_png.empty()) {
      const std::string png = escapeHtml(urlPath(stem + ".png"));
      html << "<a href='" << png << "'><img class='still' alt='the referee&#39;s picture of the run' data-src='" << png << "'></a>";
    }
  }
  html << "</div>\n";
}

void writeRuns(std::ostringstream& html, const std::vector<nlohmann::json>& results) {
  std::map<std::string, std::vector<const nlohmann::json*>> by_student;
  for (const auto& r : results) by_student[r.value("student", "?")].push_back(&r);
  for (const auto& [student, runs] : by_student) {
    bool any_flagged = false;
    for (const nlohmann::json* r : runs) any_flagged = any_flagged || flagged(*r);
    html << "<section class='student' data-student='" << escapeHtml(student) << "' data-flagged='" << (any_flagged ? "yes" : "no")
         << "'><h2 id='" << escapeHtml(student) << "'>" << escapeHtml(runs.front()->value("student_name", student)) << "</h2>\n";
    // What was handed in and what of it was graded (an LMS's export, a folder without MyAlgorithm).
    const std::string hand_in = runs.front()->value("hand_in", std::string());
    if (!hand_in.empty()) html << "<p class='hand-in'>" << escapeHtml(hand_in) << "</p>\n";
    html << "<div class='runs'>\n";
    for (const nlohmann::json* r : runs) writeCard(html, *r);
    html << "</div></section>\n";
  }
}

}  // namespace

std::string reportHtml(const std::vector<StudentGrade>& grades, const std::vector<nlohmann::json>& results,
                       const std::string& more) {
  std::ostringstream html;
  writeHead(html, grades, results);
  writeOverview(html, grades, results);
  writeStudents(html, grades, results);
  writeFlagged(html, results);
  html << more;
  writeRuns(html, results);
  html << "<script>" << kSortScript << "</script>\n</body></html>\n";
  return html.str();
}

}  // namespace aula::grade
