#include "run_settings.hpp"

#include <aula/config/paths.hpp>
#include <aula/grade/calibration.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/desktop/window_layout.hpp>
#include <aula/desktop/work_area.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/supervision/rules.hpp>
#include <aula/world/world_spec.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <optional>

namespace aula::commands {
using config::Config;
using config::ConfigError;
using config::SettingsTable;

namespace {

// Every override must be some process's key; the "did you mean" comes from all of them.
void requireDeclared(const settings::Exercise& ex, const Config& overrides, const std::vector<const SettingsTable*>& tables) {
  for (const std::string& key : overrides.keys()) {
    bool declared = false;
    for (const auto* t : tables) declared = declared || t->declares(key);
    if (declared) continue;
    std::string suggestion;
    for (const auto* t : tables) {
      if (suggestion.empty()) suggestion = t->suggest(key);
    }
    throw ConfigError(overrides.origin(key) + ": unknown key '" + key + "'" +
                      (suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)") + "; `aula config " + ex.name +
                      "` lists the settings");
  }
}

// The world has no robot of the Robot setting's name but one the exercise can only have meant:
// every process of the run is given it (as an override), and the run says so in one line.
void adoptTheWorldsOnlyRobot(const settings::Exercise& ex, const world::WorldSpec& world, RunSettings& run) {
  const std::string key = ex.section + ".Robot";
  if (!run.component().has(key)) return;
  const std::string named = run.component().getString(key);
  const world::RobotSpec* robot = exerciseRobot(ex, world, named);
  if (robot == nullptr || robot->name == named) return;
  const std::string origin = "the world's only robot with the exercise's plugins";
  run.overrides.set(key, robot->name, origin);
  for (auto& [table, cfg] : run.effective) {
    if (table->declares(key)) cfg.set(key, robot->name, origin);
  }
  std::cerr << ex.name << ": the world has no robot '" << named << "' (" << key << "); using its only robot with the "
            << "exercise's plugins, '" << robot->name << "'\n";
}

// A world that declares destinations (<aula:destination>) is driven to its first, unless the
// command line names one (`aula grade` names each in turn): every process is given it.
void driveToTheWorldsDestination(const settings::Exercise& ex, const world::WorldSpec& world, RunSettings& run) {
  const std::string key = ex.section + ".Destination";
  if (world.destinations.empty() || !run.component().has(key) || run.overrides.has(key)) return;
  const world::Destination& d = world.destinations.front();
  const std::string value = world::settingValue(d);
  const std::string origin = "the world's destination '" + d.name + "'";
  run.overrides.set(key, value, origin);
  for (auto& [table, cfg] : run.effective) {
    if (table->declares(key)) cfg.set(key, value, origin);
  }
}

// With the default rubric, the world's calibration file (W.rubric.cfg, `aula calibrate`) sets the
// rubric settings the .cfg and the command line leave alone, for every process that reads them;
// the referee is told which file it was, for its report.
void applyCalibration(const settings::Exercise& ex, const Config& file, const world::WorldSpec& world, RunSettings& run,
                      const std::string& calibration_file) {
  const std::string preset_key = ex.section + ".Referee.Rubric";
  if (ex.referee_settings == nullptr || !ex.referee_settings->declares(preset_key) ||
      run.referee().getString(preset_key) != "default") {
    if (!calibration_file.empty()) {
      throw config::ConfigError("--calibration=" + calibration_file + ": a calibration applies to the default rubric only" +
                                (ex.referee_settings != nullptr && ex.referee_settings->declares(preset_key)
                                     ? " (" + preset_key + " = " + run.referee().getString(preset_key) + ")"
                                     : " (" + ex.name + " has no rubric to calibrate)"));
    }
    return;
  }
  const Config settings = settings::mergedSettings(run.effective);
  Config calibrated = grade::readCalibration(ex.name, run.world, world.sha256, calibration_file, &settings);
  if (calibrated.keys().empty()) return;
  const std::string calibration_key = ex.section + ".Referee.Calibration";
  if (ex.referee_settings->declares(calibration_key)) {
    const std::string file_name =
        std::filesystem::path(calibration_file.empty() ? grade::calibrationPathOf(run.world) : calibration_file).filename().string();
    calibrated.set(calibration_key, file_name, "the world's calibration");  // a report the same on every machine
  }
  for (const std::string& key : calibrated.keys()) {
    if (run.overrides.has(key) || file.has(key)) continue;  // what the teacher set wins
    run.overrides.set(key, calibrated.getString(key), calibrated.origin(key));
    for (auto& [table, cfg] : run.effective) {
      if (table->declares(key)) cfg.set(key, calibrated.getString(key), calibrated.origin(key));
    }
  }
}

}  // namespace

void checkPointsOnTheMap(const settings::Exercise& ex, const Config& component, const world::WorldSpec& world) {
  std::optional<world::OccupancyMap> map;
  for (const auto& spec : ex.component_settings->specs()) {
    if (!spec.free_point) continue;
    if (!map) {
      const auto z_band = component.getDoubleList(ex.section + ".Map.ZBand");
      map = world::occupancyMapOf(world, {component.getDouble(ex.section + ".Map.Resolution"), z_band[0], z_band[1]});
    }
    const auto xy = component.getDoubleList(spec.key);
    if (const auto problem = world::pointProblem(*map, xy[0], xy[1])) {
      throw ConfigError(component.origin(spec.key) + ": " + spec.key + " = " + component.getString(spec.key) + ": " + *problem);
    }
  }
}

std::vector<std::string> missingPlugins(const settings::Exercise& ex, const world::RobotSpec& robot) {
  std::vector<std::string> missing;
  for (const std::string& need : ex.required_plugins) {
    const auto colon = need.find(':');
    try {
      world::channelOf(robot, need.substr(0, colon), colon == std::string::npos ? "" : need.substr(colon + 1));
    } catch (const world::WorldError&) {
      missing.push_back("a " + need.substr(0, colon) + " plugin" +
                        (colon == std::string::npos ? "" : " named '" + need.substr(colon + 1) + "'"));
    }
  }
  return missing;
}

const world::RobotSpec* exerciseRobot(const settings::Exercise& ex, const world::WorldSpec& world, const std::string& named) {
  if (const world::RobotSpec* robot = world.findRobot(named)) return robot;
  const world::RobotSpec* only = nullptr;
  for (const auto& robot : world.robots) {
    if (!missingPlugins(ex, robot).empty()) continue;
    if (only != nullptr) return nullptr;  // two: which one is for the teacher to say
    only = &robot;
  }
  return only;
}

RunSettings resolveSettings(const settings::Exercise& ex, const std::string& cfg_path, const Config& overrides,
                            const std::string& calibration_file) {
  RunSettings run;
  run.cfg_path = cfg_path;
  run.overrides = overrides;
  const Config file = Config::fromFile(run.cfg_path);
  std::vector<const SettingsTable*> tables = {&settings::simulator()};
  for (const auto* t : ex.tables()) tables.push_back(t);
  requireDeclared(ex, run.overrides, tables);
  if (!run.overrides.has("Simulator.PhysicsStep")) {
    std::ostringstream step;
    step << ex.physics_step_s;
    run.overrides.set("Simulator.PhysicsStep", step.str(), "the " + ex.name + " exercise's step");
  }
  run.effective = settings::resolveProcesses(ex, file, run.overrides);
  // The world, from the component's settings (the .cfg or --world): resolved once for all.
  const std::string world_key = ex.section + ".World";
  run.world = config::resolveWorldPath(run.component().getString(world_key), run.component().origin(world_key) + ": " + world_key);
  const world::WorldSpec world = world::loadWorld(run.world);  // read once for the checks below
  adoptTheWorldsOnlyRobot(ex, world, run);
  driveToTheWorldsDestination(ex, world, run);
  applyCalibration(ex, file, world, run, calibration_file);
  checkPointsOnTheMap(ex, run.component(), world);
  return run;
}

std::vector<std::vector<std::string>> windowPlaces(const RunSettings& run, bool view_3d) {
  std::vector<std::vector<std::string>> places(run.effective.size());
  const auto work_area = desktop::workArea();
  if (!work_area) return places;
  std::vector<desktop::WindowedProcess> processes;  // the clients, then the simulator (effective[0])
  for (size_t i = 1; i <= run.effective.size(); ++i) {
    const size_t process = i % run.effective.size();
    if (process != 0 || view_3d) processes.push_back({run.effective[process].first, run.effective[process].second});
  }
  const desktop::RunLayout layout = desktop::layOutRun(*work_area, processes, {});
  for (size_t i = 0; i < processes.size(); ++i) places[(i + 1) % run.effective.size()] = layout.arguments[i];
  return places;
}

Config settingsOf(const cli::Arguments& args) {
  Config overrides;
  for (const auto& [key, value] : args.settings()) overrides.set(key, value, "command line --" + key);
  return overrides;
}

const settings::Exercise& exerciseArgument(const std::string& name, const std::string& command) {
  if (const settings::Exercise* ex = settings::exerciseNamed(name)) return *ex;
  std::string names;
  for (const auto& ex : settings::exercises()) names += (names.empty() ? "" : ", ") + ex.name;
  throw ConfigError("aula " + command + ": unknown exercise '" + name + "' (one of: " + names + ")");
}

std::string binDir() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::string(".") : self.parent_path().string();
}

std::string runBus(const cli::Arguments& args, const RunSettings& run) {
  config::CommandLine chosen;
  if (args.given("lcm-url")) chosen.options["lcm-url"] = args.text("lcm-url");
  const config::Config& cfg = run.component();
  const char* env = std::getenv("LCM_DEFAULT_URL");
  const bool someone_chose = args.given("lcm-url") || (cfg.has("Aula.LcmUrl") && cfg.origin("Aula.LcmUrl") != "default") ||
                             (env != nullptr && *env != '\0');
  const std::string url = someone_chose ? lcmbus::resolveUrl(chosen, cfg) : "udpm://239.255.76.67:0?ttl=0";
  return lcmbus::withFreePort(url);
}

// What a run's options stand for in the processes' settings.
// An option and its key given both (--duration=5 --Vacuum.Referee.Duration=abc) are refused: one
// would silently win, and the other go unchecked.
config::Config overridesOf(const settings::Exercise& ex, const cli::Arguments& args, bool headless) {
  config::Config overrides = settingsOf(args);
  auto setFrom = [&](const char* option, const std::string& key, const std::string& value) {
    if (overrides.has(key)) {
      throw config::ConfigError(args.spelled(option) + " and --" + key + "=" + overrides.getString(key) +
                        " set the same setting: give only one");
    }
    overrides.set(key, value, std::string("command line --") + option);
  };
  if (args.given("algorithm")) {
    // "reference" names each exercise's default reference: its own built-in of that name, else the
    // one its calibration anchors the scale on (Autopark's "reactive").
    std::string algorithm = args.text("algorithm");
    const config::SettingSpec* choices = ex.component_settings->find(ex.section + ".Algorithm");
    const bool has_reference = choices != nullptr && std::count(choices->choices.begin(), choices->choices.end(), "reference") > 0;
    if (algorithm == "reference" && !has_reference && ex.calibration) algorithm = ex.calibration->anchor;
    setFrom("algorithm", ex.section + ".Algorithm", algorithm);
  }
  if (headless && ex.referee_settings != nullptr) overrides.set(ex.section + ".Autostart", "true", "command line --headless");
  if (args.given("world")) setFrom("world", ex.section + ".World", args.text("world"));
  if (args.given("seed")) setFrom("seed", "Simulator.Seed", args.text("seed"));
  if (args.given("duration") && !ex.episode_key.empty()) setFrom("duration", ex.episode_key, args.text("duration"));
  return overrides;
}

double wallBudgetOf(const settings::Exercise& ex, const RunSettings& run, const cli::Arguments& args, bool headless) {
  if (args.given("timeout")) return args.real("timeout");
  if (!headless || ex.referee_settings == nullptr) return 0;
  const double episode_s = ex.episode_key.empty() ? 0 : run.referee().getDouble(ex.episode_key);
  // Past the episode's, the time the student's code may take by its own budgets: a slow algorithm
  // within them is waited for (the backstop running out on it would be a retry it bought).
  const config::Config& c = run.component();
  const double algorithm_s = c.getDouble("Component.StartBudget") + c.getDouble("Component.RunBudget") +
                             c.getDouble("Component.RunBlockedLimit");
  return supervision::defaultWallBudget(episode_s, args.given("rtf") ? args.real("rtf") : 0) + algorithm_s;
}

}  // namespace aula::commands
