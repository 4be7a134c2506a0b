#pragma once
// The simulator process core: the DART world, the drivers on its robots, the one clock, the
// control channel and lockstep. Single-threaded: LCM is handled between physics steps.

#include <aula/auth/run_key.hpp>
#include <aula/drivers/driver.hpp>
#include <aula/geometry/raycaster2d.hpp>
#include <aula/physics/physics_world.hpp>
#include <aula/sim/lockstep_server.hpp>
#include <aula/world/world_spec.hpp>

#include <aula/lockstep_ack_t.hpp>
#include <aula/lockstep_register_t.hpp>
#include <aula/sim_clock_t.hpp>
#include <aula/sim_control_t.hpp>

#include <aula/lcm/bus.hpp>
#include <aula/lcm/log_replay.hpp>
#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace aula::config { class Config; }

namespace aula::sim {

struct SimulatorOptions {
  double step_s = 0.005;             // physics step
  double real_time_factor = 1.0;     // pacing in free-running mode; 0 = as fast as possible
  bool lockstep = false;
  int64_t seed = 0;
  int64_t clock_period_us = 20000;   // SIM_CLOCK ticks at least this often (sim time)
  int lockstep_wait_clients = 0;     // lockstep: do not start before this many clients joined
  std::chrono::milliseconds lockstep_resend{20};   // re-send an unacked tick after (wall)
  // A client silent this long (wall): a graded run ends; otherwise the simulator waits while
  // the client's process lives (a debugger's breakpoint) and drops it once it is gone.
  std::chrono::milliseconds lockstep_drop{5000};
  double duration_s = 0.0;           // stop after this much sim time; 0 = run until stopped
  bool start_paused = false;
  drivers::SensorNoise noise;        // Simulator.Noise.*: sensor realism, off by default
  // Alone (three terminals: no launcher watches the processes): a client whose process is gone
  // without leaving (killed, crashed) ends the run. Under the launcher (aula-sim --status-fd) it
  // watches its children itself and tells the referee why.
  bool watch_client_processes = false;

  // Reads Simulator.* keys; throws config::ConfigError.
  static SimulatorOptions fromConfig(const config::Config& cfg);
};

// Simulator.StartPose.<robot> = x, y, yaw (m, m, rad): where a robot starts instead of the
// world's pose (a teacher's start position; a world reset returns there). Throws
// config::ConfigError for an unknown robot or a malformed pose.
void applyStartPoses(const config::Config& cfg, world::WorldSpec& spec);

class Simulator {
 public:
  // Throws world::WorldError on bad drivers/parameters. With `key` (a graded run: the launcher's
  // --key-fd) the truth the referee grades and the clock are signed, and SIM_CONTROL is obeyed
  // only when signed with it.
  Simulator(world::WorldSpec spec, SimulatorOptions options, lcmbus::Bus& bus,
            std::optional<auth::Key> key = std::nullopt);
  ~Simulator();
  Simulator(const Simulator&) = delete;
  // Before the world loads: what the clients send (registrations, acks, controls) waits in the
  // socket until the simulator handles the bus, instead of being dropped by its filter (a client
  // re-sends its registration only 100 ms later: every run would start that much later).
  static void listenForClients(lcmbus::Bus& bus);
  Simulator& operator=(const Simulator&) = delete;

  // Runs until `should_stop()` returns true or duration_s is reached. `frame`, if given, runs
  // about 30 times per wall second (a viewer's render) and stops the run by returning false.
  void run(const std::function<bool()>& should_stop, const std::function<bool()>& frame = nullptr);
  // Drives the robots with recorded commands instead of (or beside) live ones: each is handed to
  // the simulator's own subscriptions when the run reaches the tick it answered, before the
  // physics steps on (aula-sim --commands: a recorded run's motions with no component, the
  // baseline of bench/exercise_overhead.sh).
  void driveWith(std::vector<lcmbus::RecordedMessage> commands);
  // Advances to the next clock tick and publishes it (no pacing, no lockstep waiting).
  void advanceToNextTick();

  physics::PhysicsWorld& physics() { return *physics_; }
  const world::WorldSpec& spec() const { return spec_; }
  int64_t timeUs() const { return physics_->timeUs(); }
  const SimulatorOptions& options() const { return options_; }
  // SIM_CONTROL requests refused (in a graded run one not signed with the run's key, or a
  // replayed one; an unknown robot, a pose outside the world, a yaw not in [-pi, pi], an unknown
  // command): each is logged and counted, none reaches DART, and the clock tells the referee.
  long long rejectedControls() const { return rejected_controls_; }
  // This process's instance id (random, 63 bits, never 0): every tick carries it.
  int64_t instance() const { return instance_; }
  // Before the first tick: listens on the clock channel until `until` (wall) for a tick of
  // another instance, i.e. another simulator already running on this bus (which answers the
  // SIM_HELLO this one sent as it was built), and returns it. Meanwhile controls are ignored and
  // registrations are taken in silence (this one ticks only once it knows it is alone).
  std::optional<aula::sim_clock_t> otherSimulatorUntil(std::chrono::steady_clock::time_point until);
  // Ticks of another instance heard on the clock channel (another simulator, or a forgery).
  long long foreignTicks() const { return foreign_ticks_; }
  // A tick of another simulator that has clients, heard while this one never had one: this one
  // is the second on the bus (its listen before the first tick missed the other on a loaded
  // machine), and stops as if it had heard it then; nullopt otherwise. Two without clients both go on.
  const std::optional<aula::sim_clock_t>& secondOnTheBus() const { return second_on_bus_; }
  // Why the simulator ended the run before its end ("lockstep client 'vacuum-cleaner' silent for
  // 5.0 s" in a graded run; "lockstep client 'teletaxi' (pid 4242) is gone without leaving the
  // run" when watch_client_processes), or "": run() has returned then.
  const std::string& endedBecause() const { return ended_because_; }
  // After run() ended the run early: the last ticks, which say why (sim_clock_t.ended), for the
  // clients. Three of them 10 ms apart; a client that misses all three sees the clock stop.
  void announceEnd();

