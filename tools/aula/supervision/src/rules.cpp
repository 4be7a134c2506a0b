#include "aula/supervision/rules.hpp"

#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>
#include <aula/process/cpu_affinity.hpp>
#include <aula/process/exit_codes.hpp>
#include <aula/process/machine_reason.hpp>
#include <aula/version.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace aula::supervision {

double defaultWallBudget(double episode_sim_s, double rtf) {
  return 60.0 + 1.5 * episode_sim_s / (rtf > 0 ? std::min(rtf, 1.0) : 1.0);
}

int chooseCpu(const std::string& choice, const std::vector<int>& allowed, int current) {
  if (choice == "any" || allowed.empty()) return -1;
  if (choice == "auto") return current;
  char* end = nullptr;
  const long asked = std::strtol(choice.c_str(), &end, 10);
  if (choice.empty() || *end != '\0' || std::find(allowed.begin(), allowed.end(), asked) == allowed.end()) {
    throw config::ConfigError("--cpu=" + choice + ": one of the CPUs this process may use (" +
                              process::cpuList(allowed) + "), auto or any");
  }
  return static_cast<int>(asked);
}

std::string signalName(int code) {
  if (code <= 128) return "exit code " + std::to_string(code);
  const char* name = sigabbrev_np(code - 128);
  return std::string("SIG") + (name != nullptr ? name : std::to_string(code - 128));
}

const int kComponentKilledFromOutside = 128 + SIGKILL;

std::string componentFault(int code) {
  if (code == process::kExitAlgorithmHung) return "a call into the algorithm overran its budget";
  if (code == process::kExitAlgorithmExited) return "the algorithm ended the component (exit() inside execute())";
  if (code == process::kExitAlgorithmForbidden) return "the algorithm tried what no student's algorithm may";
  if (code == 128 + SIGXFSZ) return "the algorithm wrote a file larger than the sandbox allows (SIGXFSZ)";
  // A forbidden call tried with SIGSYS blocked: the kernel ends the process (forbidden_calls.hpp).
  if (code == 128 + SIGSYS) return "the algorithm made a system call the sandbox forbids (SIGSYS)";
  // SIGKILL is never the sandbox's own limit (those end a run with their reason first), nor a
  // crash, nor the algorithm's process (it may signal no process but its own and its children:
  // sandbox/forbidden_calls.hpp): someone outside the run killed it (the out-of-memory killer).
  if (code == kComponentKilledFromOutside) return process::machineReason("the component was killed (SIGKILL) from outside the run");
  if (code > 128) return "component crashed (" + signalName(code) + ")";
  return "";
}

std::string crashInStudentLines(const std::string& fault, const std::string& crash_line) {
  const std::string component = "component ";
  if (fault.rfind(component + "crashed (", 0) != 0) return "";
  const std::string said = fault.substr(component.size()) + " at ";
  // The line is the student's process's: it is believed for the same signal only, and kept short.
  if (crash_line.rfind(said, 0) != 0 || crash_line.size() == said.size()) return "";
  return component + crash_line.substr(0, 300);
}

// A headless component ends only when it is told to, or with a code that says why: exit code 0
// in the middle of a run is the algorithm's doing, by a way round the component's exit() watch.
const char* const kAlgorithmEndedMidRun =
    "the algorithm ended the component (exit code 0 in the middle of the run: _exit(), quick_exit() or exit() "
    "outside a call into it)";

