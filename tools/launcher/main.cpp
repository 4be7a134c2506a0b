// aula run EXERCISE [--headless] [--world=FILE] [--algorithm=NAME] [--seed=N] [--rtf=X] ...
// aula config EXERCISE [--world=FILE] [--Key=value ...]
// aula regrade FILE.lcmlog [--report=FILE.json]
// Starts the simulator and the exercise's processes (like the original's three terminals),
// waits for the run to end and stops everything cleanly: it never leaves a process behind
// (children die with it: PR_SET_PDEATHSIG) and exits non-zero if any process failed.
// Every --Key=value is checked against the declared settings (aula_settings) and handed only to
// the processes that declare it; the world is resolved once and handed to all three.
#include <aula/auth/run_key.hpp>
#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>
#include <aula/grade/grade_command.hpp>
#include <aula/grade/grade_plan.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/process/child_process.hpp>
#include <aula/settings/tables.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include "run_recorder.hpp"

#include <aula/image/png.hpp>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include <nlohmann/json.hpp>

#include <aula/process/exit_codes.hpp>
#include <aula/process/line_pipe.hpp>
#include <aula/process/guarded_main.hpp>
#include <aula/process/signal_watcher.hpp>
#include <aula/process/cpu_affinity.hpp>
#include <aula/sandbox/sandbox.hpp>

#include <fcntl.h>
#include <poll.h>
#include <sstream>
#include <unistd.h>

