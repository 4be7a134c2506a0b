#pragma once
// What every component and referee process does first: parse the command line, load its .cfg
// (plus --Key=value overrides) and check it against the program's declared settings
// (aula_settings), load the exercise's world, open the LCM bus. Errors are ConfigError or
// WorldError (exit code 2) or BusError (exit code 1), each naming the file, line, key or URL.

#include <aula/auth/run_key.hpp>
#include <aula/config/config.hpp>
#include <aula/process/guarded_main.hpp>
#include <aula/world/world_spec.hpp>

#include <aula/lcm/bus.hpp>
#include <lcm/lcm-cpp.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace aula::app {

// The process skeleton lives in aula_process (no Qt); these names stay for the components' and
// referees' main().
using process::guardedMain;
using process::HelpShown;

struct ProcessSetup {
  std::string program;                 // "vacuum-cleaner"
  config::CommandLine command_line;
  config::Config cfg;                  // the effective settings: every declared key
  std::string cfg_path;
  world::WorldSpec world;              // <Section>.World, with every model resolved
  std::unique_ptr<lcmbus::Bus> bus;
  bool headless = false;
  // A referee's --key-fd=N: the graded run's key from the launcher (nothing in a run without
  // one: windows, three terminals, a regrade).
  std::optional<auth::Key> run_key;
  // A component's --lockstep-key-fd=N: in a graded run, the key of its lockstep client only
  // (aula_auth's clientKey), never the run's.
  std::optional<auth::Key> lockstep_key;

  // Options every process accepts: --config=FILE, --headless, --lcm-url=URL, --help, plus
  // `extra_options` (e.g. "report", "screenshot"); a referee also takes --replay=FILE.lcmlog
  // (headless, its bus the log: aula_lcm's log_replay.hpp). The default .cfg is the exercise's, in the
  // data folder. `usage` is the first lines of --help. Throws HelpShown after printing --help.
  static ProcessSetup fromArgs(int argc, const char* const* argv, const std::string& program,
                               const std::vector<std::string>& extra_options, const std::string& usage,
                               bool opens_window = true);
};

}  // namespace aula::app
