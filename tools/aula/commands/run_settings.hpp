#pragma once
// The settings of one run, shared by `aula run` and `aula config`: the exercise's .cfg, the
// --Key=value overrides and what the command's own options set, resolved for each process
// against its own table; the world resolved once for all three.

#include <aula/cli/command.hpp>
#include <aula/config/config.hpp>
#include <aula/settings/tables.hpp>
#include <aula/world/world_spec.hpp>

#include <string>
#include <utility>
#include <vector>

namespace aula::commands {

struct RunSettings {
  std::string cfg_path;
  config::Config overrides;  // checked: each key is declared by at least one process of the run
  std::string world;         // absolute path, handed to every process
  settings::ProcessSettings effective;  // simulator first (settings::resolveProcesses)

  const config::Config& component() const { return effective.at(1).second; }
  const config::Config& referee() const { return effective.back().second; }
};

// `overrides`: the --Key=value settings, plus what the command's options stand for (its caller
// sets "Vacuum.Algorithm" for --algorithm, with the origin "command line --algorithm").
// `calibration_file`: the world's calibration to apply with the default rubric (`--calibration`,
// what `aula grade` gives each run), instead of WORLD.rubric.cfg beside the world.
RunSettings resolveSettings(const settings::Exercise& ex, const std::string& cfg_path, const config::Config& overrides,
                            const std::string& calibration_file = "");

// Points the component will drive to (free_point settings) must be free floor of `world`'s map:
// a ConfigError naming the setting and the reason otherwise (the component checks what needs its
// planner). `aula run` checks before any process starts, `aula check-world` with the defaults.
void checkPointsOnTheMap(const settings::Exercise& ex, const config::Config& component, const world::WorldSpec& world);

// What `robot` lacks of the plugins `ex` needs ("a laser plugin named 'laser_front'"); empty if nothing.
std::vector<std::string> missingPlugins(const settings::Exercise& ex, const world::RobotSpec& robot);

// The robot `ex` drives in `world`: the one its Robot setting names (`named`), else the world's
// only robot with every plugin the exercise needs (nothing else could have been meant); nullptr
// when neither. `aula run` hands the one chosen to every process of the run.
const world::RobotSpec* exerciseRobot(const settings::Exercise& ex, const world::WorldSpec& world, const std::string& named);

// With windows: where each process's windows go, as settings for its command line
// ("--Vacuum.Window.Position=0, 0"), one list per process of `run.effective` (the simulator's 3D
// view only with `view_3d`), from one layout on the screen's work area (aula/desktop): the
// component's windows first, then the referee's, then the 3D view. A window whose position the
// .cfg or the command line sets keeps it; without a display, every list is empty.
std::vector<std::vector<std::string>> windowPlaces(const RunSettings& run, bool view_3d);

// The command line's --Section.Key=value settings as a Config with their origins.
config::Config settingsOf(const cli::Arguments& args);
// Those, plus what `aula run`'s own options stand for (--algorithm, --world, --seed, --duration;
// headless: autostart); an option and its key given both are refused.
config::Config overridesOf(const settings::Exercise& ex, const cli::Arguments& args, bool headless);
// A headless run's wall-clock backstop (--timeout, else supervision::defaultWallBudget plus what
// the student's code may take by its Component budgets); 0: none (windows, no referee).
double wallBudgetOf(const settings::Exercise& ex, const RunSettings& run, const cli::Arguments& args, bool headless);

// The run's bus: --lcm-url, the .cfg's Aula.LcmUrl or LCM_DEFAULT_URL when one of them chooses,
// else one of its own, so that two runs on one machine never hear each other. Port 0: a free
// port the OS hands out, now, for all three processes.
std::string runBus(const cli::Arguments& args, const RunSettings& run);

// The exercise named by a command's EXERCISE argument; a usage error listing them otherwise.
AULA_NO_DANGLING const settings::Exercise& exerciseArgument(const std::string& name, const std::string& command);

// The folder of the running `aula` (its sibling programs, its install prefix's parent).
std::string binDir();

}  // namespace aula::commands
