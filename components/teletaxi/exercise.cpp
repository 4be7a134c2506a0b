// TeleTaxi: global navigation with Gradient Path Planning in a city.
// The exercise's declaration: its programs, its settings (the component's and the referee's
// tables), what `aula check-world`, `aula calibrate` and `aula grade --worlds=generate:...` need
// of it. Registered by aula_exercise() in this folder's CMakeLists.txt.
#include <aula/settings/exercise_keys.hpp>
#include <aula/settings/tables.hpp>

#include <memory>

namespace aula::teletaxi {
namespace {

using config::SettingsTable;
using settings::calibrationKey;
using settings::mapKeys;
using settings::motionKeys;
using settings::programTable;
using settings::windowKeys;
using settings::worldKeys;

// The component publishes its plan there, the referee traces it: one key in both tables.
void planChannel(SettingsTable& t) {
  t.text("TeleTaxi.Plan.Channel", "TELETAXI_PLAN",
         "where each generatePath()'s field and path (plan_t; never graded) go, for the run's log and the player");
}

SettingsTable makeTaxiComponent() {
  SettingsTable t = programTable("teletaxi");
  worldKeys(t, "TeleTaxi", "worlds/cityLarge.world", "taxi_holo");
  mapKeys(t, "TeleTaxi", 1.25, "0.01, 100");
  motionKeys(t, "TeleTaxi", 20, 2, 0.08, 50, 10);
  t.algorithm("TeleTaxi.Algorithm", "student", {"student", "reference"},
              "the algorithm that drives the taxi (student: the template; PATH.so: a plugin built with aula_add_algorithm; "
              "PATH.py: a MyAlgorithm.py)");
  config::SettingSpec destination;
  destination.key = "TeleTaxi.Destination";
  destination.type = config::SettingType::DoubleList;
  destination.default_value = "120, -40";
  destination.list_size = 2;
  destination.unit = "m";
  destination.min = -1e6;
  destination.max = 1e6;
  destination.free_point = true;  // the launcher refuses one off the map or in a building at once
  destination.help = "destination x, y: pre-selected in the window, the one headless runs drive to";
  t.add(destination);
  windowKeys(t, "TeleTaxi.Window", "1000, 690", "the TeleTaxi window");
  windowKeys(t, "TeleTaxi.GridWindow", "420, 420", "the \"Grid Field\" window (api.grid.showGrid())");
  planChannel(t);
  return t;
}

SettingsTable makeTaxiReferee() {
  SettingsTable t = programTable("teletaxi-referee");
  worldKeys(t, "TeleTaxi", "worlds/cityLarge.world", "taxi_holo");
  windowKeys(t, "TeleTaxi.RefereeWindow", "460, 640", "the referee's window");
  mapKeys(t, "TeleTaxi", 1.25, "0.01, 100");  // the picture shows the component's map
  planChannel(t);
  t.real("TeleTaxi.Referee.Timeout", 600, "s", 0, 1e6, "give up this long after GO! (simulated time)", true);
  t.real("TeleTaxi.Referee.StopSpeed", 0.05, "m/s", 0, 10, "'stopped' means slower than this...", true);
  t.real("TeleTaxi.Referee.StopHold", 1.0, "s", 0, 600, "...for this long", true);
  t.real("TeleTaxi.Referee.Period", 0.1, "s", 0.005, 10, "how often the referee syncs with the simulator (simulated time)");
  t.real("TeleTaxi.Referee.ArrivalRadius", 5, "m", 0, 1000, "arrived: stopped within this distance of the destination", true);
  t.real("TeleTaxi.Referee.FullMarkSpeed", 2.6, "m/s", 0, 100,
         "average speed along the path worth a speed mark of 10 (it adds 0.2 x speed mark)", true);
  t.real("TeleTaxi.Referee.FullMarkTime", 0, "s", 0, 1e6,
         "driving time worth a speed mark of 10 instead of FullMarkSpeed (0: none); a world's calibration sets it to "
         "the reference's time to the destination");
  t.real("TeleTaxi.Referee.MinTravel", 2, "m", 0, 1000,
         "the distance mark counts only when the taxi travelled at least this far since GO!");
  calibrationKey(t, "TeleTaxi");
  t.presets("TeleTaxi.Referee.Rubric", "default",
            {"TeleTaxi.Referee.ArrivalRadius", "TeleTaxi.Referee.FullMarkSpeed", "TeleTaxi.Referee.FullMarkTime",
             "TeleTaxi.Referee.MinTravel"},
            {{"default", "a taxi that did not drive gets no distance mark; the world's calibration, if any, sets the speed "
                         "scale from the reference's time to the destination", {}},
             {"fixed", "the default scale on every world, never a world's calibration", {}},
             {"original", "the thesis's scale: arriving without driving is worth 8", {{"TeleTaxi.Referee.MinTravel", "0"}}}},
            "the grading scale: a preset of the rubric settings (a value set in the .cfg or on the command line wins)");
  return t;
}

}  // namespace

settings::Exercise declareExercise() {
  settings::Exercise e;
  e.name = "teletaxi";
  e.section = "TeleTaxi";
  e.config_file = "config/teleTaxi.cfg";
  e.component = "teletaxi";
  e.referee = "teletaxi-referee";
  e.component_settings = std::make_shared<const SettingsTable>(makeTaxiComponent());
  e.referee_settings = std::make_shared<const SettingsTable>(makeTaxiReferee());
  e.required_plugins = {"pose3d", "motors", "bumper"};
  e.summary = "global navigation with Gradient Path Planning";
  e.episode_key = "TeleTaxi.Referee.Timeout";
  e.physics_step_s = 0.005;
  // The speed scale: the reference's driving time to that destination.
  e.calibration = settings::ExerciseCalibration{"driving_time_s", "", "reference", {"TeleTaxi.Referee.FullMarkTime"},
                                                settings::reachKeys("TeleTaxi"), "reached", "", ""};
  auto& context = e.calibration->context_keys;  // the destination first, as files record it
  context.insert(context.begin(), "TeleTaxi.Destination");
  e.generator = settings::WorldGenerator{"city", "make_city.py", 1.25};
  return e;
}

}  // namespace aula::teletaxi
