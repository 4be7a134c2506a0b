// Autopark: parallel parking with three lasers.
// The exercise's declaration: its programs, its settings (the component's and the referee's
// tables), what `aula check-world`, `aula calibrate` and `aula grade --worlds=generate:...` need
// of it. Registered by aula_exercise() in this folder's CMakeLists.txt.
#include <aula/settings/exercise_keys.hpp>
#include <aula/settings/tables.hpp>

#include <memory>

namespace aula::autopark {
namespace {

using config::SettingsTable;
using settings::calibrationKey;
using settings::motionKeys;
using settings::programTable;
using settings::windowKeys;
using settings::worldKeys;

SettingsTable makeAutoparkComponent() {
  SettingsTable t = programTable("autopark");
  worldKeys(t, "Autopark", "worlds/autopark.world", "car");
  windowKeys(t, "Autopark.Window", "1120, 550", "the Autopark window");
  motionKeys(t, "Autopark", 3, 1, 0.05, 10, 5);
  t.algorithm("Autopark.Algorithm", "student", {"student", "reactive", "planner"},
              "PATH.so: a plugin; PATH.py: a MyAlgorithm.py; reactive: the thesis's two arcs; planner: laser map + OMPL "
              "Reeds-Shepp path (docs/planner.md)");
  return t;
}

SettingsTable makeAutoparkReferee() {
  SettingsTable t = programTable("autopark-referee");
  worldKeys(t, "Autopark", "worlds/autopark.world", "car");
  windowKeys(t, "Autopark.RefereeWindow", "560, 460", "the referee's window");
  t.real("Autopark.Referee.Timeout", 300, "s", 0, 1e6, "the run ends 'not parked' this long after Run", true);
  t.text("Autopark.Referee.Curb", "",
         "the parking-side curb's collision name; empty: the static box along the street nearest below the car's start");
  t.text("Autopark.Referee.CarPrefix", "",
         "the parked cars' model names start with this; empty: every static box between that curb and the car's start");
  t.real("Autopark.Referee.StillHold", 3, "s", 0, 600, "parked = still inside the slot for this long", true);
  t.real("Autopark.Referee.Period", 0.1, "s", 0.005, 10, "how often the referee syncs with the simulator (simulated time)");
  t.real("Autopark.Referee.FullMarkTime", 170, "s", 0, 1e6, "parked in under this time: full time score", true);
  t.choice("Autopark.Referee.GapRule", "slot", {"slot", "absolute"},
           "how the gaps to the front and rear cars are scored: slot (SlotGapFractions of the ideal gap, any slot "
           "length) or absolute (GapBands in metres)");
  t.reals("Autopark.Referee.SlotGapFractions", "0.25, 0.5", 2, "", 0, 1,
          "GapRule slot: each gap as a fraction of the ideal gap (slot length - car length) / 2: half marks from [0], "
          "full marks from [1] (a car centred within (1 - [1]) x the ideal gap)");
  t.reals("Autopark.Referee.GapBands", "1.0, 1.5, 3.5", 3, "m", 0, 100,
          "GapRule absolute: gaps to the front and rear cars: half marks from [0], full marks in [[1], [2])");
  t.reals("Autopark.Referee.CurbBands", "0.75, 1.5", 2, "m", 0, 100,
          "nearest corner to the curb: full marks within [0], half within [1]");
  t.choice("Autopark.Referee.Scale", "parked", {"parked", "thesis"},
           "parked: the four terms grade a car parked in the slot; a run that does not park there gets NotParkedMark; "
           "contacts cost ContactCost shares of the mark. thesis: each term wherever the car stopped, any contact loses "
           "the collision quarter");
  t.real("Autopark.Referee.NotParkedMark", 1.0, "", 0, 10,
         "Scale parked: the mark of a run that does not park in the slot (stayed still, drove off, gave up, parked "
         "elsewhere), less its contacts' cost");
  t.reals("Autopark.Referee.ContactCost", "0.1, 0.1, 0.05", 3, "", 0, 10,
          "Scale parked: the share of the mark each contact costs [0], plus [1] per second in contact, plus [2] per cm "
          "it went into what it touched (at most the whole mark)");
  calibrationKey(t, "Autopark");
  t.presets("Autopark.Referee.Rubric", "default",
            {"Autopark.Referee.FullMarkTime", "Autopark.Referee.GapRule", "Autopark.Referee.SlotGapFractions",
             "Autopark.Referee.GapBands", "Autopark.Referee.CurbBands", "Autopark.Referee.Scale",
             "Autopark.Referee.NotParkedMark", "Autopark.Referee.ContactCost"},
            {{"default", "gaps relative to the slot: a centred car gets full marks in any slot of 1.2 L or more; not "
                         "parked is worth NotParkedMark; a contact costs a share of the mark; the street's calibration, "
                         "if any, sets the time allowance from the reactive parker's time",
              {}},
             {"fixed", "the default scale on every street, never a street's calibration", {}},
             {"original", "the thesis's scale: gaps of [1.5, 3.5) m to each car; any contact loses a quarter",
              {{"Autopark.Referee.GapRule", "absolute"}, {"Autopark.Referee.Scale", "thesis"}}}},
            "the grading scale: a preset of the rubric settings (a value set in the .cfg or on the command line wins)");
  return t;
}

}  // namespace

settings::Exercise declareExercise() {
  settings::Exercise e;
  e.name = "autopark";
  e.section = "Autopark";
  e.config_file = "config/autopark.cfg";
  e.component = "autopark";
  e.referee = "autopark-referee";
  e.component_settings = std::make_shared<const SettingsTable>(makeAutoparkComponent());
  e.referee_settings = std::make_shared<const SettingsTable>(makeAutoparkReferee());
  e.required_plugins = {"pose3d", "motors", "bumper", "laser:laser_front", "laser:laser_rear", "laser:laser_right"};
  e.summary = "find the free slot and park in parallel (--world=autopark_ackermann_1.3L.world: a car-like car)";
  e.episode_key = "Autopark.Referee.Timeout";
  e.physics_step_s = 0.005;
  // The time allowance: the thesis's reactive parker's time on that street.
  e.calibration = settings::ExerciseCalibration{"park_time_s", "", "reactive", {"Autopark.Referee.FullMarkTime"},
                                                settings::reachKeys("Autopark"), "parked", "", "planner"};
  e.generator = settings::WorldGenerator{"street", "make_autopark.py", 0.1};
  e.referee_scene = "parking_street";
  return e;
}

}  // namespace aula::autopark
