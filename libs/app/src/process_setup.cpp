#include "aula/app/process_setup.hpp"

#include <aula/sandbox/forbidden_calls.hpp>
#include <aula/sandbox/sandbox.hpp>

#include <fstream>

#include <aula/config/paths.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/process/signal_watcher.hpp>
#include <aula/lcm/log_replay.hpp>
#include <aula/settings/tables.hpp>

#include <cstdlib>
#include <iostream>

namespace aula::app {

namespace {

// In a graded run's sandbox the component runs only the grade's algorithm (sandbox.hpp). True in
// a graded run's sandbox. Another is the student's code starting the component again with another
// algorithm (the reference): the run ends with that reason, flagged on the launcher's private line.
bool requireGradedAlgorithm(const config::Config& cfg, const config::CommandLine& command_line, const std::string& section,
                            const std::string& program) {
  std::ifstream graded(sandbox::kGradedAlgorithmFile);
  std::string algorithm;
  if (!graded || !std::getline(graded, algorithm)) return false;
  const std::string key = section + ".Algorithm";
  if (cfg.getString(key) == algorithm) return true;
  if (command_line.flag("crash-fd")) {
    sandbox::endForForbiddenTry(static_cast<int>(command_line.optionDouble("crash-fd", -1)), program,
                                "run the component again with " + key + "=" + cfg.getString(key));
  }
  throw config::ConfigError(cfg.origin(key) + ": " + key + " = " + cfg.getString(key) +
                            ": a graded run's component runs only the grade's algorithm (" + algorithm + ")");
}

// A graded component's watch on the system calls only an escape needs, said on the launcher's
// private line (forbidden_calls.hpp), from before the student's plugin is loaded.
void watchForbiddenCalls(const config::CommandLine& command_line, const std::string& program) {
  if (!command_line.flag("crash-fd")) return;
  const std::string why = sandbox::watchForbiddenCalls(static_cast<int>(command_line.optionDouble("crash-fd", -1)));
  if (!why.empty()) std::cerr << program << ": " << why << ": forbidden system calls are refused, not flagged" << std::endl;
}

}  // namespace
namespace {

bool haveDisplay() {
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && *value != '\0') return true;
  }
  return false;
}

}  // namespace

ProcessSetup ProcessSetup::fromArgs(int argc, const char* const* argv, const std::string& program,
                                    const std::vector<std::string>& extra_options, const std::string& usage,
                                    bool opens_window) {
  const config::SettingsTable& table = settings::tableOf(program);
  const settings::Exercise* exercise = settings::exerciseOfProgram(program);
  std::vector<std::string> takes_value = {"config", "lcm-url"};
  std::vector<std::string> known = {"config", "lcm-url", "headless", "help", "control-fd"};
  known.insert(known.end(), extra_options.begin(), extra_options.end());
  if (exercise != nullptr && exercise->referee == program) known.insert(known.end(), {"replay", "key-fd", "isolation"});
  // aula replay's windows: the component's shows and cannot act; neither watches its peers.
  if (exercise != nullptr && (exercise->component == program || exercise->referee == program)) known.push_back("view-only");
  // The launcher's private line for a crash's one line (crash_report.hpp).
  // And a graded run's key for its lockstep client (auth::clientKey).
  if (exercise != nullptr && exercise->component == program) known.insert(known.end(), {"crash-fd", "lockstep-key-fd"});
  ProcessSetup setup;
  setup.program = program;
  setup.command_line = config::CommandLine::parse(argc, argv, takes_value);
  if (setup.command_line.flag("help")) {
    std::cout << usage << "\nSettings (in the .cfg, or --Key=value on the command line):\n" << table.help();
    throw HelpShown();
  }
  setup.command_line.requireKnown(known);
  if (!setup.command_line.positional.empty()) {
    throw config::ConfigError("command line: unexpected argument '" + setup.command_line.positional.front() + "'");
  }
  // A referee grading a recorded run has no window and no simulator: it reads the log.
  const bool replay = setup.command_line.flag("replay");
  if (replay) lcmbus::requireLog(setup.command_line.option("replay"));
  setup.headless = setup.command_line.flag("headless") || replay;
  // Before any thread starts (Qt's, TBB's): only the watcher ever takes a stop signal, headless
  // (runHeadless) or with a window (BusPump, which closes it).
  if (setup.headless || opens_window) process::blockStopSignals();
  if (opens_window && !setup.headless && !haveDisplay()) {
    throw config::ConfigError("no display (DISPLAY is not set): use --headless");
  }

  setup.cfg_path = setup.command_line.option("config", exercise != nullptr ? config::dataPath(exercise->config_file) : "");
  config::Config file = setup.cfg_path.empty() ? config::Config() : config::Config::fromFile(setup.cfg_path);
  // Command-line keys must be this program's own; the .cfg may also hold its siblings' keys.
  config::Config overrides;
  setup.command_line.applyOverrides(overrides);
  table.resolve(overrides);
  file.merge(overrides);
  std::vector<const config::SettingsTable*> siblings;
  if (exercise != nullptr) {
    for (const auto* t : exercise->tables()) {
      if (t != &table) siblings.push_back(t);
    }
  }
  setup.cfg = table.resolve(file, siblings);
  if (exercise != nullptr && exercise->component == program &&
      requireGradedAlgorithm(setup.cfg, setup.command_line, exercise->section, program) &&
      !setup.cfg.getBool("Component.OwnProcess")) {  // else the algorithm's own process watches (algorithm_box.hpp)
    watchForbiddenCalls(setup.command_line, program);
  }

  if (exercise != nullptr) {
    const std::string key = exercise->section + ".World";
    setup.world = world::loadWorld(config::resolveWorldPath(setup.cfg.getString(key), setup.cfg.origin(key) + ": " + key));
    std::cerr << program << ": world " << setup.world.source_path << " (sha256 " << setup.world.sha256.substr(0, 12)
              << ")" << std::endl;
  }
  if (setup.command_line.flag("key-fd")) {
    setup.run_key = auth::readKey(static_cast<int>(setup.command_line.optionDouble("key-fd", -1)), "--key-fd");
  }
  if (setup.command_line.flag("lockstep-key-fd")) {  // good for one client of one run: the process may stay dumpable
    setup.lockstep_key =
        auth::readKey(static_cast<int>(setup.command_line.optionDouble("lockstep-key-fd", -1)), "--lockstep-key-fd", false);
  }
  setup.bus = lcmbus::openBus(replay ? lcmbus::kReplayUrl : lcmbus::resolveUrl(setup.command_line, setup.cfg));
  return setup;
}

}  // namespace aula::app