namespace {

using aula::config::CommandLine;
using aula::config::Config;
using aula::config::ConfigError;
using aula::config::SettingsTable;
using aula::settings::Exercise;

constexpr const char* kUsage =
    "usage: aula run EXERCISE [--headless [--sandbox]] [--world=FILE] [--algorithm=NAME] [--seed=N]\n"
    "                [--report=FILE.json] [--picture=FILE.png] [--record=FILE.lcmlog] [--lockstep] [--rtf=X]\n"
    "                [--duration=SECONDS] [--timeout=WALL_SECONDS] [--lcm-url=URL] [--cpu=N|any] [--config=FILE.cfg]\n"
    "                [--Key=value ...]\n"
    "       aula config EXERCISE [--world=FILE] [--config=FILE.cfg] [--markdown] [--Key=value ...]\n"
    "       aula check-world FILE [--map=FILE.png]\n"
    "       aula new EXERCISE DIR\n"
    "       aula regrade FILE.lcmlog [--report=FILE.json]\n"
    "       aula replay FILE.lcmlog [--speed=X]\n"
    "%GRADE%"
    "  run         start the simulator, the component and the referee\n"
    "  check-world load a world, list its robots, sensors and channels, say what each exercise would miss\n"
    "  config      print the effective settings of each process and where each came from\n"
    "  grade       grade a class: every submission (a folder with MyAlgorithm.cpp) x world x seed, headless;\n"
    "              DIR/grades.csv and DIR/runs/ (see docs/grading.md)\n"
    "  new         start your own algorithm in DIR: MyAlgorithm.cpp, CMakeLists.txt, README.md;\n"
    "              build it with `cmake -S DIR -B DIR/build && cmake --build DIR/build`, run it with\n"
    "              `aula run EXERCISE --algorithm=DIR/build/libmy_algorithm.so`\n"
    "  regrade     grade a run recorded with --record again, from the log alone (no simulator)\n"
    "  replay      play a recorded run back into the exercise's windows (pause, speed, time slider)\n"
    "  --record    write the whole run to FILE.lcmlog (LCM's log format; lcm-logplayer plays it)\n"
    "  --lcm-url   the run's bus (udpm://GROUP:PORT?ttl=0); port 0: a free one from the OS\n"
    "  --sandbox   run the component (the student's code) in bubblewrap: read-only files, no other\n"
    "              process in sight, IPv4 datagram sockets only (as `aula grade` does; docs/grading.md)\n"
    "  --headless  no windows; lockstep, as fast as possible (or at --rtf); the run ends with the mark\n"
    "  --cpu       the CPU a headless run's processes share (default: the one `aula` starts on; they take\n"
    "              turns in lockstep, and one CPU spares them cross-CPU wake-ups); any: the kernel places them\n"
    "  --timeout   a headless run's wall-clock budget (default: the episode at real time x 1.5 + 60 s); past it the\n"
    "              run ends, graded so far, and exits 1\n"
    "  --world     any SDF world: all three processes use it (see docs/worlds.md)\n"
    "  --report    the referee's JSON report; --picture: its PNG picture of the run (both at the end)\n"
    "  --Key=value a declared setting (`aula config EXERCISE` lists them), e.g. --Vacuum.Referee.Duration=300\n"
    "exercises:\n";

int usage(std::ostream& out, int code) {
  const std::string text = kUsage;
  const auto at = text.find("%GRADE%");
  out << text.substr(0, at) << aula::grade::kGradeUsage << text.substr(at + 7);
  for (const auto& ex : aula::settings::exercises()) out << "  " << ex.name << "  " << ex.summary << "\n";
  return code;
}

// Points the component will drive to must be free floor of the world's map: refused here, before
// any process starts, with the reason (the component checks what needs its planner).
void checkPointsOnTheMap(const Exercise& ex, const Config& component, const std::string& world_path) {
  std::optional<aula::world::OccupancyMap> map;
  for (const auto& spec : ex.component_settings->specs()) {
    if (!spec.free_point) continue;
    if (!map) {
      const auto world = aula::world::loadWorld(world_path);
      const auto z_band = component.getDoubleList(ex.section + ".Map.ZBand");
      map = aula::world::occupancyMapOf(world, {component.getDouble(ex.section + ".Map.Resolution"), z_band[0], z_band[1]});
    }
    const auto xy = component.getDoubleList(spec.key);
    if (const auto problem = aula::world::pointProblem(*map, xy[0], xy[1])) {
      throw ConfigError(component.origin(spec.key) + ": " + spec.key + " = " + component.getString(spec.key) + ": " + *problem);
    }
  }
}

// The settings of one run: the .cfg, the --Key=value overrides and what the launcher's own
// options set, resolved for each process against its own table.
struct RunSettings {
  std::string cfg_path;
  Config overrides;  // checked: each key is declared by at least one process of the run
  std::string world;  // absolute path, handed to every process
  std::vector<std::pair<const SettingsTable*, Config>> effective;  // simulator first
};

RunSettings resolveSettings(const Exercise& ex, const CommandLine& cl) {
  RunSettings run;
  run.cfg_path = cl.option("config", aula::config::dataPath(ex.config_file));
  const Config file = Config::fromFile(run.cfg_path);
  for (const auto& [key, value] : cl.overrides) run.overrides.set(key, value, "command line --" + key);
  if (cl.flag("algorithm")) run.overrides.set(ex.section + ".Algorithm", cl.option("algorithm"), "command line --algorithm");
  if (cl.flag("headless") && ex.referee_settings != nullptr) {
    run.overrides.set(ex.section + ".Autostart", "true", "command line --headless");
  }
  if (cl.flag("world")) run.overrides.set(ex.section + ".World", cl.option("world"), "command line --world");
  if (cl.flag("seed")) run.overrides.set("Simulator.Seed", cl.option("seed"), "command line --seed");

  std::vector<const SettingsTable*> tables = {&aula::settings::simulator()};
  for (const auto* t : ex.tables()) tables.push_back(t);
  // Every override must be some process's key; the "did you mean" comes from all of them.
  for (const std::string& key : run.overrides.keys()) {
    bool declared = false;
    for (const auto* t : tables) declared = declared || t->declares(key);
    if (declared) continue;
    std::string suggestion;
    for (const auto* t : tables) {
      if (suggestion.empty()) suggestion = t->suggest(key);
    }
    throw ConfigError(run.overrides.origin(key) + ": unknown key '" + key + "'" +
                      (suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)") + "; `aula config " +
                      ex.name + "` lists the settings");
  }
  for (const auto* t : tables) {
    // The simulator reads config/simulator.cfg (aula-sim does the same), the clients the exercise's.
    Config mine = t == tables.front() ? Config::fromFile(aula::config::dataPath("config/simulator.cfg")) : file;
    for (const std::string& key : run.overrides.keys()) {
      if (t->declares(key)) mine.set(key, run.overrides.getString(key), run.overrides.origin(key));
    }
    std::vector<const SettingsTable*> siblings;
    for (const auto* other : ex.tables()) {
      if (other != t) siblings.push_back(other);
    }
    run.effective.emplace_back(t, t->resolve(mine, siblings));
  }
  // The world, from the component's settings (the .cfg or --world): resolved once for all.
  const Config& component = run.effective[1].second;
  const std::string world_key = ex.section + ".World";
  run.world = aula::config::resolveWorldPath(component.getString(world_key), component.origin(world_key) + ": " + world_key);
  checkPointsOnTheMap(ex, component, run.world);
  return run;
}

// `aula check-world`: the world's facts, one line each.
void printWorld(const aula::world::WorldSpec& spec) {
  namespace world = aula::world;
  std::cout << "world '" << spec.name << "': " << spec.source_path << "\n  sha256 " << spec.sha256 << "\n";
  if (spec.physics_step_s > 0) {
    std::cout << "  physics step " << spec.physics_step_s * 1e3 << " ms (<physics><max_step_size>)\n";
  } else {
    std::cout << "  physics step: not stated, so Simulator.PhysicsStep (default 5 ms)\n";
  }
  if (!spec.statics.empty()) {
    const Eigen::Vector4d b = world::staticBounds(spec);
    std::cout << "  " << spec.statics.size() << " static primitives, x [" << b[0] << ", " << b[2] << "] y [" << b[1]
              << ", " << b[3] << "] m\n";
  }
  for (const auto& robot : spec.robots) {
    const Eigen::Vector3d p = robot.pose.translation();
    std::cout << "robot '" << robot.name << "' at (" << p.x() << ", " << p.y() << "), yaw "
              << world::yawOf(robot.pose) << " rad, " << robot.mass_kg << " kg\n";
    for (const auto& plugin : robot.plugins) {
      std::cout << "  " << plugin.type << " '" << plugin.name << "' on " << plugin.getString("channel", "(no channel)") << "\n";
    }
  }
}

// What `ex` would miss in `spec` with its default settings: its robot, the plugins it needs,
// a start on free floor of its map.
std::vector<std::string> exerciseProblems(const Exercise& ex, const aula::world::WorldSpec& spec) {
  namespace world = aula::world;
  const Config cfg = ex.component_settings->resolve(Config());
  const std::string robot_key = ex.section + ".Robot";
  const world::RobotSpec* robot = spec.findRobot(cfg.getString(robot_key));
  if (robot == nullptr) return {"a robot named '" + cfg.getString(robot_key) + "' (" + robot_key + ")"};
  std::vector<std::string> missing;
  for (const std::string& need : ex.required_plugins) {
    const auto colon = need.find(':');
    try {
      world::channelOf(*robot, need.substr(0, colon), colon == std::string::npos ? "" : need.substr(colon + 1));
    } catch (const world::WorldError&) {
      missing.push_back("a " + need.substr(0, colon) + " plugin" +
                        (colon == std::string::npos ? "" : " named '" + need.substr(colon + 1) + "'"));
    }
  }
  if (cfg.has(ex.section + ".Map.Resolution") && !spec.statics.empty()) {
    const auto z = cfg.getDoubleList(ex.section + ".Map.ZBand");
    const auto map = world::occupancyMapOf(spec, {cfg.getDouble(ex.section + ".Map.Resolution"), z[0], z[1]});
    const Eigen::Vector3d p = robot->pose.translation();
    if (const auto problem = world::pointProblem(map, p.x(), p.y())) missing.push_back("a start on free floor: " + *problem);
  }
  return missing;
}

// aula check-world FILE [--map=FILE.png]: what a teacher runs on a new world.
int checkWorld(const CommandLine& cl) {
  namespace world = aula::world;
  const world::WorldSpec spec = world::loadWorld(aula::config::resolveWorldPath(cl.positional[1], "command line: FILE"));
  printWorld(spec);
  for (const auto& ex : aula::settings::exercises()) {
    if (ex.referee_settings == nullptr) continue;
    const auto missing = exerciseProblems(ex, spec);
    std::cout << ex.name << ": " << (missing.empty() ? "ok" : "cannot run; the world needs");
    for (size_t i = 0; i < missing.size(); ++i) std::cout << (i ? "; " : " ") << missing[i];
    std::cout << "\n";
  }
  if (cl.flag("map")) {
    const Eigen::Vector4d b = world::staticBounds(spec);
    const double resolution_m = std::max(0.01, std::max(b[2] - b[0], b[3] - b[1]) / 1000.0);
    const auto map = world::occupancyMapOf(spec, {resolution_m, 0.01, 100.0});
    if (!aula::image::writePng(cl.option("map"), map.image)) throw ConfigError("--map=" + cl.option("map") + ": cannot write");
    std::cout << "map: " << cl.option("map") << " (" << map.image.cols << " x " << map.image.rows << " px, "
              << resolution_m << " m/px; black = what a robot touches)\n";
  }
  return 0;
}

int printConfig(const Exercise& ex, const CommandLine& cl) {
  const RunSettings run = resolveSettings(ex, cl);
  if (cl.flag("markdown")) {
    // The grading rules of docs/exercises/<exercise>.md (scripts/update-exercise-docs.sh).
    if (ex.referee_settings == nullptr) throw ConfigError("--markdown: '" + ex.name + "' has no referee");
    std::cout << run.effective.back().first->markdown(run.effective.back().second, ex.section + ".Referee.");
    return 0;
  }
  std::cout << "world: " << run.world << "\nconfig: " << run.cfg_path << "\n";
  for (const auto& [table, cfg] : run.effective) {
    std::cout << "\n" << table->owner() << ":\n" << table->describe(cfg);
  }
  return 0;
}

std::string binDir();

// `aula new EXERCISE DIR`: a student's own project, outside Aula's tree. Never overwrites.
int newProject(const Exercise& ex, const std::string& dir) {
  namespace fs = std::filesystem;
  if (ex.referee_settings == nullptr) throw ConfigError("aula new: '" + ex.name + "' has no student algorithm");
  const fs::path root(dir);
  for (const char* name : {"MyAlgorithm.cpp", "CMakeLists.txt", "README.md"}) {
    if (fs::exists(root / name)) {
      throw ConfigError("aula new: " + (root / name).string() + " already exists; nothing was written (choose a new folder)");
    }
  }
  const std::string template_path = aula::config::dataPath("templates/" + ex.name + "/MyAlgorithm.cpp");
  if (!fs::is_regular_file(template_path)) throw ConfigError("aula new: no template at " + template_path);
  std::error_code error;
  fs::create_directories(root, error);
  if (error) throw ConfigError("aula new: cannot create " + dir + ": " + error.message());
  fs::copy_file(template_path, root / "MyAlgorithm.cpp", error);
  if (error) throw ConfigError("aula new: cannot write " + (root / "MyAlgorithm.cpp").string() + ": " + error.message());
  // This Aula's own package first (installed: <prefix>/lib/cmake/Aula; a build tree: build/).
  const fs::path prefix = fs::path(binDir()).parent_path();
  std::ofstream cmake(root / "CMakeLists.txt");
  cmake << "# Your " << ex.name << " algorithm as a plugin: libmy_algorithm.so in build/.\n"
        << "cmake_minimum_required(VERSION 3.16)\n"
        << "project(my_algorithm CXX)\n"
        << "find_package(Aula REQUIRED HINTS \"" << (prefix / "lib" / "cmake" / "Aula").string() << "\" \""
        << prefix.string() << "\")\n"
        << "aula_add_algorithm(NAME my_algorithm EXERCISE " << ex.name << " SOURCES MyAlgorithm.cpp)\n";
  std::ofstream readme(root / "README.md");
  readme << "# My " << ex.name << " algorithm\n"
         << "Edit `MyAlgorithm.cpp` (the API is at its top), then `cmake -S . -B build && cmake --build build`.\n"
         << "Run it: `aula run " << ex.name << " --algorithm=build/libmy_algorithm.so` (add `--headless` for no windows).\n";
  if (!cmake || !readme) throw ConfigError("aula new: cannot write into " + dir);
  std::cout << "aula new: " << ex.name << " project in " << dir << "\n"
            << "  cmake -S " << dir << " -B " << dir << "/build && cmake --build " << dir << "/build\n"
            << "  aula run " << ex.name << " --algorithm=" << dir << "/build/libmy_algorithm.so\n";
  return 0;
}

std::string binDir() {
  char buffer[4096];
  const ssize_t n = readlink("/proc/self/exe", buffer, sizeof buffer - 1);
  std::string self = n > 0 ? std::string(buffer, n) : std::string("./aula");
  const auto slash = self.rfind('/');
  return slash == std::string::npos ? "." : self.substr(0, slash);
}

// `aula replay ...` is aula-replay (a Qt program; the launcher links no Qt): the same arguments.
int replay(int argc, char** argv) {
  const std::string program = binDir() + "/aula-replay";
  std::vector<char*> args = {const_cast<char*>(program.c_str())};
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) != "replay" || args.size() > 1) args.push_back(argv[i]);
  }
  args.push_back(nullptr);
  execv(program.c_str(), args.data());
  throw std::runtime_error("cannot start " + program + ": " + std::strerror(errno));
}

