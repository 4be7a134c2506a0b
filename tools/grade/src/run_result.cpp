#include "run_result.hpp"

#include <aula/process/exit_codes.hpp>
#include <aula/process/machine_reason.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace aula::grade {
namespace fs = std::filesystem;

namespace {

// Why a run was refused (exit 2): the last line a process said that is its own error, not the
// launcher's or the referee's account of it ("no mark: the run never started (the reason is
// above)", "aula: ... exited with code 2") nor a process's world line.
std::string refusalOf(const std::string& log_path) {
  std::ifstream in(log_path);
  std::string line, reason;
  while (std::getline(in, line)) {
    if (line.empty() || line.rfind("aula", 0) == 0 || line.rfind("no mark:", 0) == 0) continue;
    if (line.find(": world ") != std::string::npos) continue;
    reason = line;
  }
  return reason.empty() ? lastLine(log_path) : reason;
}

}  // namespace

std::optional<nlohmann::ordered_json> readJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    return nlohmann::ordered_json::parse(in);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

std::string lastLine(const std::string& log_path) {
  std::ifstream in(log_path);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  return last;
}

nlohmann::ordered_json resultOf(const PlannedRun& run, std::optional<int> exit_code, bool timed_out, double wall_s) {
  nlohmann::ordered_json result;
  if (auto report = readJson(run.report_path)) {
    result = std::move(*report);
  } else {
    result["mark"] = 0.0;
    result["seed"] = run.seed;
    result["world"] = run.world_name;
    result["world_sha256"] = run.world_sha256;
    result["finished"] = false;
    result["algorithm"] = run.plugin.empty() ? "" : fs::path(run.plugin).filename().string();
  }
  result["student"] = run.student;
  result["language"] = run.language;
  if (!result.contains("world")) result["world"] = run.world_name;
  result["graded_world"] = run.world_name;  // a world's file, or one of its destinations ("city-plaza.world")
  result["plugin_sha256"] = run.plugin_sha256;
  result["settings"] = run.settings;
  result["wall_time_s"] = std::round(wall_s * 100) / 100;
  if (exit_code) result["exit_code"] = *exit_code;
  // The machine's reason is what this grade or the launcher saw for itself (machine_reason.hpp):
  // the grade's backstop, the launcher's exit code, a launcher killed or ending with no report, a
  // build stopped at its backstop. No text of a report, a log or a compiler decides it.
  std::string failure;
  bool machine = false;
  const bool launcher_killed = exit_code && *exit_code > 128;  // SIGKILL, SIGTERM from outside the grade
  if (!run.compile_error.empty()) {
    failure = run.compile_error;
    machine = run.build_machine;
  } else if (timed_out) {
    failure = process::machineReason("the grade's wall-clock backstop of " +
                                     std::to_string(static_cast<int>(run.wall_limit_s)) + " s ran out");
    machine = true;
  } else if (exit_code && (*exit_code == process::kExitMachine || launcher_killed)) {
    const std::string said = result.value("aborted", std::string());
    failure = process::saysMachineReason(said)
                  ? said
                  : process::machineReason("the run ended (exit " + std::to_string(*exit_code) + "): " + lastLine(run.log_path));
    machine = true;
  } else if (result.contains("algorithm_error")) {
    failure = result["algorithm_error"].get<std::string>();
  } else if (result.contains("aborted")) {
    failure = result["aborted"].get<std::string>();
  } else if (exit_code && *exit_code == 2) {
    failure = "refused: " + refusalOf(run.log_path);
  } else if (!exit_code || *exit_code != 0 || !fs::exists(run.report_path)) {
    // No report, no reason of the student's: the launcher itself failed or was killed.
    failure = process::machineReason("the run failed (exit " + (exit_code ? std::to_string(*exit_code) : std::string("?")) +
                                     "): " + lastLine(run.log_path));
    machine = true;
  }
  if (!failure.empty()) result["failure"] = failure;
  result["machine_reason"] = machine;  // this grade's own word, over any the report had
  result["log"] = run.log_path;
  return result;
}

}  // namespace aula::grade