ExitVerdict onExit(const ExitEvent& e, const std::string& program) {
  ExitVerdict v;
  const bool component = e.role == Role::Component, referee = e.role == Role::Referee;
  if (e.role == Role::Simulator && e.simulator_ended_run) return v;  // the referee grades and ends the run
  // The simulator died (killed from outside, the out-of-memory killer): not the student's doing.
  // The referee grades what there is and says why; the run is run again by a grade.
  if (e.has_referee && e.role == Role::Simulator && e.code != 0 && !e.referee_told) {
    v.tell_referee = process::machineReason(program + (e.code > 128 ? " died (" + signalName(e.code) + ")"
                                                                   : " exited with code " + std::to_string(e.code)));
    v.message = v.tell_referee;
    v.result = 1;
    v.machine = true;
    return v;
  }
  if (e.has_referee && referee && e.code > 128) {
    v.aborted_report = process::machineReason(program + " died (" + signalName(e.code) + ")");
    v.message = v.aborted_report + ": the run has no mark";
    v.result = 1;
    v.run_over = true;
    v.machine = true;
    return v;
  }
  v.discard = e.has_referee && !referee && e.code == process::kExitUsage;
  if (e.has_referee && component && e.code == 0 && !e.headless) {
    v.message = "the component's window was closed: stopping the run";
    v.run_over = true;
    return v;
  }
  std::string fault = e.has_referee && component ? componentFault(e.code) : "";
  // Which budget, as the component's watchdog said it on its private line.
  const std::string overran = "overran ";
  if (!fault.empty() && e.code == process::kExitAlgorithmHung && e.crash_line.rfind(overran, 0) == 0) {
    fault = e.crash_line.substr(overran.size(), 300);
  }
  if (e.has_referee && component && e.headless && e.code == 0) fault = kAlgorithmEndedMidRun;
  // What it tried, as the component's tripwire said it on its private line (flagged there too).
  if (!fault.empty() && e.code == process::kExitAlgorithmForbidden && !e.refused.empty()) {
    fault = "the algorithm tried to " + e.refused.substr(0, 200) + ", which no student's algorithm may";
  }
  if (!fault.empty() && !e.referee_told) {
    v.tell_referee = fault;
    v.algorithm_fault = crashInStudentLines(fault, e.crash_line);
    v.result = 1;
    v.machine = component && e.code == kComponentKilledFromOutside;
    return v;  // the referee grades what there is and ends the run
  }
  const bool faulted_component = e.referee_told && component;
  if (e.has_referee && referee && e.code == process::kExitFailed) {
    v.message = "the run ended before its end: the referee's report says why";
    v.result = 1;
  } else if (e.code != 0 && !faulted_component) {
    v.message = program + " exited with code " + std::to_string(e.code);
    v.result = e.code == process::kExitUsage ? process::kExitUsage : 1;
  }
  v.run_over = (e.code != 0 && !faulted_component) || e.last_child || e.role == Role::Simulator;
  return v;
}

std::string staleBuild(const std::string& plugin_path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path plugin(plugin_path);
  if (plugin.extension() != ".so") return "";
  std::ifstream cache(plugin.parent_path() / "CMakeCache.txt");
  std::string line, project;
  while (std::getline(cache, line)) {
    if (line.rfind("CMAKE_HOME_DIRECTORY:INTERNAL=", 0) == 0) project = line.substr(line.find('=') + 1);
  }
  const auto built = fs::last_write_time(plugin, error);
  if (project.empty() || error) return "";
  for (const auto& entry : fs::directory_iterator(project, error)) {
    const std::string ext = entry.path().extension().string();
    const bool source = ext == ".cpp" || ext == ".hpp" || ext == ".h" || entry.path().filename() == "CMakeLists.txt";
    if (source && entry.last_write_time(error) > built) {
      return entry.path().string() + " changed after " + plugin.filename().string() +
             " was built: the last build failed or did not run (cmake --build " + plugin.parent_path().string() + ")";
    }
  }
  return "";
}

std::string limitPassed(const sandbox::Limits& limits, uint64_t output_bytes, const std::vector<pid_t>* processes) {
  if (output_bytes > limits.output_bytes) {
    return "the algorithm printed more than " + std::to_string(limits.output_bytes >> 20) + " MB (stdout and stderr)";
  }
  if (processes == nullptr) return "";
  const int started = static_cast<int>(processes->size()) - limits.aula_processes;
  if (started > limits.processes) return "the algorithm started more than " + std::to_string(limits.processes) + " processes";
  if (started > 0 && sandbox::memoryOf(*processes) > limits.memory_bytes) {
    return "the algorithm used more than " + std::to_string(limits.memory_bytes >> 20) + " MB of memory (its processes together)";
  }
  return "";
}

void writeAbortedReport(const std::string& report_path, const std::string& exercise, const std::string& algorithm,
                        const std::string& why) {
  if (report_path.empty()) return;
  config::writeFileAtomically(report_path, abortedReport(exercise, algorithm, why).dump(2) + "\n", "report");
}

nlohmann::ordered_json abortedReport(const std::string& exercise, const std::string& algorithm, const std::string& why) {
  nlohmann::ordered_json report;
  report["exercise"] = exercise;
  report["aula_version"] = kVersion;
  report["finished"] = false;
  report["algorithm"] = algorithm;
  report["aborted"] = why;
  return report;
}

}  // namespace aula::supervision
