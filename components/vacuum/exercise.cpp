// Vacuum cleaner: coverage of a house with no localization.
// The exercise's declaration: its programs, its settings (the component's and the referee's
// tables), what `aula check-world`, `aula calibrate` and `aula grade --worlds=generate:...` need
// of it. Registered by aula_exercise() in this folder's CMakeLists.txt.
#include <aula/settings/exercise_keys.hpp>
#include <aula/settings/tables.hpp>

#include <memory>

namespace aula::vacuum {
namespace {

using config::SettingsTable;
using settings::calibrationKey;
using settings::mapKeys;
using settings::motionKeys;
using settings::programTable;
using settings::windowKeys;
using settings::worldKeys;

// The component publishes the belief there, the referee traces it: one key in both tables.
void beliefChannel(SettingsTable& t) {
  t.text("Vacuum.Belief.Channel", "VACUUM_BELIEF",
         "where the algorithm's belief (api.belief: its own pose and map, never graded) is published for the window, "
         "the log and the run's player");
}

void vacuumDuration(SettingsTable& t) {
  t.real("Vacuum.Referee.Duration", 900, "s", 0, 1e6, "length of a run (simulated time); the component shows the time left", true);
}

SettingsTable makeVacuumComponent() {
  SettingsTable t = programTable("vacuum-cleaner");
  worldKeys(t, "Vacuum", "worlds/vacuum.world", "roomba");
  windowKeys(t, "Vacuum.Window", "880, 690", "the vacuum cleaner's window");
  mapKeys(t, "Vacuum", 0.02, "0.005, 0.09");
  motionKeys(t, "Vacuum", 0.5, 3.0, 0.08, 2, 10);
  t.algorithm("Vacuum.Algorithm", "student", {"student", "reference", "classic", "bounce"},
              "the algorithm that drives the roomba (reference: maps the house with its laser and plans its coverage; "
              "classic: the thesis's spiral, walls and bounces; bounce: the random-bounce baseline; PATH.so: a plugin; "
              "PATH.py: a MyAlgorithm.py)");
  beliefChannel(t);
  vacuumDuration(t);
  return t;
}

SettingsTable makeVacuumReferee() {
  SettingsTable t = programTable("vacuum-cleaner-referee");
  worldKeys(t, "Vacuum", "worlds/vacuum.world", "roomba");
  windowKeys(t, "Vacuum.RefereeWindow", "720, 690", "the referee's window");
  mapKeys(t, "Vacuum", 0.02, "0.005, 0.09");
  vacuumDuration(t);
  beliefChannel(t);
  t.real("Vacuum.Referee.RobotRadius", 0.165, "m", 0, 10, "radius of the footprint that cleans", true);
  t.real("Vacuum.Referee.Period", 1.0, "s", 0.005, 10,
         "how often the referee syncs with the simulator (simulated time; it counts every pose in between)");
  // Calibrated on the shipped house over 20 seeds (docs/exercises/vacuum.md): the random-bounce
  // baseline's median coverage is about 39 % (a 4.9), the thesis's classic cleaner's about 66 %
  // (a 10); the mapping reference covers about 86 %.
  t.real("Vacuum.Referee.HalfMarkCoverage", 40, "%", 0, 100, "coverage worth a 5 (the mark rises linearly from 0 %)", true);
  t.real("Vacuum.Referee.FullMarkCoverage", 60, "%", 0, 100, "coverage worth a 10 (linearly from the half mark's)", true);
  calibrationKey(t, "Vacuum");
  t.presets("Vacuum.Referee.Rubric", "default", {"Vacuum.Referee.HalfMarkCoverage", "Vacuum.Referee.FullMarkCoverage"},
            {{"default", "the world's calibration when it has one (W.rubric.cfg, written by aula calibrate: the random-bounce "
                         "baseline's median is worth a 5, the reference's a 10), else fixed", {}},
             {"fixed", "the shipped house's scale on every world: the baseline is worth about a 5 there, the reference a 10",
              {}},
             {"original", "the thesis's scale: 10 x coverage / 30 %",
              {{"Vacuum.Referee.HalfMarkCoverage", "15"}, {"Vacuum.Referee.FullMarkCoverage", "30"}}}},
            "the grading scale: a preset of the rubric settings (a value set in the .cfg or on the command line wins)");
  return t;
}

}  // namespace

settings::Exercise declareExercise() {
  settings::Exercise e;
  e.name = "vacuum";
  e.section = "Vacuum";
  e.config_file = "config/vacuumCleaner.cfg";
  e.component = "vacuum-cleaner";
  e.referee = "vacuum-cleaner-referee";
  e.component_settings = std::make_shared<const SettingsTable>(makeVacuumComponent());
  e.referee_settings = std::make_shared<const SettingsTable>(makeVacuumReferee());
  e.required_plugins = {"pose3d", "motors", "laser", "bumper"};
  e.summary = "clean the house without localization";
  e.episode_key = "Vacuum.Referee.Duration";
  e.physics_step_s = 0.010;
  // The coverage scale: the random-bounce baseline's median at a 5, the reference's at a 10.
  e.calibration = settings::ExerciseCalibration{"coverage_percent", "bounce", "reference",
                                                {"Vacuum.Referee.HalfMarkCoverage", "Vacuum.Referee.FullMarkCoverage"},
                                                settings::reachKeys("Vacuum"), "", "wedged", "classic"};
  auto& context = e.calibration->context_keys;  // the episode's length first, as files record it
  context.insert(context.begin(), "Vacuum.Referee.Duration");
  e.generator = settings::WorldGenerator{"house", "make_house.py", 0.05};
  return e;
}

}  // namespace aula::vacuum
