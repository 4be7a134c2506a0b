#include "aula/settings/exercise_keys.hpp"

#include <cctype>

namespace aula::settings {

using config::SettingsTable;

SettingsTable programTable(const std::string& program) {
  SettingsTable t(program);
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
  t.text(section + ".Console.Channel", upper + "_CONSOLE",
         "channel of what the student's program prints (console_t; never graded): the run's log keeps it and the "
         "referee's trace carries it to the run's player");
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
  t.flag("Component.OwnProcess", true,
         "run the student's algorithm in a process of its own, which gets only what the API gives and makes only "
         "the system calls on its list, no socket (the component keeps the world, the bus and the run's keys); "
         "off: inside the component");
  t.real("Component.Sandbox.Memory", 2048, "MB", 64, 1e7,
         "memory the student's code may use: in a sandboxed (graded) run its processes together, past it the run ends "
         "with that reason; in every run the address space of the algorithm's own process (Component.OwnProcess)");
  t.integer("Component.Sandbox.Processes", 64, "", 0, 4096,
            "processes the student's code may start in a sandboxed run; past it the run ends with that reason");
  t.real("Component.Sandbox.FileSize", 64, "MB", 1, 1e7,
         "the largest file the student's code may write in a sandboxed run, and its private temporary folder's size");
  t.real("Component.Sandbox.Output", 256, "MB", 1, 1e7,
         "what the student's code may print in a sandboxed run (stdout and stderr); past it the run ends with that reason");
}

void calibrationKey(SettingsTable& t, const std::string& section) {
  t.text(section + ".Referee.Calibration", "",
         "the calibration file the launcher applied (aula run sets it; the report names it); empty: none");
}

std::vector<std::string> reachKeys(const std::string& section) {
  return {section + ".MaxV", section + ".MaxW", "Simulator.Noise.LaserStddev", "Simulator.Noise.LaserDropout",
          "Simulator.Noise.WheelSlip"};
}

}  // namespace aula::settings
