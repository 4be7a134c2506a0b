#include "aula/settings/tables.hpp"

#include <cctype>
#include <stdexcept>

namespace aula::settings {
namespace {

using config::SettingsTable;

SettingsTable common(const std::string& owner) {
  SettingsTable t(owner);
  t.text("Aula.LcmUrl", "udpm://239.255.76.67:7667?ttl=0",
         "LCM bus shared by the simulator, the component and the referee (--lcm-url overrides it)");
  return t;
}

// The world and robot every process of an exercise shares; the launcher sets World for all three.
void worldKeys(SettingsTable& t, const std::string& section, const std::string& world, const std::string& robot) {
  t.text(section + ".World", world,
         "the SDF world (absolute, or relative to the data folder); `aula run --world=FILE` sets it for all processes");
  t.text(section + ".Robot", robot, "the robot's model name in the world; its plugins name its channels");
  // Channels named after the section: VACUUM_EPISODE, VACUUM_REFEREE...
  std::string upper = section;
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  t.text(section + ".Episode.Channel", upper + "_EPISODE", "channel of the component's episode messages to the referee");
  t.text(section + ".RefereeStatus.Channel", upper + "_REFEREE",
         "channel of the referee's status (time left, how the episode ended) to the component's window");
}

// A window of the process: its fixed size, and where `aula run` / `aula replay` put it (one layout
// of the run's windows, aula/desktop/window_layout.hpp). The sizes fit side by side on 1920x1080.
void windowKeys(SettingsTable& t, const std::string& prefix, const std::string& size_px, const std::string& what) {
  t.reals(prefix + ".Size", size_px, 2, "px", 160, 16384,
          "width, height of " + what + ", fixed while it runs (text that grows wraps or is cut, never the window)");
  t.reals(prefix + ".Position", "-1, -1", 2, "px", -1, 65535,
          "where the top-left corner of " + what + "'s frame goes on the screen; `aula run` and `aula replay` set it "
          "from one layout of the run's windows; -1, -1: where the window manager puts it");
}

// The occupancy map both the component and the referee draw from the world.
void mapKeys(SettingsTable& t, const std::string& section, double resolution_m, const std::string& z_band) {
  t.real(section + ".Map.Resolution", resolution_m, "m/px", 0.001, 100, "occupancy map resolution", true);
  t.reals(section + ".Map.ZBand", z_band, 2, "m", -1000, 1000,
          "heights of the geometry drawn into the map (what the robot can touch): min, max");
}

// Limits are bounded by what the exercise's robot could ever do (its motors driver clamps too).
void motionKeys(SettingsTable& t, const std::string& section, double max_v, double max_w, double period_s,
                double v_bound_mps, double w_bound_radps) {
  t.real(section + ".MaxV", max_v, "m/s", 0, v_bound_mps, "speed limit the motors proxy clamps the student's commands to", true);
  t.real(section + ".MaxW", max_w, "rad/s", 0, w_bound_radps, "turn-rate limit the motors proxy clamps to", true);
  t.real(section + ".Period", period_s, "s", 0.005, 1, "execute() period, seconds of simulated time");
  t.flag(section + ".Autostart", false, "start the algorithm at once (set by `aula run --headless`)");
  // The student's calls are measured by what they use, never by the machine's wall time
  // (ExecuteWatchdog): CPU seconds of the thread that runs them, and seconds it spends blocked.
  t.real("Component.ExecuteBudget", 2.0, "s", 0, 86400,
         "CPU time one call of execute() may use before the run ends (an endless loop); 0: no limit, for a debugger");
  t.real("Component.StartBudget", 60.0, "s", 0, 86400,
         "CPU time creating the algorithm may use: loading its file, its imports (numpy, cv2) and its constructor or __init__; 0: no limit");
  t.real("Component.PlanBudget", 60.0, "s", 0, 86400,
         "CPU time one call that plans (TeleTaxi's generatePath()) may use; 0: no limit");
  t.real("Component.BlockedLimit", 10.0, "s", 0, 86400,
         "time one call may spend blocked, sleeping or waiting (not computing); 0: no limit");
  t.real("Component.RunBudget", 600.0, "s", 0, 1e7,
         "CPU time all the algorithm's calls of a run may use together; 0: no limit");
  t.real("Component.RunBlockedLimit", 60.0, "s", 0, 1e7,
         "time all the algorithm's calls of a run may spend blocked together; 0: no limit");
  t.real("Component.Sandbox.Memory", 2048, "MB", 64, 1e7,
         "memory the student's code may use in a sandboxed (graded) run; past it the run ends with that reason");
  t.integer("Component.Sandbox.Processes", 64, "", 0, 4096,
            "processes the student's code may start in a sandboxed run; past it the run ends with that reason");
  t.real("Component.Sandbox.FileSize", 64, "MB", 1, 1e7,
         "the largest file the student's code may write in a sandboxed run, and its private temporary folder's size");
  t.real("Component.Sandbox.Output", 256, "MB", 1, 1e7,
         "what the student's code may print in a sandboxed run (stdout and stderr); past it the run ends with that reason");
}

SettingsTable makeSimulator() {
  SettingsTable t = common("aula-sim");
  t.real("Simulator.PhysicsStep", 0.005, "s", 1e-4, 0.05,
         "physics step for worlds without <physics><max_step_size> (the world's own step wins)");
  t.real("Simulator.RealTimeFactor", 1.0, "", 0, 1e6, "pacing: 1 = real time, 0 = as fast as possible");
  t.flag("Simulator.Lockstep", false, "advance only when every registered client has acknowledged");
  t.integer("Simulator.Lockstep.WaitForClients", 0, "clients", 0, 64, "lockstep: wait for this many clients before the first step");
  t.integer("Simulator.Lockstep.ResendMs", 20, "ms", 1, 60000, "lockstep: re-send an unacknowledged tick after this wall time");
  t.integer("Simulator.Lockstep.DropAfterMs", 600000, "ms", 1, 86400000, "lockstep: a backstop for a starved machine: a client silent this long (wall) ends a graded run for the machine's reason (the launcher sees a process that is gone at once; a slow one is waited for); outside a graded run a silent client is waited for while its process lives, and dropped once it is gone");
  t.real("Simulator.ClockPeriod", 0.02, "s", 1e-4, 10, "SIM_CLOCK tick period, seconds of simulated time");
  t.integer("Simulator.Seed", 0, "", -9223372036854775807LL, 9223372036854775807LL, "seed of every random process (sensor noise)");
  t.real("Simulator.Duration", 0, "s", 0, 1e9, "stop after this much simulated time (0: run until stopped)");
  t.flag("Simulator.StartPaused", false, "start paused (resume from SIM_CONTROL)");
  // Sensor realism, opt-in per run, seeded by Simulator.Seed (drivers::SensorNoise); the referee
  // always grades the true pose.
  t.real("Simulator.Noise.LaserStddev", 0, "m", 0, 1, "Gaussian noise on every laser hit (a world's noise_stddev when larger)");
  t.real("Simulator.Noise.LaserDropout", 0, "", 0, 1, "the share of laser beams that get no echo (read max_range)");
  t.real("Simulator.Noise.WheelSlip", 0, "", 0, 1, "relative stddev of the speed the wheels deliver, drawn per command");
  t.presets("Simulator.Noise", "off", {"Simulator.Noise.LaserStddev", "Simulator.Noise.LaserDropout", "Simulator.Noise.WheelSlip"},
            {{"off", "exact sensors and wheels (the exercises as the original taught them)", {}},
             {"realistic", "a 2D lidar's 1 cm of noise and 1 % of beams lost, wheels delivering 2 % more or less",
              {{"Simulator.Noise.LaserStddev", "0.01"}, {"Simulator.Noise.LaserDropout", "0.01"},
               {"Simulator.Noise.WheelSlip", "0.02"}}}},
            "sensor realism: a preset of the Simulator.Noise.* settings (a value set in the .cfg or on the command line wins)");
  windowKeys(t, "Simulator.Window", "544, 306", "the 3D view (aula-sim --gui, `aula run --3d`)");
  config::SettingSpec start;
  start.key = "Simulator.StartPose.*";
  start.type = config::SettingType::DoubleList;
  start.list_size = 3;
  start.unit = "m, m, rad";
  start.min = -1e6;
  start.max = 1e6;
  start.help = "Simulator.StartPose.<robot> = x, y, yaw: where a robot starts instead of its world pose";
  t.add(start);
  return t;
}

SettingsTable makeDemo() {
  SettingsTable t = common("aula-demo-client");
  t.text("Demo.World", "worlds/vacuum.world", "the SDF world (absolute, or relative to the data folder)");
  t.text("Demo.Robot", "roomba", "the robot's model name in the world; its plugins name its channels");
  t.real("Demo.Period", 0.08, "s", 0.005, 1, "control period, seconds of simulated time");
  t.real("Demo.MaxV", 0.3, "m/s", 0, 10, "forward speed", true);
  t.real("Demo.TurnW", 1.0, "rad/s", 0, 20, "turn rate when blocked", true);
  t.real("Demo.Clearance", 0.4, "m", 0, 10, "turn when the laser sees anything closer", true);
  return t;
}

SettingsTable makeTaxiComponent() {
  SettingsTable t = common("teletaxi");
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
  return t;
}

SettingsTable makeTaxiReferee() {
  SettingsTable t = common("teletaxi-referee");
  worldKeys(t, "TeleTaxi", "worlds/cityLarge.world", "taxi_holo");
  windowKeys(t, "TeleTaxi.RefereeWindow", "460, 640", "the referee's window");
  mapKeys(t, "TeleTaxi", 1.25, "0.01, 100");  // the picture shows the component's map
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
  t.text("TeleTaxi.Referee.Calibration", "",
         "the calibration file the launcher applied (aula run sets it; the report names it); empty: none");
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

void vacuumDuration(SettingsTable& t) {
  t.real("Vacuum.Referee.Duration", 900, "s", 0, 1e6, "length of a run (simulated time); the component shows the time left", true);
}

SettingsTable makeVacuumComponent() {
  SettingsTable t = common("vacuum-cleaner");
  worldKeys(t, "Vacuum", "worlds/vacuum.world", "roomba");
  windowKeys(t, "Vacuum.Window", "880, 690", "the vacuum cleaner's window");
  mapKeys(t, "Vacuum", 0.02, "0.005, 0.09");
  motionKeys(t, "Vacuum", 0.5, 3.0, 0.08, 2, 10);
  t.algorithm("Vacuum.Algorithm", "student", {"student", "reference", "classic", "bounce"},
              "the algorithm that drives the roomba (reference: maps the house with its laser and plans its coverage; "
              "classic: the thesis's spiral, walls and bounces; bounce: the random-bounce baseline; PATH.so: a plugin; "
              "PATH.py: a MyAlgorithm.py)");
  t.text("Vacuum.Belief.Channel", "VACUUM_BELIEF",
         "where the algorithm's belief (api.belief: its own pose and map, never graded) is published for the window and the log");
  vacuumDuration(t);
  return t;
}

SettingsTable makeVacuumReferee() {
  SettingsTable t = common("vacuum-cleaner-referee");
  worldKeys(t, "Vacuum", "worlds/vacuum.world", "roomba");
  windowKeys(t, "Vacuum.RefereeWindow", "720, 690", "the referee's window");
  mapKeys(t, "Vacuum", 0.02, "0.005, 0.09");
  vacuumDuration(t);
  t.real("Vacuum.Referee.RobotRadius", 0.165, "m", 0, 10, "radius of the footprint that cleans", true);
  t.real("Vacuum.Referee.Period", 1.0, "s", 0.005, 10,
         "how often the referee syncs with the simulator (simulated time; it counts every pose in between)");
  // Calibrated on the shipped house over 20 seeds (docs/exercises/vacuum.md): the random-bounce
  // baseline's median coverage is about 39 % (a 4.9), the reference's about 66 % (a 10).
  t.real("Vacuum.Referee.HalfMarkCoverage", 40, "%", 0, 100, "coverage worth a 5 (the mark rises linearly from 0 %)", true);
  t.real("Vacuum.Referee.FullMarkCoverage", 60, "%", 0, 100, "coverage worth a 10 (linearly from the half mark's)", true);
  t.text("Vacuum.Referee.Calibration", "",
         "the calibration file the launcher applied (aula run sets it; the report names it); empty: none");
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

SettingsTable makeAutoparkComponent() {
  SettingsTable t = common("autopark");
  worldKeys(t, "Autopark", "worlds/autopark.world", "car");
  windowKeys(t, "Autopark.Window", "1120, 550", "the Autopark window");
  motionKeys(t, "Autopark", 3, 1, 0.05, 10, 5);
  t.algorithm("Autopark.Algorithm", "student", {"student", "reactive", "planner"},
              "PATH.so: a plugin; PATH.py: a MyAlgorithm.py; reactive: the thesis's two arcs; planner: laser map + OMPL "
              "Reeds-Shepp path (docs/planner.md)");
  return t;
}

SettingsTable makeAutoparkReferee() {
  SettingsTable t = common("autopark-referee");
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
  t.text("Autopark.Referee.Calibration", "",
         "the calibration file the launcher applied (aula run sets it; the report names it); empty: none");
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

std::vector<const config::SettingsTable*> Exercise::tables() const {
  std::vector<const config::SettingsTable*> out = {component_settings};
  if (referee_settings != nullptr) out.push_back(referee_settings);
  return out;
}

const config::SettingsTable& simulator() {
  static const SettingsTable table = makeSimulator();  // immutable after construction
  return table;
}

const config::SettingsTable& demo() {
  static const SettingsTable table = makeDemo();
  return table;
}

const std::vector<Exercise>& exercises() {
  static const SettingsTable taxi = makeTaxiComponent(), taxi_referee = makeTaxiReferee();
  static const SettingsTable vacuum = makeVacuumComponent(), vacuum_referee = makeVacuumReferee();
  static const SettingsTable park = makeAutoparkComponent(), park_referee = makeAutoparkReferee();
  static const std::vector<Exercise> all = {
      {"teletaxi", "TeleTaxi", "config/teleTaxi.cfg", "teletaxi", "teletaxi-referee", &taxi, &taxi_referee,
       {"pose3d", "motors", "bumper"}, "global navigation with Gradient Path Planning", "TeleTaxi.Referee.Timeout",
       0.005},
      {"vacuum", "Vacuum", "config/vacuumCleaner.cfg", "vacuum-cleaner", "vacuum-cleaner-referee", &vacuum,
       &vacuum_referee, {"pose3d", "motors", "laser", "bumper"}, "clean the house without localization",
       "Vacuum.Referee.Duration", 0.010},
      {"autopark", "Autopark", "config/autopark.cfg", "autopark", "autopark-referee", &park, &park_referee,
       {"pose3d", "motors", "bumper", "laser:laser_front", "laser:laser_rear", "laser:laser_right"},
       "find the free slot and park in parallel (--world=autopark_ackermann_1.3L.world: a car-like car)",
       "Autopark.Referee.Timeout", 0.005},
      {"demo", "Demo", "config/demo.cfg", "aula-demo-client", "", &demo(), nullptr, {"pose3d", "motors", "laser", "bumper"},
       "the roomba bouncing around the house (no referee)", "", 0.010},
  };
  return all;
}

const Exercise* exerciseOfProgram(const std::string& program) {
  for (const auto& e : exercises()) {
    if (e.component == program || e.referee == program) return &e;
  }
  return nullptr;
}

const Exercise* exerciseNamed(const std::string& name) {
  for (const auto& e : exercises()) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

const Exercise& requireExercise(const std::string& name) {
  if (const Exercise* e = exerciseNamed(name)) return *e;
  throw std::logic_error("no exercise named '" + name + "' in the settings' table of exercises");
}

const config::SettingsTable& tableOf(const std::string& program) {
  if (program == "aula-sim") return simulator();
  for (const auto& e : exercises()) {
    if (e.component == program) return *e.component_settings;
    if (e.referee == program) return *e.referee_settings;
  }
  throw std::logic_error("no settings table for program '" + program + "'");
}

}  // namespace aula::settings
