#include "aula/app/process_setup.hpp"

#include <aula/lcm/bus.hpp>
#include <aula/world/world_spec.hpp>

#include <iostream>

namespace aula::app {

ProcessSetup ProcessSetup::fromArgs(int argc, const char* const* argv, const std::string& default_cfg,
                                    const std::vector<std::string>& extra_options) {
  std::vector<std::string> takes_value = {"config", "lcm-url"};
  std::vector<std::string> known = {"config", "lcm-url", "headless", "help"};
  known.insert(known.end(), extra_options.begin(), extra_options.end());
  ProcessSetup setup;
  setup.command_line = config::CommandLine::parse(argc, argv, takes_value);
  setup.command_line.requireKnown(known);
  if (!setup.command_line.positional.empty()) {
    throw config::ConfigError("command line: unexpected argument '" +
                              setup.command_line.positional.front() + "'");
  }
  setup.cfg_path = setup.command_line.option("config", std::string(AULA_SOURCE_DIR) + "/" + default_cfg);
  setup.cfg = config::Config::fromFile(setup.cfg_path);
  setup.command_line.applyOverrides(setup.cfg);
  setup.headless = setup.command_line.flag("headless");
  setup.bus = lcmbus::openBus(lcmbus::resolveUrl(setup.command_line, setup.cfg));
  return setup;
}

std::string sourcePath(const config::Config& cfg, const std::string& key, const std::string& fallback) {
  const std::string path = cfg.getString(key, fallback);
  return !path.empty() && path[0] == '/' ? path : std::string(AULA_SOURCE_DIR) + "/" + path;
}

int guardedMain(const std::string& program, const std::function<int()>& body) {
  try {
    return body();
  } catch (const config::ConfigError& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 2;
  } catch (const world::WorldError& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace aula::app
