#include "aula/settings/tables.hpp"

#include "aula/settings/exercise_keys.hpp"

#include <aula/config/paths.hpp>

#include <algorithm>
#include <stdexcept>

namespace aula::settings {
namespace {

using config::SettingsTable;

SettingsTable makeSimulator() {
  SettingsTable t = programTable("aula-sim");
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
  SettingsTable t = programTable("aula-demo-client");
  t.text("Demo.World", "worlds/vacuum.world", "the SDF world (absolute, or relative to the data folder)");
  t.text("Demo.Robot", "roomba", "the robot's model name in the world; its plugins name its channels");
  t.real("Demo.Period", 0.08, "s", 0.005, 1, "control period, seconds of simulated time");
  t.real("Demo.MaxV", 0.3, "m/s", 0, 10, "forward speed", true);
  t.real("Demo.TurnW", 1.0, "rad/s", 0, 20, "turn rate when blocked", true);
  t.real("Demo.Clearance", 0.4, "m", 0, 10, "turn when the laser sees anything closer", true);
  return t;
}

}  // namespace

std::vector<const config::SettingsTable*> Exercise::tables() const {
  std::vector<const config::SettingsTable*> out = {component_settings.get()};
  if (referee_settings != nullptr) out.push_back(referee_settings.get());
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
  // Built once, immutable after: the declared exercises (exercise_registry.cpp, generated from
  // each exercise's aula_exercise()), then the demo.
  static const std::vector<Exercise> all = [] {
    std::vector<Exercise> out = declaredExercises();
    std::sort(out.begin(), out.end(), [](const Exercise& a, const Exercise& b) { return a.name < b.name; });
    Exercise demo_run;  // the demo client bouncing the roomba: a program, no referee, no student
    demo_run.name = "demo";
    demo_run.section = "Demo";
    demo_run.config_file = "config/demo.cfg";
    demo_run.component = "aula-demo-client";
    demo_run.component_settings = std::make_shared<const SettingsTable>(demo());
    demo_run.required_plugins = {"pose3d", "motors", "laser", "bumper"};
    demo_run.summary = "the roomba bouncing around the house (no referee)";
    demo_run.physics_step_s = 0.010;
    out.push_back(std::move(demo_run));
    return out;
  }();
  return all;
}

std::string exerciseNames(bool with_demo) {
  std::vector<std::string> names;
  for (const auto& e : exercises()) {
    if (with_demo || e.referee_settings != nullptr) names.push_back(e.name);
  }
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return out;
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

ProcessSettings resolveProcesses(const Exercise& ex, const config::Config& exercise_file, const config::Config& overrides) {
  std::vector<const SettingsTable*> tables = {&simulator()};
  for (const auto* t : ex.tables()) tables.push_back(t);
  ProcessSettings processes;
  for (const auto* t : tables) {
    config::Config mine = t == tables.front() ? config::Config::fromFile(config::dataPath("config/simulator.cfg")) : exercise_file;
    for (const std::string& key : overrides.keys()) {
      if (t->declares(key)) mine.set(key, overrides.getString(key), overrides.origin(key));
    }
    std::vector<const SettingsTable*> siblings;
    for (const auto* other : ex.tables()) {
      if (other != t) siblings.push_back(other);
    }
    processes.emplace_back(t, t->resolve(mine, siblings));
  }
  return processes;
}

config::Config mergedSettings(const ProcessSettings& processes) {
  config::Config merged;
  for (const auto& [table, cfg] : processes) {
    for (const std::string& key : cfg.keys()) {
      if (!merged.has(key)) merged.set(key, cfg.getString(key), cfg.origin(key));
    }
  }
  return merged;
}

}  // namespace aula::settings
