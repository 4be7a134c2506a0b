#pragma once
// The rules of a supervised run, as plain functions: how long a headless run may take, which
// CPU its processes share, what a process's exit code means, and the report written for a
// referee that cannot write its own.

#include <aula/sandbox/sandbox.hpp>

#include <nlohmann/json.hpp>

#include <sys/types.h>

#include <optional>
#include <string>
#include <vector>

namespace aula::supervision {

// A headless run's wall-clock budget when --timeout does not say: the episode's sim length at
// real time (or slower, at an --rtf below 1), half again, plus a minute for start-up. 0 rtf: as
// fast as possible (budgeted at real time). A run past it is stuck.
double defaultWallBudget(double episode_sim_s, double rtf);

// The CPU a headless run's processes share: "auto" (the one the launcher runs on), "any" (-1:
// wherever the kernel puts them) or a CPU number among `allowed`; `current` is the launcher's.
// Throws config::ConfigError naming the allowed CPUs.
int chooseCpu(const std::string& choice, const std::vector<int>& allowed, int current);

// "SIGSEGV" for a death by signal (exit code 128 + N), else "exit code N".
std::string signalName(int code);
// "component crashed (SIGSEGV)", "a call into the algorithm overran its budget", or "" when the
// component's exit is not the student's doing.
std::string componentFault(int code);
// The component's exit code when it was killed from outside the run (SIGKILL): the machine's reason.
extern const int kComponentKilledFromOutside;

// "component crashed (SIGSEGV) at MyAlgorithm.cpp:14 (MyAlgorithm::execute)": the `fault` the
// exit code gives, where the component's own crash line (its --crash-fd) says where the same
// signal struck; "" when it does not (no line, another signal, no student's line found).
std::string crashInStudentLines(const std::string& fault, const std::string& crash_line);

// The three processes of a run, by their place in Supervision::lines.
enum class Role { Simulator = 0, Component = 1, Referee = 2 };

// What the supervisor knows when a child exits.
struct ExitEvent {
  Role role = Role::Simulator;
  int code = 0;
  bool has_referee = true;
  bool headless = true;
  bool referee_told = false;     // the referee was already told why the run ends
  bool simulator_ended_run = false;  // the simulator said why it ended a graded run
  bool last_child = false;
  std::string crash_line;            // what a component said of its crash (crash_report.hpp)
  std::string refused;               // the last try its watch refused ("call makeReferenceAlgorithm...")
};

// What it does about it.
struct ExitVerdict {
  bool run_over = false;
  std::optional<int> result;      // the launcher's exit code, when this exit sets it
  std::string tell_referee;       // a fault to hand the referee (it grades what there is)
  std::string algorithm_fault;    // and before it, the fault in the student's lines ("" when unknown)
  std::string aborted_report;     // the referee died: write a report with this reason, no mark
  bool discard = false;           // the run never started: the referee gives no mark
  std::string message;            // one line for the terminal ("" for none)
  // The launcher saw a process of Aula's end from outside the run (killed, died): the machine's
  // reason (process/machine_reason.hpp), decided here and never read back from any text.
  bool machine = false;
};

// A graded (headless, refereed) component that exits 0 before the referee was told why the run
// ends was ended by the algorithm (_exit(), quick_exit(), exit() from a thread of its own): the
// referee is told so (kAlgorithmEndedMidRun), not left to find the component silent.
extern const char* const kAlgorithmEndedMidRun;
// A budget overrun's reason is the component's own line ("overran execute() used more than 2 s of
// CPU time ..."), when it said one.
ExitVerdict onExit(const ExitEvent& event, const std::string& program);

// Why a student's plugin is older than its sources ("" when it is not, or when its build folder
// names no sources): the build's CMakeCache.txt names the project; any of its C++ sources or its
// CMakeLists.txt changed after the plugin was built means the build failed or was not run.
std::string staleBuild(const std::string& plugin_path);

// Why a sandboxed component is past a limit the launcher counts, or "": its output (stdout and
// stderr), its processes (bubblewrap's two aside) and, with processes of its own, their memory
// together (each is held by its own address-space limit too). `processes`: the component's
// process tree, or nullptr when it was not looked at this time.
std::string limitPassed(const sandbox::Limits& limits, uint64_t output_bytes, const std::vector<pid_t>* processes);

// The report of a run whose referee cannot write one: no mark, and why.
nlohmann::ordered_json abortedReport(const std::string& exercise, const std::string& algorithm, const std::string& why);
// That report, written at `report_path` (atomically; "" for none).
void writeAbortedReport(const std::string& report_path, const std::string& exercise, const std::string& algorithm,
                        const std::string& why);

}  // namespace aula::supervision
