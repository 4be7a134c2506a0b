// aula-sim WORLD [--config simulator.cfg] [--lockstep] [--rtf X] [--seed N] [--lcm-url URL]
//                [--duration S] [--Simulator.Key=value ...]
// Headless by default, like gzserver.
#include "src/sim_view.hpp"

#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>
#include <aula/settings/tables.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/lcm/log_replay.hpp>
#include <aula/motors_t.hpp>
#include <aula/process/exit_codes.hpp>
#include <aula/process/guarded_main.hpp>
#include <aula/process/signal_watcher.hpp>
#include <aula/sim/simulator.hpp>
#include <aula/world/world_spec.hpp>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>

namespace {

constexpr const char* kUsage =
    "usage: aula-sim WORLD [--gui] [--config FILE] [--lockstep] [--rtf X] [--seed N] [--lcm-url URL]\n"
    "                [--duration SECONDS] [--paused] [--Simulator.Key=value ...]\n"
    "  WORLD        an SDF world, e.g. worlds/vacuum.world\n"
    "  --gui        open a 3D view of the world (headless by default, like gzserver)\n"
    "  --screenshot=FILE.png  with --gui: save the view after one second of wall time\n"
    "  --config     simulator settings (default: config/simulator.cfg if present)\n"
    "  --lockstep   advance only when every registered client has acknowledged\n"
    "  --rtf X      real-time factor in free-running mode (0 = as fast as possible)\n"
    "  --duration   stop after this many simulated seconds\n"
    "  --commands=RUN.lcmlog  drive the robots with the motors commands recorded in a run's log\n"
    "               (aula run --record), each at the tick it answered: the run's motions, no component\n";

// The simulator settings: the .cfg (--config, else the data folder's if present), then the
// command-line flags and --Simulator.Key=value, checked against the declared table.
aula::config::Config simulatorConfig(const aula::config::CommandLine& cl) {
  using namespace aula;
  config::Config file;
  if (cl.flag("config")) {
    file = config::Config::fromFile(cl.option("config"));
  } else {
    const std::string fallback = config::dataPath("config/simulator.cfg");
    if (std::ifstream(fallback).good()) file = config::Config::fromFile(fallback);
  }
  if (cl.flag("lockstep")) file.set("Simulator.Lockstep", "true", "command line --lockstep");
  if (cl.flag("paused")) file.set("Simulator.StartPaused", "true", "command line --paused");
  if (cl.flag("rtf")) file.set("Simulator.RealTimeFactor", cl.option("rtf"), "command line --rtf");
  if (cl.flag("seed")) file.set("Simulator.Seed", cl.option("seed"), "command line --seed");
  if (cl.flag("duration")) file.set("Simulator.Duration", cl.option("duration"), "command line --duration");
  cl.applyOverrides(file);
  return settings::simulator().resolve(file);  // checks every key first
}

// A world's <physics><max_step_size> does not choose the step: Simulator.PhysicsStep does (`aula
// run` sets the exercise's), so the same house gives the same marks whether it states one or not.
void sayWorldStepIgnored(const aula::world::WorldSpec& spec, const aula::sim::SimulatorOptions& options) {
  if (spec.physics_step_s > 0 && std::abs(spec.physics_step_s - options.step_s) > 1e-12) {
    std::cerr << "aula-sim: " << spec.source_path << " states <max_step_size>" << spec.physics_step_s
              << "</max_step_size>; the step is Simulator.PhysicsStep, " << options.step_s * 1e3 << " ms\n";
  }
}

// --gui: runs with a 3D view looking at the first robot, from a distance that fits the world.
void runWithView(aula::sim::Simulator& simulator, const std::string& screenshot,
                 const aula::desktop::Placement& window, aula::process::SignalWatcher& signals) {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  if (simulator.physics().robotCount() > 0) center = simulator.physics().robotState(0).position_m;
  double size_m = 10.0;
  for (const auto& o : simulator.spec().statics) {
    size_m = std::max(size_m, 0.5 * (o.pose.translation().head<2>() - center.head<2>()).norm());
  }
  aula::sim::SimView view(simulator.physics().dartWorld(), center, std::min(size_m, 60.0), window);
  int frames = 0;
  simulator.run([&] { return signals.stopRequested() || simulator.secondOnTheBus().has_value(); }, [&] {
    if (++frames == 30 && !screenshot.empty()) view.captureNextFrame(screenshot);
    return view.frame();
  });
  // A loaded machine may draw fewer than 30 frames in a short run: the screenshot is still taken.
  if (frames < 30 && !screenshot.empty()) {
    view.captureNextFrame(screenshot);
    view.frame();
  }
}

int runSimulator(int argc, char** argv) {
  using namespace aula;
  const auto cl = config::CommandLine::parse(argc, argv, {"config", "rtf", "seed", "lcm-url", "duration", "commands"});
  if (cl.flag("help")) {
    std::cout << kUsage << "\nSettings (in the .cfg, or --Key=value on the command line):\n"
              << settings::simulator().help();
    return 0;
  }
  cl.requireKnown({"config", "lockstep", "rtf", "seed", "lcm-url", "duration", "paused", "gui", "screenshot", "key-fd", "status-fd", "commands", "help"});
  if (cl.positional.size() != 1) {
    std::cerr << "aula-sim: expected exactly one WORLD file\n" << kUsage;
    return process::kExitUsage;
  }
  const config::Config cfg = simulatorConfig(cl);
  auto options = sim::SimulatorOptions::fromConfig(cfg);
  // The bus before the world: the clients, started with the simulator, register while it loads.
  auto bus = lcmbus::openBus(lcmbus::resolveUrl(cl, cfg));
  sim::Simulator::listenForClients(*bus);
  world::WorldSpec spec = world::loadWorld(config::resolveWorldPath(cl.positional[0], "command line: WORLD"));
  sim::applyStartPoses(cfg, spec);
  sayWorldStepIgnored(spec, options);
  process::SignalWatcher signals;
  // --key-fd=N: a graded run's key, from the launcher (docs/grading.md, "What a student's code can do").
  std::optional<auth::Key> key;
  if (cl.flag("key-fd")) key = auth::readKey(static_cast<int>(cl.optionDouble("key-fd", -1)), "--key-fd");
  // --status-fd=N: the launcher's pipe, told why the simulator ended a run early.
  const int status_fd = cl.flag("status-fd") ? static_cast<int>(cl.optionDouble("status-fd", -1)) : -1;
  options.watch_client_processes = status_fd < 0;  // alone, no launcher watches the processes
  // Another simulator on this URL would drive our clients with its clock: before our first tick,
  // ask (SIM_HELLO, sent as the simulator is built) and listen for one (while the world loads,
  // then up to listen_for in all). A running simulator answers at once with its tick: its
  // loop handles the bus at every tick, and waits at most 20 ms at a time when it waits for
  // clients, is paused or paced; it also ticks at least every 100 ms of wall time by itself.
  // Started by hand (no launcher, which gives each run a bus of its own), a second simulator on a
  // bus is a real risk and its start is not urgent: it listens longer, for a running one that a
  // loaded machine schedules late. Should it still miss it, it stops at the first tick it hears
  // from a simulator with clients while it has none (secondOnTheBus).
  const auto listen_for = status_fd < 0 ? std::chrono::milliseconds(1000) : std::chrono::milliseconds(60);
  const auto listen_until = std::chrono::steady_clock::now() + listen_for;
  sim::Simulator simulator(std::move(spec), options, *bus, key);
  if (cl.flag("commands")) {
    simulator.driveWith(lcmbus::recordedMessagesOfType(cl.option("commands"), aula::motors_t::getHash()));
  }
  auto alreadyRunning = [&](const aula::sim_clock_t& other) {
    return config::ConfigError("another simulator (instance " + std::to_string(other.instance) + ", world " + other.world +
                               ") is already running on " + bus->url());
  };
  if (const auto other = simulator.otherSimulatorUntil(listen_until)) throw alreadyRunning(*other);
  // One write: the run's other processes write to the same terminal or log at the same moment.
  std::ostringstream started;
  started << "aula-sim: world '" << simulator.spec().name << "' (" << simulator.spec().source_path << ", sha256 "
          << simulator.spec().sha256.substr(0, 12) << ") with " << simulator.physics().robotCount() << " robot(s), step "
          << options.step_s * 1e3 << " ms, " << (options.lockstep ? "lockstep" : "free-running") << ", seed " << options.seed
          << (key ? ", graded (signed truth, signed SIM_CONTROL only)" : "") << "\n";
  std::cerr << started.str() << std::flush;
  if (cl.flag("gui")) {
    runWithView(simulator, cl.option("screenshot"), aula::desktop::placementOf(cfg, "Simulator.Window"), signals);
  } else {
    simulator.run([&] { return signals.stopRequested() || simulator.secondOnTheBus().has_value(); });
  }
  if (simulator.secondOnTheBus()) throw alreadyRunning(*simulator.secondOnTheBus());
  std::cerr << "aula-sim: stopped at " << simulator.timeUs() / 1e6 << " s of sim time";
  if (simulator.rejectedControls() > 0) std::cerr << "; " << simulator.rejectedControls() << " SIM_CONTROL requests rejected";
  if (simulator.foreignTicks() > 0) std::cerr << "; " << simulator.foreignTicks() << " ticks of another simulator heard";
  std::cerr << "\n";
  if (!simulator.endedBecause().empty()) {
    // The launcher's private line (--status-fd): why, for the referee's report.
    if (status_fd >= 0) {
      const std::string line = "ended " + simulator.endedBecause() + "\n";
      (void)!::write(status_fd, line.data(), line.size());
    }
    // Then the clients: the launcher knows why before any client can end because of it.
    simulator.announceEnd();
    return process::kExitFailed;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return aula::process::guardedMain("aula-sim", [&] { return runSimulator(argc, argv); });
}
