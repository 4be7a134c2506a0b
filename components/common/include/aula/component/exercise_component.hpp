#pragma once
// What every academic component is, whatever its exercise: the robot named by
// `<Prefix>.Robot`, its true pose (for the window) and its motors, the algorithm table by name
// (the exercise's built-ins, "student", or a plugin), the sim-time control loop, the episode
// messages for the referee, the referee's status, teleoperation, Autostart and hot reload.
// An exercise derives from it, adds its own sensors and API, and says how the student's
// algorithm is called (`execute`). The settings it reads are the same keys under every
// exercise's prefix: Period, Algorithm, Robot, MaxV, MaxW, Autostart, Episode.Channel,
// RefereeStatus.Channel, and Component.ExecuteBudget.

#include <aula/component/algorithm_host.hpp>
#include <aula/component/control_loop.hpp>
#include <aula/component/crash_report.hpp>
#include <aula/component/episode_sender.hpp>
#include <aula/component/proxies.hpp>
#include <aula/component/referee_status.hpp>
#include <aula/config/config.hpp>
#include <aula/console_t.hpp>
#include <aula/sim_control_t.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/settings/tables.hpp>
#include <aula/world/world_spec.hpp>

#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace aula::component {

// The Component.*Budget settings, read once.
inline AlgorithmBudgets budgetsOf(const config::Config& cfg) {
  AlgorithmBudgets b;
  const double blocked_s = cfg.getDouble("Component.BlockedLimit");
  b.start = {cfg.getDouble("Component.StartBudget"), blocked_s, "Component.StartBudget"};
  b.execute = {cfg.getDouble("Component.ExecuteBudget"), blocked_s, "Component.ExecuteBudget"};
  b.plan = {cfg.getDouble("Component.PlanBudget"), blocked_s, "Component.PlanBudget"};
  b.run = {cfg.getDouble("Component.RunBudget"), cfg.getDouble("Component.RunBlockedLimit")};
  b.memory_bytes = static_cast<uint64_t>(cfg.getDouble("Component.Sandbox.Memory") * (1 << 20));
  return b;
}

template <class Algorithm>
class ExerciseComponent {
 public:
  using Host = AlgorithmHost<Algorithm>;

