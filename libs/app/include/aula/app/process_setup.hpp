#pragma once
// What every component and referee process does first: parse the command line, load its .cfg
// (plus --Key=value overrides) and check it against the program's declared settings
// (aula_settings), load the exercise's world, open the LCM bus. Errors are ConfigError or
// WorldError (exit code 2) or BusError (exit code 1), each naming the file, line, key or URL.

#include <aula/config/config.hpp>
#include <aula/world/world_spec.hpp>

#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace aula::app {

// `--help` was asked for and printed: the process ends with exit code 0.
class HelpShown : public std::runtime_error {
 public:
  HelpShown() : std::runtime_error("help shown") {}
};

struct ProcessSetup {
  std::string program;                 // "vacuum-cleaner"
  config::CommandLine command_line;
  config::Config cfg;                  // the effective settings: every declared key
  std::string cfg_path;
  world::WorldSpec world;              // <Section>.World, with every model resolved
  std::unique_ptr<lcm::LCM> bus;
  bool headless = false;

  // Options every process accepts: --config=FILE, --headless, --lcm-url=URL, --help, plus
  // `extra_options` (e.g. "report", "screenshot"). The default .cfg is the exercise's, in the
  // data folder. `usage` is the first lines of --help. Throws HelpShown after printing --help.
  static ProcessSetup fromArgs(int argc, const char* const* argv, const std::string& program,
                               const std::vector<std::string>& extra_options, const std::string& usage,
                               bool opens_window = true);
};

// Runs `body` and maps Aula's errors to exit codes with a message prefixed by `program`:
// HelpShown -> 0; ConfigError and WorldError -> 2; anything else -> 1.
int guardedMain(const std::string& program, const std::function<int()>& body);

}  // namespace aula::app
