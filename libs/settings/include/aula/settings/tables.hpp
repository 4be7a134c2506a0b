#pragma once
// The settings every Aula process declares, in one place: the simulator, the demo client, and
// each exercise's component and referee. The launcher reads them too: it hands each process
// only the keys that process declares, and `aula config` prints the effective values.
// Channel names are not settings: they come from the robot's plugins in the world.

#include <aula/config/no_dangling.hpp>
#include <aula/config/settings.hpp>

#include <string>
#include <vector>

namespace aula::settings {

const config::SettingsTable& simulator();
const config::SettingsTable& demo();

// One exercise's processes: their program names and tables (component first, then referee).
struct Exercise {
  std::string name;              // "vacuum": the name given to `aula run`
  std::string section;           // "Vacuum": the keys' section
  std::string config_file;       // relative to the data folder: "config/vacuumCleaner.cfg"
  std::string component;         // program names
  std::string referee;
  const config::SettingsTable* component_settings;
  const config::SettingsTable* referee_settings;  // nullptr when the exercise has none
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

  std::vector<const config::SettingsTable*> tables() const;
};

const std::vector<Exercise>& exercises();
// The exercise a program belongs to ("vacuum-cleaner-referee" -> vacuum); nullptr if none.
const Exercise* exerciseOfProgram(const std::string& program);
const Exercise* exerciseNamed(const std::string& name);
// The exercise an exercise's own code names ("vacuum"); throws std::logic_error if unknown.
AULA_NO_DANGLING const Exercise& requireExercise(const std::string& name);
// The table of a program ("aula-sim", "vacuum-cleaner", ...); throws std::logic_error if unknown.
AULA_NO_DANGLING const config::SettingsTable& tableOf(const std::string& program);

}  // namespace aula::settings