  // Why a SET_POSE to (x, y, yaw) cannot be done, or nullopt.
  std::optional<std::string> poseProblem(double x_m, double y_m, double yaw_rad) const;

 private:
  void injectDueCommands();
  void onControl(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_control_t* msg);
  // In a graded run: a request not signed with the run's key, or not newer than the last obeyed.
  bool forgedControl(const std::string& channel, const aula::sim_control_t& msg);
  void onRegister(const lcm::ReceiveBuffer*, const std::string&, const aula::lockstep_register_t* m);
  void onAck(const lcm::ReceiveBuffer*, const std::string&, const aula::lockstep_ack_t* msg);
  // In a graded run: false (and logged, once per client name) when `msg` is not signed with that
  // client's key of this run (auth::clientKey): another run's client, or a forgery.
  template <class Message>
  bool fromThisRun(const std::string& channel, const Message& msg);
  void onClock(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t* tick);
  void onHello(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t* hello);
  aula::sim_clock_t tickAt(int64_t utime_us) const;  // the clock message at `utime_us`, unsigned
  void publishClock();
  void resetWorld();
  // The steps of run(). startIfReady, holdWhilePausedOrWaiting and awaitLockstepAcks return true
  // when they used up this pass of the loop; drawFrameIfDue returns false once the viewer stops.
  struct RunClocks;
  using WallTime = std::chrono::steady_clock::time_point;
  bool drawFrameIfDue(const std::function<bool()>& frame, RunClocks& clocks);
  bool waitingForClients() const;
  // A lockstep run that waited for its clients and has none left (they all left, or were
  // dropped): the world holds until one comes back instead of running on alone.
  bool abandoned() const;
  bool startIfReady(WallTime now, RunClocks& clocks);
  bool holdWhilePausedOrWaiting(WallTime now, RunClocks& clocks);
  bool awaitLockstepAcks(WallTime now);
  // watch_client_processes: true (and the reason in ended_because_) once a client's process is gone.
  bool clientProcessGone(WallTime now);
  // The clock at least every kHeartbeat of wall time, whatever the pace: a client that hears
  // nothing for seconds knows the simulator is gone (LockstepClient::simulatorGone).
  void heartbeat(WallTime now, RunClocks& clocks);
  void measureRealTimeFactor(RunClocks& clocks);
  void paceToRealTime(RunClocks& clocks, const std::function<bool()>& should_stop);
  const geometry::Raycaster2D* raycasterAt(double z_m);
  void log(const std::string& line) const;

  world::WorldSpec spec_;
  SimulatorOptions options_;
  lcmbus::Bus& bus_;
  std::unique_ptr<physics::PhysicsWorld> physics_;
  std::map<long long, std::unique_ptr<geometry::Raycaster2D>> raycasters_;  // key: z in mm
  drivers::DriverContext context_;
  std::vector<std::unique_ptr<drivers::Driver>> drivers_;
  LockstepServer lockstep_;
  std::vector<lcm::Subscription*> subscriptions_;
  int64_t seq_ = 0;
  bool started_ = false;  // tick 0 published (after the expected lockstep clients joined)
  bool paused_ = false;
  double measured_rtf_ = 0.0;
  long long rejected_controls_ = 0;
  auth::Stamper stamper_;           // numbers and signs the truth and the clock
  std::optional<auth::Key> key_;    // a graded run's: each lockstep client's key is derived from it
  std::map<std::string, auth::Signer> client_signers_;  // by client name, made at its first message
  std::set<std::string> refused_clients_;               // named in the log once each
  int64_t last_control_seq_ = 0;    // the auth_seq of the last signed request obeyed
  bool repace_ = false;        // SET_RTF: pacing restarts from the current time
  bool step_pending_ = false;  // STEP while paused
  int64_t instance_ = 0;
  bool probing_ = false;       // otherSimulatorUntil: only the clock is heard
  std::chrono::steady_clock::time_point last_hello_answer_{};
  std::vector<lcmbus::RecordedMessage> recorded_commands_;  // driveWith
  std::size_t next_recorded_command_ = 0;
  std::optional<aula::sim_clock_t> first_foreign_;
  std::optional<aula::sim_clock_t> second_on_bus_;  // secondOnTheBus()
  bool had_client_ = false;                          // a lockstep client ever joined
  long long foreign_ticks_ = 0;
  Eigen::Vector4d bounds_m_;  // min x, min y, max x, max y where a robot may be put
  bool graded_ = false;       // a run key: no client is ever dropped, a silent one ends the run
  std::string ended_because_;
  std::chrono::steady_clock::time_point last_process_check_{};
};

}  // namespace aula::sim