bool noDisplay() {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (display == nullptr || *display == '\0') && (wayland == nullptr || *wayland == '\0');
}

// The three command lines of a run: each process gets the .cfg, the world and only its own keys.
std::vector<std::vector<std::string>> commandLines(const Exercise& ex, const CommandLine& cl, const RunSettings& run) {
  const std::string bin = binDir();
  const size_t clients = ex.referee_settings == nullptr ? 1 : 2;
  std::vector<std::string> sim = {bin + "/aula-sim", run.world};
  if (cl.flag("lockstep") || cl.flag("headless")) {
    sim.push_back("--lockstep");
    sim.push_back("--Simulator.Lockstep.WaitForClients=" + std::to_string(clients));
  }
  // Headless runs go as fast as possible unless --rtf says otherwise; --rtf counts in every mode.
  if (cl.flag("rtf")) sim.push_back("--rtf=" + cl.option("rtf"));
  else if (cl.flag("headless")) sim.push_back("--rtf=0");
  if (cl.flag("lcm-url")) sim.push_back("--lcm-url=" + cl.option("lcm-url"));

  std::vector<std::vector<std::string>> lines = {sim};
  const std::vector<std::string> programs = {ex.component, ex.referee};
  for (size_t i = 0; i < ex.tables().size(); ++i) {
    std::vector<std::string> args = {bin + "/" + programs[i], "--config=" + run.cfg_path,
                                     "--" + ex.section + ".World=" + run.world};
    if (cl.flag("headless")) args.push_back("--headless");
    if (cl.flag("lcm-url")) args.push_back("--lcm-url=" + cl.option("lcm-url"));
    lines.push_back(args);
  }
  for (const std::string& key : run.overrides.keys()) {
    if (key == ex.section + ".World") continue;
    const std::string arg = "--" + key + "=" + run.overrides.getString(key);
    if (aula::settings::simulator().declares(key)) lines[0].push_back(arg);
    for (size_t i = 0; i < ex.tables().size(); ++i) {
      if (ex.tables()[i]->declares(key)) lines[i + 1].push_back(arg);
    }
  }
  if (ex.referee_settings == nullptr && cl.flag("duration")) lines[1].push_back("--duration=" + cl.option("duration"));
  for (const char* output : {"report", "picture"}) {
    if (ex.referee_settings != nullptr && cl.flag(output)) lines[2].push_back(std::string("--") + output + "=" + cl.option(output));
  }
  return lines;
}