  // `exercise`: its name in the settings' table of exercises ("vacuum"), which gives the keys'
  // section ("Vacuum") and the program's name ("vacuum-cleaner", also its lockstep client's).
  // `cfg`: the effective settings; the robot and its channels come from `world`. Throws
  // PluginError (exit 2) for an algorithm that cannot be used, WorldError for a missing robot.
  // `lockstep_key`: a graded run's key for the component's lockstep client (--lockstep-key-fd).
  ExerciseComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                    const std::string& exercise, const std::optional<auth::Key>& lockstep_key = std::nullopt)
      : ExerciseComponent(bus, cfg, world, settings::requireExercise(exercise), lockstep_key) {}
  virtual ~ExerciseComponent() = default;
  ExerciseComponent(const ExerciseComponent&) = delete;
  ExerciseComponent& operator=(const ExerciseComponent&) = delete;

  // "Run my algorithm" (TeleTaxi's GO!) and its Stop; stopping stops the robot.
  void setRunning(bool running) {
    if (running) releaseTheStart();
    loop_->setRunning(running);
    if (running && started_utime_ < 0) {
      started_utime_ = loop_->simTimeUs();  // the referee's clock starts at Run
      // Out of lockstep the world did not wait for the algorithm: its timing is the machine's.
      if (loop_->clockSeen() && !loop_->inLockstep()) noteNotTheSeedsRun("not in lockstep (--lockstep=off)");
    }
    episode_->markChanged();
  }
  bool running() const { return loop_->running(); }
  // "Run my algorithm" or Stop pressed in a window (TeleTaxi's GO! and Stop): setRunning, and a
  // stop, or a run again, inside the episode makes this run another than its seed's graded one.
  void pressRun(bool on) {
    if (on != running() && started_utime_ >= 0 && !episodeOver()) noteNotTheSeedsRun(on ? "run again after a stop" : "stopped during the episode");
    setRunning(on);
  }
  void teleoperate(double v_mps, double w_radps) {  // ignored while the algorithm runs
    if (running()) return;
    if (v_mps != 0 || w_radps != 0) {
      if (started_utime_ < 0) {
        noteNotTheSeedsRun("teleoperated before Run");  // headless, the algorithm starts from the world at 0 s
      } else if (!episodeOver()) {
        noteNotTheSeedsRun("teleoperated during the episode");
      }
      releaseTheStart();
    }
    motors_->sendV(v_mps);
    motors_->sendW(w_radps);
  }
  // Why this run is no longer its seed's graded run (a headless run of the seed), or "" while it
  // is: the referee's report and every window's status say it (episode_t.not_the_seeds_run).
  const std::string& notTheSeedsRun() const { return not_the_seeds_run_; }
  // Hot reload: loads the algorithm again (a plugin's new build), puts the robot back at its
  // start and starts a new episode, running again if it ran and the exercise allows it. False
  // when the new build cannot be used (the algorithm's fault says why).
  bool reloadAlgorithm() {
    if (host_->hung()) return false;  // a call is still stuck in it: the fault says so
    const bool was_running = running();
    setRunning(false);
    // The new episode starts from the start pose at this sim time, not from the world at 0 s.
    if (started_utime_ >= 0) noteNotTheSeedsRun("reloaded during the run");
    const bool loaded = host_->reload();
    started_utime_ = -1;  // the referee's clock starts again at the next Run
    const bool may_resume = startNewEpisode();
    episode_->restart(start_);
    if (was_running && loaded && may_resume) setRunning(true);
    return loaded;
  }
  // With windows the simulator holds the world at 0 s until the first Run (or teleoperation): the
  // episode starts from the state and random streams a headless run of the seed starts from, so
  // the windowed run is the graded run (docs/architecture.md, "A windowed run is the graded run").
  void releaseTheStart() {
    if (!loop_->heldAtStart()) return;
    aula::sim_control_t resume{};
    resume.command = aula::sim_control_t::RESUME;
    bus_.publish(lcmbus::kControlChannel, &resume);
  }
  // With windows: a hung execute() halts the algorithm instead of ending the process.
  void containHangs() { host_->containHangs(); }
  // A crash's one line goes to this descriptor (the launcher's private line) before the process dies.
  void reportCrashesTo(int fd) { component::reportCrashesTo(fd); }
  void poll() { loop_->poll(); }  // housekeeping (lockstep registration)
  void leave() { loop_->leave(); }
  // Why the simulator is gone (it ended the run, or its clock stopped), or "" (LockstepClient's).
  std::string simulatorGone() const { return loop_->simulatorGone(); }
  // Started by `aula run`: the launcher watches the simulator's process (LockstepClient).
  void watchedByLauncher() { loop_->watchedByLauncher(); }

  int generation() const { return episode_->generation(); }
  lcmbus::Bus& bus() { return bus_; }  // the window's speed control (SIM_CONTROL)
  int64_t simTimeUs() const { return loop_->simTimeUs(); }
  int64_t startedUtime() const { return started_utime_; }  // the episode's first Run (-1: not yet)
  bool autostart() const { return autostart_; }
  const std::string& algorithmName() const { return algorithm_name_; }
  const AlgorithmHostBase& algorithm() const { return *host_; }
  const Pose3dProxy& truePose() const { return *pose_; }  // the window's, never the algorithm's unless its API has it
  const MotorsProxy& motors() const { return *motors_; }
  double maxV() const { return motors_->maxV(); }
  double maxW() const { return motors_->maxW(); }
  const StartPose& startPose() const { return start_; }
  // The referee's word on the episode (time left, its end); when it ends, the algorithm stops.
  const RefereeStatusListener& refereeStatus() const { return *referee_status_; }
  // Called after every control tick (GUI refresh hooks, tests).
  void setOnTick(std::function<void(int64_t)> hook) { on_tick_ = std::move(hook); }

 protected:
  // A call into the student's algorithm on the exercise's API: execute() every control period
  // while running; CallKind::Plan for an exercise that plans (TeleTaxi's generatePath()).
  virtual void invoke(Algorithm& algorithm, CallKind kind) = 0;
  // The same call when the algorithm runs in a process of its own (Component.OwnProcess): what
  // the API gives now, written with the exercise's exchange (box_wire.hpp), and what the
  // algorithm left, read with it; the algorithm's end (the exercise's Box, algorithm_box_main.hpp)
  // reads and writes the same.
  virtual void boxInputs(BoxWire& wire, CallKind kind) = 0;
  virtual void boxOutputs(BoxWire& wire, CallKind kind) = 0;
  // Calls the algorithm (invoke, or in its own process); false when it failed or is halted.
  bool callAlgorithm(CallKind kind, const char* what) {
    if (host_->ownProcess()) {
      return host_->callInBox(
          runSeed(), what, kind, [this, kind](BoxWire& wire) { boxInputs(wire, kind); },
          [this, kind](BoxWire& wire) { boxOutputs(wire, kind); });
    }
    return host_->call(runSeed(), what, kind, [this, kind](Algorithm& algorithm) { invoke(algorithm, kind); });
  }
  // A hung call may still read the exercise's own sensors: freeze them (the pose is frozen here).
  virtual void detachSensors() {}
  // At every tick, before Autostart and the episode message (TeleTaxi: the taxi on its grid).
  virtual void beforeTick(int64_t /*utime*/) {}
  // Autostart waits until this holds (TeleTaxi: a destination and the taxi's pose).
  virtual bool readyToAutostart() const { return true; }
  // Just before Autostart runs the algorithm: false when it cannot run (TeleTaxi: no path).
  virtual bool prepareAutostart() { return true; }
  // What the episode messages carry besides the run state (TeleTaxi: the destination).
  virtual std::optional<std::pair<double, double>> episodeGoal() const { return std::nullopt; }
  // What the algorithm says of where it stands, for the referee's report (Autopark's api.status).
  virtual std::string algorithmStatus() const { return ""; }
  // The exercise's state for a new episode (hot reload); false when the algorithm may not run
  // on at once (TeleTaxi: a new path must be generated first).
  virtual bool startNewEpisode() { return true; }

  // The run's seed (from the simulator's clock), which the algorithm is made with.
  uint64_t runSeed() const { return static_cast<uint64_t>(loop_->seed()); }
  Pose3dProxy& poseProxy() { return *pose_; }
  MotorsProxy& motorsProxy() { return *motors_; }
  Host& host() { return *host_; }
  EpisodeSender& episode() { return *episode_; }

 private:
  ExerciseComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                    const settings::Exercise& names, const std::optional<auth::Key>& lockstep_key)
      : bus_(bus),
        program_(names.component),
        algorithm_name_(cfg.getString(names.section + ".Algorithm")),
        console_channel_(cfg.getString(names.section + ".Console.Channel")) {
    const std::string& p = names.section;
    const world::RobotSpec& robot = world::requireRobot(world, cfg.getString(p + ".Robot"));
    start_ = {robot.name, robot.pose.translation().x(), robot.pose.translation().y(), world::yawOf(robot.pose)};
    autostart_ = cfg.getBool(p + ".Autostart");
    pose_ = std::make_unique<Pose3dProxy>(bus, world::channelOf(robot, "pose3d"));
    motors_ = std::make_unique<MotorsProxy>(bus, world::channelOf(robot, "motors"), cfg.getDouble(p + ".MaxV"),
                                            cfg.getDouble(p + ".MaxW"));
    host_ = std::make_unique<Host>(names.component, names.name, algorithm_name_, *motors_, budgetsOf(cfg),
                                   cfg.getBool("Component.OwnProcess"));
    episode_ = std::make_unique<EpisodeSender>(bus, cfg.getString(p + ".Episode.Channel"), names.name, *host_);
    host_->setOnHung([this] {  // the stuck call may still read these: never written again
      pose_->detach();
      detachSensors();
      motors_->halt();
    });
    referee_status_ = std::make_unique<RefereeStatusListener>(bus, cfg.getString(p + ".RefereeStatus.Channel"),
                                                              names.component, [this] { return generation(); });
    referee_status_->setOnFinished([this](const aula::referee_status_t&) { setRunning(false); });
    const double period_s = cfg.getDouble(p + ".Period");
    loop_ = std::make_unique<ControlLoop>(bus, names.component, static_cast<int64_t>(std::llround(period_s * 1e6)), *motors_,
                                          [this] { step(); }, lockstep_key);
    loop_->setOnTick([this](int64_t utime) { tick(utime); });
  }

  void step() {
    if (!callAlgorithm(CallKind::Execute, "execute()")) {
      setRunning(false);
      return;
    }
    // Read once the call has returned (its thread is done with the API), and bounded: it is the
    // student's text, sent at every change.
    algorithm_status_ = algorithmStatus().substr(0, kStatusBytes);
  }
  void tick(int64_t utime) {
    beforeTick(utime);
    // Autostart runs the algorithm from the first tick it can (sim time 0 in a headless lockstep
    // run; later when windows join a running world), once.
    if (autostart_ && !autostarted_ && readyToAutostart()) {
      autostarted_ = true;
      if (prepareAutostart()) setRunning(true);
    }
    episode_->tick(utime, {running(), started_utime_, episodeGoal(), algorithm_status_, not_the_seeds_run_});
    publishPrinted(utime);
    if (on_tick_) on_tick_(utime);
  }
  // The referee has ended the current episode (what comes after it is not graded).
  bool episodeOver() const {
    const auto status = referee_status_->latest();
    return status && status->finished;
  }
  void noteNotTheSeedsRun(const std::string& why) {
    if (not_the_seeds_run_.find(why) != std::string::npos) return;
    not_the_seeds_run_ += (not_the_seeds_run_.empty() ? "" : "; ") + why;
    std::cerr << program_ << ": " << why << ": this run is no longer the graded run of its seed" << std::endl;
  }
  // What the algorithm printed during this tick's calls, on the bus (console_t), stamped with
  // the tick's sim time: the run's log keeps it, the referee's trace takes it to the player.
  void publishPrinted(int64_t utime) {
    aula::console_t msg{};
    msg.text = host_->takePrinted();
    if (msg.text.empty()) return;
    msg.utime = utime;
    bus_.publish(console_channel_, &msg);
  }

  lcmbus::Bus& bus_;
  std::string program_;  // the component's name, for its messages
  std::string algorithm_name_;
  std::string console_channel_;
  StartPose start_;
  bool autostart_ = false;
  bool autostarted_ = false;
  static constexpr size_t kStatusBytes = 300;
  std::string algorithm_status_;  // algorithmStatus() after the last execute() that returned
  std::string not_the_seeds_run_;  // "; "-joined, each reason once
  int64_t started_utime_ = -1;  // the first Run of this episode (-1: not yet)
  std::unique_ptr<Pose3dProxy> pose_;
  std::unique_ptr<MotorsProxy> motors_;
  std::unique_ptr<Host> host_;
  std::unique_ptr<EpisodeSender> episode_;
  std::unique_ptr<RefereeStatusListener> referee_status_;
  std::unique_ptr<ControlLoop> loop_;
  std::function<void(int64_t)> on_tick_;
};

}  // namespace aula::component
