#pragma once
// The settings every Aula process declares: the simulator's and the demo client's here, each
// exercise's in its own declaration (components/<exercise>/exercise.cpp, registered by
// aula_exercise() in that folder's CMakeLists.txt: no list here names an exercise). The launcher
// reads them too: it hands each process only the keys that process declares, and `aula config`
// prints the effective values. Channel names are not settings: they come from the robot's plugins.

#include <aula/config/no_dangling.hpp>
#include <aula/config/settings.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace aula::settings {

const config::SettingsTable& simulator();
const config::SettingsTable& demo();

// What `aula calibrate` measures of an exercise on a world (docs/grading.md, "Calibration"): the
// report's measure, and the referee's rubric settings computed from the baseline's and the
// anchor's medians of it.
struct ExerciseCalibration {
  std::string measure;                   // a report field: "coverage_percent"
  std::string baseline, anchor;          // default algorithms; no baseline: a scale of one point, the anchor's
  std::vector<std::string> rubric_keys;  // the referee's settings it writes (the baseline's first, if any)
  // Settings (any process's) that change what a run can reach besides the world: the destination,
  // the episode's length, the noise, the speed limits. Written in the calibration file; a run
  // with other values is refused, and a grade with other values makes its own calibration.
  std::vector<std::string> context_keys;
  // A report field every anchor run must have true ("parked"; "" for none): an anchor that failed
  // would anchor the scale on a failure.
  std::string success;
  // A report field every anchor run must have false ("wedged"; "" for none): the same, where every
  // run ends with a measure (a cleaner that gave up in a corner still covered some floor).
  std::string failure;
  std::string other_anchor;  // the algorithm to suggest when the anchor fails ("" for none)
};

// How `aula grade --worlds=generate:KIND:N` makes held-out worlds of an exercise.
struct WorldGenerator {
  std::string kind;          // "house": what a teacher writes after generate:
  std::string script;        // the generator in the data folder's worlds/tools/: "make_house.py"
  double map_resolution_m;   // the resolution of the map drawn to check each generated world
};

// One exercise's processes: their program names and tables (component first, then referee).
struct Exercise {
  std::string name;              // "vacuum": the name given to `aula run`
  std::string section;           // "Vacuum": the keys' section
  std::string config_file;       // relative to the data folder: "config/vacuumCleaner.cfg"
  std::string component;         // program names
  std::string referee;
  std::shared_ptr<const config::SettingsTable> component_settings;
  std::shared_ptr<const config::SettingsTable> referee_settings;  // nullptr when the exercise has none
  // What the exercise needs of its robot's plugins: "TYPE" or "TYPE:NAME" (`aula check-world`).
  std::vector<std::string> required_plugins;
  std::string summary;  // one line for `aula --help`: what the student does
  // The referee's key for the episode's length in sim time (`aula run --duration`, the wall
  // budget): "Vacuum.Referee.Duration"; "" for an exercise with no referee.
  std::string episode_key;
  // The physics step of every run of the exercise (`aula run` gives it to the simulator unless
  // --Simulator.PhysicsStep says otherwise); a world's <physics> does not change it, so marks
  // mean the same on every world. 10 ms for the house, 5 ms for the city and the street.
  double physics_step_s = 0.005;
  std::optional<ExerciseCalibration> calibration;  // none: `aula grade` runs on the fixed rubric
  std::optional<WorldGenerator> generator;         // none: no generated worlds
  // What the referee needs in a world besides the robot: "" (nothing), or "parking_street" (a curb
  // and parked cars, aula/scoring/parking_geometry.hpp): `aula check-world` checks it.
  std::string referee_scene;
  // The version of the exercise's plugin API (its aula_exercise() ABI_VERSION, set by the
  // generated registry): a plugin built for another is refused (plugin_library.cpp).
  int abi_version = 0;

  std::vector<const config::SettingsTable*> tables() const;
};

// The exercises the build declares, each by its own aula_exercise() (exercise_registry.cpp, generated).
std::vector<Exercise> declaredExercises();
// Every exercise declared in the build (sorted by name), then the demo (no referee).
const std::vector<Exercise>& exercises();
// The exercises' names for a help text or an error: "autopark, teletaxi or vacuum" (those with a
// referee), or with the demo too ("..., vacuum or demo").
std::string exerciseNames(bool with_demo);
// The exercise a program belongs to ("vacuum-cleaner-referee" -> vacuum); nullptr if none.
const Exercise* exerciseOfProgram(const std::string& program);
const Exercise* exerciseNamed(const std::string& name);
// The exercise an exercise's own code names ("vacuum"); throws std::logic_error if unknown.
AULA_NO_DANGLING const Exercise& requireExercise(const std::string& name);
// The table of a program ("aula-sim", "vacuum-cleaner", ...); throws std::logic_error if unknown.
AULA_NO_DANGLING const config::SettingsTable& tableOf(const std::string& program);

// Each process's settings in a run of `ex`, the simulator's first, then ex.tables()'s: the
// simulator's from config/simulator.cfg (aula-sim reads it too), the others' from `exercise_file`
// (the exercise's .cfg), each with the `overrides` its table declares, resolved (defaults,
// presets). `aula run` starts its processes with them; `aula calibrate` records from them.
using ProcessSettings = std::vector<std::pair<const config::SettingsTable*, config::Config>>;
ProcessSettings resolveProcesses(const Exercise& ex, const config::Config& exercise_file, const config::Config& overrides);
// One Config of every key of `processes` (the first process that declares a key gives its value).
config::Config mergedSettings(const ProcessSettings& processes);

}  // namespace aula::settings