std::string programName(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Why a component that ran the student's algorithm ended, in words, or "" when it is not the
// student's doing.
// "SIGSEGV" for a death by signal (exit code 128 + N), else "exit code N".
std::string signalName(int code) {
  if (code <= 128) return "exit code " + std::to_string(code);
  const char* name = sigabbrev_np(code - 128);
  return std::string("SIG") + (name != nullptr ? name : std::to_string(code - 128));
}

std::string componentFault(int code, double execute_budget_s) {
  if (code == aula::process::kExitAlgorithmHung) {
    std::ostringstream text;
    text << "execute() did not return within " << execute_budget_s << " s";
    return text.str();
  }
  if (code > 128) return "component crashed (" + signalName(code) + ")";
  return "";
}

// What the launcher knows of the run it supervises.
struct Supervision {
  std::vector<std::vector<std::string>> lines;  // simulator, component, referee
  bool has_referee = false;
  bool headless = false;
  bool sandbox = false;      // --sandbox: the component (the student's code) runs in aula_sandbox
  double wall_budget_s = 0;  // --timeout: the run's wall-clock budget (0: none)
  std::string exercise, report_path;
  std::string algorithm;        // what the component runs ("student", "libmy_algorithm.so")
  double execute_budget_s = 2;  // Component.ExecuteBudget
  aula::process::Placement placement;  // the three processes' CPU (runCpu), batch when headless
};

// Runs the processes until the primary one (the last: referee or client) ends, any fails, or
// Ctrl-C; then stops the clients first (they send their last commands and leave lockstep).
// When the component dies (a crash, a hung execute()), the referee is told over its private
// control pipe, grades what there is, writes its report and ends the run.
// The report of a run whose referee died: no mark, and why (the referee cannot say it).
void writeAbortedReport(const Supervision& run, const std::string& why) {
  if (run.report_path.empty()) return;
  nlohmann::ordered_json report;
  report["exercise"] = run.exercise;
  report["finished"] = false;
  report["algorithm"] = run.algorithm;
  report["aborted"] = why;
  aula::grade::writeFileAtomically(run.report_path, report.dump(2) + "\n");
}

// One supervised run: its children, the private lines to them, and what has happened so far.
class RunSupervisor {
 public:
  explicit RunSupervisor(const Supervision& run) : run_(run) {}

  int supervise() {
    aula::process::SignalWatcher signals;  // before the children start: they unblock for themselves
    start();
    for (;;) {
      if (signals.stopRequested()) {
        std::cerr << "aula: stopping (" << (signals.signal() == SIGINT ? "SIGINT" : "SIGTERM") << ")\n";
        result_ = 128 + signals.signal();
        break;
      }
      checkWallBudget();
      // The referee had its chance to grade and say why: now everything stops.
      if (ending_since_ && std::chrono::steady_clock::now() - *ending_since_ > std::chrono::seconds(5)) break;
      readSimulatorStatus();
      bool finished = false;
      for (size_t i = 0; i < children_.size(); ++i) {
        if (const auto code = children_[i]->poll()) finished = onExit(i, *code) || finished;
      }
      if (finished) break;
      awaitEvent(signals);
    }
    stopAll();
    return result_;
  }

 private:
  // Starts the simulator, the component (sandboxed if asked) and the referee, each with its
  // private lines: the simulator's status pipe, the referee's control pipe, a graded run's key.
  void start() {
    int control[2] = {-1, -1}, status[2] = {-1, -1};
    if (run_.has_referee && (pipe2(control, O_CLOEXEC) != 0 || pipe2(status, O_CLOEXEC) != 0)) {
      throw std::runtime_error("pipe2 failed");
    }
    // A graded run's key, for the simulator and the referee only (never the component, which runs
    // the student's code): each reads it from a pipe of its own, not from its command line.
    const std::optional<aula::auth::Key> key =
        run_.headless && run_.has_referee ? std::optional<aula::auth::Key>(aula::auth::randomKey()) : std::nullopt;
    for (size_t i = 0; i < run_.lines.size(); ++i) {
      const bool referee = run_.has_referee && i == 2;
      const bool keyed = key && (i == 0 || referee);
      std::vector<std::string> args = run_.lines[i];
      std::vector<int> passed;
      auto pass = [&](const std::string& option, int fd) {
        args.push_back("--" + option + "=" + std::to_string(aula::process::ChildProcess::passedFd(passed.size())));
        passed.push_back(fd);
      };
      if (i == 0 && status[1] >= 0) pass("status-fd", status[1]);  // why the simulator ended a graded run
      if (referee) pass("control-fd", control[0]);
      if (keyed) pass("key-fd", aula::auth::keyPipe(*key));
      const bool sandboxed = run_.sandbox && run_.has_referee && i == 1;
      if (sandboxed) {  // the student's code: in bubblewrap, under the seccomp filter (docs/grading.md)
        const int seccomp_child_fd = aula::process::ChildProcess::passedFd(passed.size());
        passed.push_back(aula::sandbox::seccompProgram());
        args = aula::sandbox::wrap(args, seccomp_child_fd);
      }
      children_.push_back(std::make_unique<aula::process::ChildProcess>(args, "", "", passed, run_.placement));
      if (keyed || sandboxed) close(passed.back());  // the child has its copy
    }
    if (control[0] >= 0) close(control[0]);
    if (status[1] >= 0) close(status[1]);
    control_fd_ = control[1];
    simulator_status_ = std::make_unique<aula::process::LinePipe>(status[0]);
  }

  void tellReferee(const std::string& why) {
    const std::string line = "abort " + why + "\n";
    (void)!write(control_fd_, line.data(), line.size());
    told_referee_ = true;
    abort_reason_ = why;
    result_ = 1;
  }

  // The referee is told why the run ends and has a few seconds to grade what there is.
  void endRun(const std::string& why) {
    if (run_.has_referee && !told_referee_) tellReferee(why);
    ending_since_ = std::chrono::steady_clock::now();
    result_ = 1;
  }

  void checkWallBudget() {
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    if (run_.wall_budget_s > 0 && wall_s > run_.wall_budget_s && !ending_since_) {
      std::ostringstream why;
      why << "the run's wall-clock budget of " << run_.wall_budget_s << " s ran out (--timeout)";
      std::cerr << "aula: " << why.str() << "\n";
      endRun(why.str());
    }
  }

  // Sleeps until a child exits or a stop signal comes, or 20 ms pass (the wall budget, the
  // simulator's status line): the end of a run is seen when it happens.
  void awaitEvent(const aula::process::SignalWatcher& signals) {
    std::vector<pollfd> watched{{signals.fd(), POLLIN, 0}};
    for (const auto& child : children_) {
      if (child->exitFd() >= 0 && !child->poll()) watched.push_back({child->exitFd(), POLLIN, 0});
    }
    ::poll(watched.data(), watched.size(), 20);
  }

  void readSimulatorStatus() {
    for (const std::string& line : simulator_status_->lines()) {
      if (line.rfind("ended ", 0) != 0 || simulator_ended_run_) continue;
      simulator_ended_run_ = true;
      std::cerr << "aula: the simulator ended the run: " << line.substr(6) << "\n";
      endRun(line.substr(6));
    }
  }

  // Child `i` exited with `code`: says why and decides. True when the run is over.
  bool onExit(size_t i, int code) {
    const bool has_referee = run_.has_referee;
    if (i == 0) readSimulatorStatus();  // its last words were written before it exited
    if (has_referee && i == 2) referee_exited_ = true;
    if (i == 0 && simulator_ended_run_) return false;  // the referee grades what there is and ends the run
    const std::string name = programName(children_[i]->name());
    if (has_referee && i == 2 && code > 128) {
      const std::string why = name + " died (" + signalName(code) + ")";
      std::cerr << "aula: " << why << ": the run has no mark\n";
      writeAbortedReport(run_, why);
      result_ = 1;
      return true;
    }
    if (has_referee && i < 2 && code == aula::process::kExitUsage && control_fd_ >= 0) {
      (void)!write(control_fd_, "discard\n", 8);  // the run never started: the referee gives no mark
    }
    if (has_referee && i == 1 && code == 0 && !run_.headless) {
      std::cerr << "aula: the component's window was closed: stopping the run\n";
      return true;
    }
    const std::string fault = has_referee && i == 1 ? componentFault(code, run_.execute_budget_s) : "";
    if (!fault.empty() && !told_referee_) {
      std::cerr << "aula: " << name << " (running the algorithm '" << run_.algorithm << "') ended the run: " << fault << "\n";
      tellReferee(fault);
      return false;  // the referee grades what there is and ends the run
    }
    const bool faulted_component = told_referee_ && i == 1;
    if (has_referee && i == 2 && code == aula::process::kExitFailed) {
      std::cerr << "aula: the run ended before its end: the referee's report says why\n";
      result_ = 1;
    } else if (code != 0 && !faulted_component) {
      std::cerr << "aula: " << name << " exited with code " << code << "\n";
      result_ = code == 2 ? 2 : 1;
    }
    return (code != 0 && !faulted_component) || i + 1 == children_.size() || i == 0;
  }

  // The clients first (they send their last commands and leave lockstep), the simulator last.
  void stopAll() {
    if (control_fd_ >= 0) close(control_fd_);
    for (auto c = children_.rbegin(); c != children_.rend(); ++c) {
      const int code = (*c)->stop();
      if (code != 0 && code != 128 + SIGTERM && code != 128 + SIGINT && result_ == 0 && (*c)->name() != run_.lines[0][0]) {
        std::cerr << "aula: " << (*c)->name() << " stopped with code " << code << "\n";
      }
    }
    if (told_referee_ && !referee_exited_) {
      // Told why, the referee did not answer in time (stopped, hung): the report says why, no mark.
      std::cerr << "aula: the referee did not grade in time: the run has no mark\n";
      writeAbortedReport(run_, abort_reason_ + "; the referee did not answer");
    }
  }

  const Supervision& run_;
  const std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::vector<std::unique_ptr<aula::process::ChildProcess>> children_;
  int control_fd_ = -1;  // the referee's control pipe, our end
  std::unique_ptr<aula::process::LinePipe> simulator_status_;
  int result_ = 0;
  bool told_referee_ = false, referee_exited_ = false, simulator_ended_run_ = false;
  std::string abort_reason_;
  std::optional<std::chrono::steady_clock::time_point> ending_since_;
};

int supervise(const Supervision& run) { return RunSupervisor(run).supervise(); }

// A headless run's wall-clock budget when --timeout does not say: the episode's sim length at
// real time (or at --rtf), half again, plus a minute for start-up. A run past it is stuck.
double defaultWallBudget(const Exercise& ex, const CommandLine& cl, const RunSettings& run) {
  if (ex.referee_settings == nullptr) return 0;
  const Config& referee = run.effective.back().second;
  double sim_s = 0;
  for (const std::string& key : {ex.section + ".Referee.Duration", ex.section + ".Referee.Timeout"}) {
    if (referee.has(key)) sim_s = std::max(sim_s, referee.getDouble(key));
  }
  const double rtf = cl.optionDouble("rtf", 0);
  return 60.0 + 1.5 * sim_s / (rtf > 0 ? std::min(rtf, 1.0) : 1.0);
}

// --record: the logger listens and the log holds the run's record before the simulator starts.
std::unique_ptr<aula::launcher::RunRecorder> startRecording(const Exercise& ex, const CommandLine& cl,
                                                            const RunSettings& run) {
  if (ex.referee_settings == nullptr) throw ConfigError("--record: '" + ex.name + "' has no referee to grade the log");
  aula::launcher::RunRecorder::checkPath(cl.option("record"));
  const Config& referee = run.effective.back().second;
  const auto record = aula::launcher::runRecord(ex, run.world, run.effective.front().second.getInt64("Simulator.Seed"), referee);
  return std::make_unique<aula::launcher::RunRecorder>(cl.option("record"),
                                                       aula::lcmbus::resolveUrl(cl, referee), record);
}

}  // namespace

