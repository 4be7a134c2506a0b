#pragma once
// The run's supervision: what `aula run` does once the settings are resolved. It starts the
// simulator, the component (sandboxed if asked) and the referee with their private lines, waits
// for the run to end and stops everything cleanly: it never leaves a process behind (children die
// with it: PR_SET_PDEATHSIG), explains every ending and exits non-zero if any process failed.
// The rules it follows (budgets, exit codes, the reports it writes for a referee that cannot)
// are plain functions in rules.hpp, unit-tested.

#include <aula/auth/run_key.hpp>
#include <aula/process/child_process.hpp>
#include <aula/sandbox/sandbox.hpp>

#include <optional>
#include <string>
#include <vector>

namespace aula::supervision {

// What the launcher knows of the run it supervises.
struct Supervision {
  std::vector<std::vector<std::string>> lines;  // simulator, component, referee
  bool has_referee = false;
  bool headless = false;
  bool sandbox = false;      // --sandbox: the component (the student's code) runs in aula_sandbox
  sandbox::Confinement confinement;  // what it sees there (componentConfinement)
  std::optional<auth::Key> key;      // a graded run's (headless, with a referee): the simulator's and referee's
  std::string component_client;      // the component's lockstep client ("vacuum-cleaner"): given its own key
  double wall_budget_s = 0;  // --timeout: the run's wall-clock budget (0: none)
  std::string exercise, report_path;
  std::string algorithm;               // what the component runs ("student", "libmy_algorithm.so")
  process::Placement placement;        // the three processes' CPU, batch when headless
  int watched_lcm_port = 0;            // in a private network: the run's LCM port, and datagrams to any
                                       // other are escape attempts (sandbox::DatagramWatch); 0: not watched
};

// Runs the processes until the primary one (the last: referee or client) ends, any fails, or
// Ctrl-C; then stops the clients first (they send their last commands and leave lockstep).
// When the component dies (a crash, a hung execute()), the referee is told over its private
// control pipe, grades what there is, writes its report and ends the run. Returns the exit code.
int supervise(const Supervision& run);

}  // namespace aula::supervision
