#include "aula/grade/grade_command.hpp"

#include <aula/grade/grade_worlds.hpp>

#include <aula/grade/grade_plan.hpp>
#include <aula/grade/grade_runner.hpp>
#include <aula/grade/grades.hpp>
#include <aula/grade/lms_export.hpp>
#include <aula/process/child_process.hpp>
#include <aula/process/exit_codes.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <unistd.h>

namespace aula::grade {
namespace fs = std::filesystem;
using config::ConfigError;

namespace {

// Prints the grades; the exit code: 1 when a run never completed (the machine's reason on every
// try), which the grade leaves out and the same command runs again.
int printGrades(const std::vector<StudentGrade>& grades, const std::string& out_dir) {
  std::printf("%-20s %7s %7s %7s %9s\n", "student", "median", "min", "max", "failed");
  int incomplete = 0;
  for (const auto& g : grades) {
    const std::string tampered = g.runs_tampered > 0 ? " TAMPERING in " + std::to_string(g.runs_tampered) + " runs;" : "";
    std::printf("%-20s %7.2f %7.2f %7.2f %5d/%-3d%s %s\n", (g.name.empty() ? g.student : g.name).c_str(), g.median, g.min, g.max, g.runs_failed, g.runs,
                tampered.c_str(), g.failures.substr(0, 80).c_str());
    incomplete += g.runs_incomplete;
  }
  std::printf("grades: %s/grades.csv, %s/report.html\n", out_dir.c_str(), out_dir.c_str());
  const fs::path lms = fs::path(out_dir) / "lms-grades.csv";
  if (fs::exists(lms)) {
    std::printf("for the LMS: %s%s (docs/grading.md, \"From your LMS and back\")\n", lms.string().c_str(),
                fs::exists(fs::path(out_dir) / "lms-feedback.zip") ? ", lms-feedback.zip" : "");
  }
  if (incomplete == 0) return 0;
  std::fflush(stdout);
  std::cerr << "aula grade: " << incomplete << " run(s) did not complete, for the machine's reason on every try (left out "
            << "of the marks; grades.csv names them in 'incomplete'): run the same command again\n";
  return process::kExitFailed;
}

std::string formatDuration(double seconds) {
  const int s = static_cast<int>(seconds + 0.5);
  char text[32];
  std::snprintf(text, sizeof text, "%d:%02d", s / 60, s % 60);
  return text;
}

void runLocally(const Manifest& manifest, int jobs) {
  const bool terminal = ::isatty(STDOUT_FILENO) != 0;
  const auto started = std::chrono::steady_clock::now();
  const auto skipped = std::count_if(manifest.runs.begin(), manifest.runs.end(), upToDate);
  if (skipped > 0) std::cout << skipped << " runs already done (same plugin, world, seed and settings): skipped\n" << std::flush;
  runLocal(manifest, jobs, [&](const PlannedRun& run, const nlohmann::ordered_json& result, const Progress& p) {    const std::string failure = failureOf(result);
    if (terminal) {
      const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      const int ran = p.done - p.skipped;
      const double eta_s = ran > 0 ? elapsed_s / ran * (p.total - p.done) : 0;
      std::cout << "\r  " << p.done << "/" << p.total << " runs, " << p.failed << " failed, ETA "
                << formatDuration(eta_s) << "   " << std::flush;
      if (p.done == p.total) std::cout << "\n";
    } else {
      char mark[32];
      std::snprintf(mark, sizeof mark, "%.2f", result.value("mark", 0.0));
      std::cout << "[" << p.done << "/" << p.total << "] " << run.student << " " << run.world_name << " seed " << run.seed
                << ": " << mark << (failure.empty() ? "" : "  FAILED: " + failure) << "\n"
                << std::flush;
    }
  });
}

// Slurm: one array task per run still to do; `sbatch --wait` returns when all are over.
void runOnSlurm(const Manifest& manifest, const std::string& manifest_path, const std::string& bin_dir) {
  std::string indices;
  for (const PlannedRun& run : manifest.runs) {
    if (!upToDate(run)) indices += (indices.empty() ? "" : ",") + std::to_string(run.index);
  }
  if (indices.empty()) {
    std::cout << "every run is already done (same plugin, world, seed and settings)\n";
    return;
  }
  const fs::path slurm_dir = fs::path(manifest.out_dir) / "slurm";
  fs::create_directories(slurm_dir);
  const fs::path script = fs::path(manifest.out_dir) / "grade.sbatch";
  {
    std::ofstream out(script);
    out << "#!/bin/sh\n"
        << "# aula grade: one Slurm array task per run of " << manifest_path << "\n"
        << "#SBATCH --job-name=aula-grade\n"
        << "#SBATCH --array=" << indices << "\n"
        << "#SBATCH --cpus-per-task=1\n"
        << "#SBATCH --output=" << (slurm_dir / "task-%a.out").string() << "\n"
        << "exec \"" << bin_dir << "/aula\" grade-task \"" << manifest_path << "\" \"$SLURM_ARRAY_TASK_ID\"\n";
    if (!out) throw ConfigError("aula grade: cannot write " + script.string());
  }
  std::cout << "slurm: submitting " << script.string() << " (manifest " << manifest_path << ")\n" << std::flush;
  const std::string sbatch_log = (slurm_dir / "sbatch.log").string();
  process::ChildProcess sbatch({"sbatch", "--wait", "--parsable", script.string()}, sbatch_log, sbatch_log);
  int code = -1;
  for (;;) {
    if (const auto done = sbatch.wait(std::chrono::milliseconds(500))) {
      code = *done;
      break;
    }
  }
  if (code == 127) throw ConfigError("aula grade --engine=slurm: sbatch not found (is Slurm installed and on PATH?)");
  if (code != 0) {
    std::ifstream in(sbatch_log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::cerr << "aula grade: sbatch exited with code " << code << ": " << text
              << "collecting what the tasks wrote (aula grade --collect " << manifest.out_dir << ")\n";
  }
}

// The out folder took no more (GradeStopped): grades.csv from the runs that finished, if there is
// room for it, and how to go on. Exit 1: the grade is not complete.
int reportStopped(const GradeStopped& stop, const Manifest& manifest) {
  const auto finished = std::count_if(manifest.runs.begin(), manifest.runs.end(), upToDate);
  const auto total = static_cast<long>(manifest.runs.size());
  std::cout << std::flush;
  std::cerr << "\naula grade: stopped after " << finished << " of " << total << " runs: " << stop.what() << "\n"
            << std::flush;
  try {
    (void)printGrades(collect(manifest.out_dir), manifest.out_dir);
    std::cerr << "aula grade: grades.csv and report.html hold the " << finished << " finished runs only\n";
  } catch (const std::runtime_error& e) {
    std::cerr << "aula grade: no grades.csv either: " << e.what() << "\n"
              << "once there is room: aula grade --collect=" << manifest.out_dir << "\n";
  }
  std::cerr << "aula grade: every finished run keeps its result; once there is room, the same command does the other "
            << total - finished << "\n";
  return process::kExitFailed;
}

// With similarity on, the algorithms a submission may be a copy of run on the same worlds and
// seeds: the exercise's built-ins, and the teacher's --known solutions (compiled as a class of
// their own, in OUT/known/build).
void addKnownAlgorithms(const GradeRequest& request, const std::string& prefix, std::vector<Submission>& submissions) {
  const auto builtins = builtInAlgorithms(request.exercise);
  submissions.insert(submissions.end(), builtins.begin(), builtins.end());
  if (request.known.empty()) return;
  GradeRequest known = request;
  known.submissions = request.known;
  known.out_dir = (fs::path(request.out_dir) / "known").string();
  auto solutions = compileSubmissions(known, prefix);
  for (const Submission& s : solutions) {
    if (!s.compile_error.empty()) std::cout << "  known " << s.student << ": " << s.compile_error << "\n";
  }
  markKnown(solutions);
  submissions.insert(submissions.end(), solutions.begin(), solutions.end());
}

}  // namespace

int gradeClass(const GradeRequest& asked, const std::string& bin_dir) {
  GradeRequest request = asked;
  fs::create_directories(request.out_dir);
  // The students as given: an LMS's export read into hand-ins, each staged into OUT/hand-ins
  // (before the worlds: an export that does not read stops the grade before any calibration).
  std::vector<std::string> folders;
  const std::vector<Student> students_given =
      readHandIns(request.submissions, request.lms, request.out_dir, request.hand_in_limits, folders);
  request.submissions = folders;
  for (size_t i = 0; i < students_given.size(); ++i) {
    if (!students_given[i].refused.empty()) request.refused_hand_ins[folders[i]] = students_given[i].refused;
  }
  saveStudents(request.out_dir, students_given, request.lms_assignment);
  if (request.similarity_auto) request.similarity = request.submissions.size() >= 3;
  prepareWorlds(request, bin_dir);  // generated and calibrated before any student's run
  const std::string prefix = fs::path(bin_dir).parent_path().string();
  std::cout << "compiling " << request.submissions.size() << " submission(s) into " << request.out_dir << "/build\n"
            << std::flush;
  auto submissions = compileSubmissions(request, prefix);
  for (const Submission& s : submissions) {
    if (!s.compile_error.empty()) std::cout << "  " << s.student << ": " << s.compile_error << "\n";
  }
  // A refused hand-in is never read again: its code is not compared (a sparse MyAlgorithm.cpp would
  // be read whole by the comparison), here nor by a later --collect (the manifest's folders).
  std::vector<std::string> compared;
  for (const std::string& folder : request.submissions) {
    if (request.refused_hand_ins.count(folder) == 0 && checkHandIn({{folder, ""}}, request.hand_in_limits).empty()) {
      compared.push_back(folder);
    }
  }
  request.submissions = compared;
  const size_t students = submissions.size();
  if (request.similarity) addKnownAlgorithms(request, prefix, submissions);
  const Manifest manifest = planRuns(request, submissions, bin_dir);
  const std::string manifest_path = (fs::path(request.out_dir) / "manifest.json").string();
  manifest.save(manifest_path);
  std::cout << manifest.runs.size() << " runs: " << submissions.size() << " submission(s) x " << request.worlds.size()
            << " world(s) x " << request.seeds.size() << " seed(s), engine " << request.engine;
  if (submissions.size() > students) {
    std::cout << " (" << submissions.size() - students << " of them known algorithms, for similarity: never graded)";
  }
  std::cout << "\n" << std::flush;
  if (request.engine == "slurm") {
    runOnSlurm(manifest, manifest_path, bin_dir);
  } else {
    try {
      runLocally(manifest, request.jobs);
    } catch (const GradeStopped& stop) {
      return reportStopped(stop, manifest);
    }
  }
  if (!request.keep_builds) dropBuildTrees(request.out_dir);
  const int code = printGrades(collect(request.out_dir, request.similarity ? request.submissions : std::vector<std::string>{},
                                       request.exercise, request.similarity_rules, request.known),
                               request.out_dir);
  if (request.similarity) std::printf("similar work: %s/similarity.csv (flagged pairs in report.html)\n", request.out_dir.c_str());
  return code;
}

int gradeTask(const std::string& manifest_path, const std::string& text) {
  const Manifest manifest = Manifest::load(manifest_path);
  size_t used = 0;
  int index = -1;
  try {
    index = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || index < 0 || index >= static_cast<int>(manifest.runs.size())) {
    throw ConfigError("aula grade-task: INDEX '" + text + "' is not a run of " + manifest_path + " (0-" +
                      std::to_string(manifest.runs.size() - 1) + ")");
  }
  const auto result = runOne(manifest.runs[index]);
  const std::string failure = failureOf(result);
  std::cout << manifest.runs[index].student << " " << manifest.runs[index].world_name << " seed "
            << manifest.runs[index].seed << ": " << result.value("mark", 0.0)
            << (failure.empty() ? "" : "  FAILED: " + failure) << "\n";
  return 0;  // a failed run is a result, not a failed task
}

int collectGrades(const std::string& dir) {
  if (dir.empty() || !fs::is_directory(fs::path(dir) / "runs")) {
    throw ConfigError("aula grade --collect=" + dir + ": no runs/ folder there (the --out of aula grade)");
  }
  // The class is compared as the grade would have (its manifest keeps the folders and rules).
  const fs::path manifest_path = fs::path(dir) / "manifest.json";
  if (!fs::exists(manifest_path)) return printGrades(collect(dir), dir);
  const Manifest manifest = Manifest::load(manifest_path.string());
  const bool similarity = manifest.similarity_rules.has_value();
  const int code = printGrades(collect(dir, manifest.submissions, manifest.exercise,
                                       manifest.similarity_rules.value_or(SimilarityRules{}), manifest.known),
                               dir);
  if (similarity) std::printf("similar work: %s/similarity.csv (flagged pairs in report.html)\n", dir.c_str());
  return code;
}

}  // namespace aula::grade