// A headless run is one thread of control handed from process to process (lockstep): its three
// processes share one CPU, as batch tasks (aula/process/cpu_affinity.hpp). The CPU: --cpu=N, or
// the one the launcher runs on; -1 (--cpu=any, and runs with windows): wherever the kernel puts
// them. The launcher itself stays free (its recorder drains the run's log on another CPU).
int runCpu(const CommandLine& cl) {
  const std::string choice = cl.flag("cpu") ? cl.option("cpu") : cl.flag("headless") ? "auto" : "any";
  if (choice == "any") return -1;
  const std::vector<int> allowed = aula::process::allowedCpus();
  if (allowed.empty()) return -1;
  if (choice == "auto") return aula::process::currentCpu(allowed);
  char* end = nullptr;
  const long asked = std::strtol(choice.c_str(), &end, 10);
  if (choice.empty() || *end != '\0' || std::find(allowed.begin(), allowed.end(), asked) == allowed.end()) {
    throw ConfigError("--cpu=" + choice + ": one of the CPUs this process may use (" + aula::process::cpuList(allowed) +
                      "), auto or any");
  }
  return static_cast<int>(asked);
}

int main(int argc, char** argv) {
  return aula::process::guardedMain("aula", [&]() -> int {
    auto cl = CommandLine::parse(argc, argv, {});
    if (!cl.positional.empty() && (cl.positional[0] == "grade" || cl.positional[0] == "grade-task") && !cl.flag("help")) {
      return aula::grade::gradeCommand(cl, binDir());
    }
    if (!cl.positional.empty() && cl.positional[0] == "replay") return replay(argc, argv);
    cl.requireKnown({"headless", "sandbox", "world", "algorithm", "report", "picture", "record", "lockstep", "rtf", "seed",
                     "duration", "timeout", "lcm-url", "cpu", "config", "map", "markdown", "help"});
    if (cl.flag("help")) return usage(std::cout, 0);
    if (cl.positional.size() == 2 && cl.positional[0] == "check-world") return checkWorld(cl);
    if (cl.positional.size() == 2 && cl.positional[0] == "regrade") {
      return aula::launcher::regrade(cl.positional[1], cl.option("report"), binDir());
    }
    if (!cl.positional.empty() && cl.positional[0] == "new") {
      if (cl.positional.size() != 3) return usage(std::cerr, 2);
      const Exercise* ex = aula::settings::exerciseNamed(cl.positional[1]);
      if (ex == nullptr) {
        std::cerr << "aula: unknown exercise '" << cl.positional[1] << "'\n";
        return usage(std::cerr, 2);
      }
      return newProject(*ex, cl.positional[2]);
    }
    if (cl.positional.size() != 2 || (cl.positional[0] != "run" && cl.positional[0] != "config")) {
      return usage(std::cerr, 2);
    }
    const Exercise* ex = aula::settings::exerciseNamed(cl.positional[1]);
    if (ex == nullptr) {
      std::cerr << "aula: unknown exercise '" << cl.positional[1] << "'\n";
      return usage(std::cerr, 2);
    }
    if (cl.positional[0] == "config") return printConfig(*ex, cl);
    if (!cl.flag("headless") && noDisplay()) {
      std::cerr << "aula: no display (DISPLAY is not set): running headless; the mark is printed at the end\n";
      cl.options["headless"] = "";
    }
    if (cl.flag("rtf")) cl.optionDouble("rtf", 0);  // a number, or a usage error now
    if (cl.flag("sandbox") && !cl.flag("headless")) {
      throw ConfigError("--sandbox runs the student's component headless, in bubblewrap: add --headless");
    }
    if (cl.flag("sandbox") && aula::sandbox::bubblewrapPath().empty()) {
      throw ConfigError("--sandbox needs bubblewrap (/usr/bin/bwrap): apt install bubblewrap");
    }
    const int run_cpu = runCpu(cl);
    // The referee's output files: a folder that is not there is refused before anything starts.
    for (const char* output : {"report", "picture"}) {
      if (cl.flag(output)) aula::config::requireWritableFolder(cl.option(output), std::string("--") + output + "=" + cl.option(output));
    }
    // A report from an earlier run must never pass for this one's, whatever happens next.
    for (const char* output : {"report", "picture"}) {
      if (cl.flag(output)) std::filesystem::remove(cl.option(output));
    }
    const double timeout_s = cl.optionDouble("timeout", 0);
    if (cl.flag("timeout") && !(timeout_s > 0)) throw ConfigError("--timeout=" + cl.option("timeout") + ": seconds > 0");
    // Port 0 (`aula grade`'s runs): a port the OS hands out, now, for all three processes.
    if (cl.flag("lcm-url")) cl.options["lcm-url"] = aula::lcmbus::withFreePort(cl.option("lcm-url"));
    const RunSettings run = resolveSettings(*ex, cl);
    Supervision supervision;
    supervision.exercise = ex->name;
    supervision.report_path = cl.option("report");
    supervision.headless = cl.flag("headless");
    supervision.sandbox = cl.flag("sandbox");
    supervision.placement = {run_cpu, supervision.headless};
    supervision.wall_budget_s = cl.flag("timeout") ? timeout_s : supervision.headless ? defaultWallBudget(*ex, cl, run) : 0;
    supervision.lines = commandLines(*ex, cl, run);
    supervision.has_referee = ex->referee_settings != nullptr;
    if (supervision.has_referee) {
      const Config& component = run.effective[1].second;
      supervision.algorithm = component.getString(ex->section + ".Algorithm");
      supervision.execute_budget_s = component.getDouble("Component.ExecuteBudget");
    }
    std::unique_ptr<aula::launcher::RunRecorder> recorder;
    if (cl.flag("record")) recorder = startRecording(*ex, cl, run);
    const int code = supervise(supervision);
    if (recorder) recorder->stop();
    return code;
  });
}
