#pragma once
// What every component and referee process does first: parse the command line, load its .cfg
// (plus --Key=value overrides), open the LCM bus. Errors are ConfigError (exit code 2) or
// BusError (exit code 1), each naming the file, key or URL.

#include <aula/config/config.hpp>

#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace aula::app {

struct ProcessSetup {
  config::CommandLine command_line;
  config::Config cfg;
  std::string cfg_path;
  std::unique_ptr<lcm::LCM> bus;
  bool headless = false;

  // Options every process accepts: --config=FILE, --headless, --lcm-url=URL, --help,
  // plus `extra_options` (e.g. "report", "screenshot"). `default_cfg` is relative to the
  // source tree (e.g. "config/teleTaxi.cfg").
  static ProcessSetup fromArgs(int argc, const char* const* argv, const std::string& default_cfg,
                               const std::vector<std::string>& extra_options = {});
};

// Runs `body` and maps Aula's errors to exit codes with a message prefixed by `program`:
// ConfigError and WorldError -> 2, anything else -> 1.
int guardedMain(const std::string& program, const std::function<int()>& body);

// A path from a .cfg key: absolute as given, else relative to the source tree (where worlds/,
// config/ live), so a process finds it from any working directory.
std::string sourcePath(const config::Config& cfg, const std::string& key, const std::string& fallback);

}  // namespace aula::app
