#include "aula/sim/simulator.hpp"

#include <aula/process/machine_reason.hpp>

#include <aula/config/config.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/process/child_process.hpp>
#include <aula/sim_clock_t.hpp>
#include <aula/world/obstacle_slice.hpp>
#include <aula/world/occupancy_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <thread>

namespace aula::sim {
namespace {
using WallClock = std::chrono::steady_clock;
constexpr auto kHeartbeat = std::chrono::milliseconds(100);
constexpr auto kProcessCheckPeriod = std::chrono::milliseconds(100);
constexpr auto kStopLook = std::chrono::milliseconds(1);

int64_t secondsToUs(double s) { return static_cast<int64_t>(std::llround(s * 1e6)); }

// 63 random bits from the kernel (never the seed: a run's report depends on the seed only), not 0.
int64_t randomInstance() {
  for (;;) {
    const auth::Key bytes = auth::randomKey();
    uint64_t id = 0;
    for (int i = 0; i < 8; ++i) id = (id << 8) | bytes[static_cast<size_t>(i)];
    id >>= 1;
    if (id != 0) return static_cast<int64_t>(id);
  }
}
}  // namespace

SimulatorOptions SimulatorOptions::fromConfig(const config::Config& cfg) {
  SimulatorOptions o;
  // Every key is declared with its default and range (aula_settings::simulator()).
  o.step_s = cfg.getDouble("Simulator.PhysicsStep");
  o.real_time_factor = cfg.getDouble("Simulator.RealTimeFactor");
  o.lockstep = cfg.getBool("Simulator.Lockstep");
  o.seed = cfg.getInt64("Simulator.Seed");
  o.clock_period_us = secondsToUs(cfg.getDouble("Simulator.ClockPeriod"));
  o.lockstep_wait_clients = cfg.getInt("Simulator.Lockstep.WaitForClients");
  o.lockstep_resend = std::chrono::milliseconds(cfg.getInt("Simulator.Lockstep.ResendMs"));
  o.lockstep_drop = std::chrono::milliseconds(cfg.getInt("Simulator.Lockstep.DropAfterMs"));
  o.duration_s = cfg.getDouble("Simulator.Duration");
  o.start_paused = cfg.getBool("Simulator.StartPaused");
  o.noise.laser_stddev_m = cfg.getDouble("Simulator.Noise.LaserStddev");
  o.noise.laser_dropout = cfg.getDouble("Simulator.Noise.LaserDropout");
  o.noise.wheel_slip = cfg.getDouble("Simulator.Noise.WheelSlip");
  if (o.clock_period_us < secondsToUs(o.step_s)) {
    throw config::ConfigError(cfg.origin("Simulator.ClockPeriod") + ": Simulator.ClockPeriod must be >= the physics step");
  }
  return o;
}

void applyStartPoses(const config::Config& cfg, world::WorldSpec& spec) {
  const std::string prefix = "Simulator.StartPose.";
  for (const std::string& key : cfg.keys()) {
    if (key.rfind(prefix, 0) != 0) continue;
    const std::string robot = key.substr(prefix.size());
    auto it = std::find_if(spec.robots.begin(), spec.robots.end(), [&](const world::RobotSpec& r) { return r.name == robot; });
    if (it == spec.robots.end()) {
      std::string names;
      for (const auto& r : spec.robots) names += (names.empty() ? "" : ", ") + r.name;
      throw config::ConfigError(cfg.origin(key) + ": " + key + ": the world has no robot '" + robot + "' (robots: " + names + ")");
    }
    const std::vector<double> pose = cfg.getDoubleList(key);
    if (pose.size() != 3 || !std::isfinite(pose[0]) || !std::isfinite(pose[1]) || !std::isfinite(pose[2])) {
      throw config::ConfigError(cfg.origin(key) + ": " + key + ": expected x, y, yaw (m, m, rad)");
    }
    Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
    start.translation() = Eigen::Vector3d(pose[0], pose[1], it->pose.translation().z());
    start.linear() = Eigen::AngleAxisd(pose[2], Eigen::Vector3d::UnitZ()).toRotationMatrix();
    it->pose = start;
  }
}

Simulator::Simulator(world::WorldSpec spec, SimulatorOptions options, lcmbus::Bus& bus, std::optional<auth::Key> key)
    : spec_(std::move(spec)), options_(options), bus_(bus), lockstep_(options.lockstep_drop), stamper_(key), key_(key),
      instance_(randomInstance()),
      graded_(key.has_value()) {
  // The clock channel first, then the question: a simulator already running on this bus answers
  // while the world loads. Nothing is handled before the world is built.
  subscriptions_.push_back(bus_.subscribe(lcmbus::kClockChannel, &Simulator::onClock, this));
  subscriptions_.push_back(bus_.subscribe(lcmbus::kHelloChannel, &Simulator::onHello, this));
  subscriptions_.push_back(bus_.subscribe(lcmbus::kLockstepRegisterChannel, &Simulator::onRegister, this));
  subscriptions_.push_back(bus_.subscribe(lcmbus::kLockstepAckChannel, &Simulator::onAck, this));
  subscriptions_.push_back(bus_.subscribe(lcmbus::kControlChannel, &Simulator::onControl, this));
  const aula::sim_clock_t hello = tickAt(0);  // before the world is built: seq -1, no clients
  bus_.publish(lcmbus::kHelloChannel, &hello);
  physics_ = std::make_unique<physics::PhysicsWorld>(spec_, options_.step_s);
  context_.bus = &bus_;
  context_.physics = physics_.get();
  context_.seed = static_cast<uint64_t>(options_.seed);
  context_.noise = options_.noise;
  context_.stamper = &stamper_;
  context_.raycaster_at = [this](double z_m) { return raycasterAt(z_m); };
  for (int r = 0; r < physics_->robotCount(); ++r) {
    for (const auto& plugin : physics_->robotSpec(r).plugins) {
      auto driver = drivers::makeDriver(plugin.type);
      driver->attach(context_, r, plugin);
      drivers_.push_back(std::move(driver));
    }
  }
  paused_ = options_.start_paused;
  // A robot may be put anywhere within the world's statics (a metre of margin), or within
  // 1 km of the origin in a world with none.
  bounds_m_ = spec_.statics.empty() ? Eigen::Vector4d(-1000, -1000, 1000, 1000)
                                    : Eigen::Vector4d(world::staticBounds(spec_) + Eigen::Vector4d(-1, -1, 1, 1));
}

void Simulator::listenForClients(lcmbus::Bus& bus) {
  for (const char* channel : {lcmbus::kLockstepRegisterChannel, lcmbus::kLockstepAckChannel, lcmbus::kControlChannel}) {
    bus.listen(channel);
  }
}

std::optional<std::string> Simulator::poseProblem(double x_m, double y_m, double yaw_rad) const {
  if (!std::isfinite(x_m) || !std::isfinite(y_m) || !std::isfinite(yaw_rad)) return std::string("a non-finite pose");
  if (x_m < bounds_m_[0] || x_m > bounds_m_[2] || y_m < bounds_m_[1] || y_m > bounds_m_[3]) {
    std::ostringstream why;
    why << "(" << x_m << ", " << y_m << ") is outside the world (x " << bounds_m_[0] << " to " << bounds_m_[2] << ", y "
        << bounds_m_[1] << " to " << bounds_m_[3] << " m)";
    return why.str();
  }
  if (std::abs(yaw_rad) > M_PI + 1e-9) return "yaw " + std::to_string(yaw_rad) + " rad is not in [-pi, pi]";
  return std::nullopt;
}

Simulator::~Simulator() {
  for (auto* s : subscriptions_) bus_.unsubscribe(s);
}

const geometry::Raycaster2D* Simulator::raycasterAt(double z_m) {
  const long long key = std::llround(z_m * 1000.0);
  auto& slot = raycasters_[key];
  if (!slot) slot = std::make_unique<geometry::Raycaster2D>(world::sliceAtHeight(spec_, z_m));
  return slot.get();
}

void Simulator::log(const std::string& line) const {
  std::cerr << "aula-sim [" << physics_->timeUs() / 1e6 << " s]: " << line << std::endl;
}

std::optional<aula::sim_clock_t> Simulator::otherSimulatorUntil(WallClock::time_point until) {
  probing_ = true;
  while (!first_foreign_) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - WallClock::now()).count();
    if (left <= 0) break;
    bus_.handleTimeout(static_cast<int>(std::max<long long>(1, left)));
  }
  probing_ = false;
  return first_foreign_;
}

// Another simulator about to start asks whether one runs here: the current tick answers it (at
// most every 10 ms of wall time, so that a flood of questions is not a flood of ticks). Our own
// question comes back to us too.
void Simulator::onHello(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t* hello) {
  if (hello->instance == instance_ || probing_) return;
  const auto now = WallClock::now();
  if (now - last_hello_answer_ < std::chrono::milliseconds(10)) return;
  last_hello_answer_ = now;
  publishClock();
}

// Our own ticks come back to us (one read each); another instance's are another simulator's, or forged.
void Simulator::onClock(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t* tick) {
  if (tick->instance == instance_) return;
  if (!probing_ && !had_client_ && tick->num_clients > 0 && !second_on_bus_) second_on_bus_ = *tick;
  if (++foreign_ticks_ == 1) {
    first_foreign_ = *tick;
    if (!probing_) {
      log("another simulator (instance " + std::to_string(tick->instance) + ", world '" + tick->world +
          "') publishes on " + bus_.url() + "; its ticks are not ours, our clients ignore them");
    }
  }
}

bool Simulator::forgedControl(const std::string& channel, const aula::sim_control_t& msg) {
  if (!stamper_.keyed()) return false;  // outside grading the windows' controls work as they are
  if (!auth::verify(stamper_.signer(), channel, msg)) {
    ++rejected_controls_;
    log(channel + ": command " + std::to_string(msg.command) + " rejected: not signed with the run's key (a graded run)");
    return true;
  }
  if (msg.auth_seq <= last_control_seq_) {
    ++rejected_controls_;
    log(channel + ": command " + std::to_string(msg.command) + " rejected: a replay (auth_seq " +
        std::to_string(msg.auth_seq) + " <= " + std::to_string(last_control_seq_) + ")");
    return true;
  }
  last_control_seq_ = msg.auth_seq;
  return false;
}

void Simulator::onControl(const lcm::ReceiveBuffer*, const std::string& channel,
                          const aula::sim_control_t* msg) {
  if (probing_) return;
  if (forgedControl(channel, *msg)) return;
  switch (msg->command) {
    case aula::sim_control_t::PAUSE:
      paused_ = true;
      log("paused");
      break;
    case aula::sim_control_t::RESUME:
      paused_ = false;
      log("resumed");
      break;
    case aula::sim_control_t::SET_RTF:
      if (!std::isfinite(msg->real_time_factor) || msg->real_time_factor < 0 || msg->real_time_factor > 1000) {
        ++rejected_controls_;
        log(channel + ": SET_RTF " + std::to_string(msg->real_time_factor) + " rejected (0 to 1000; 0 = as fast as possible)");
      } else {
        options_.real_time_factor = msg->real_time_factor;
        repace_ = true;
        log(msg->real_time_factor > 0 ? "pace: " + std::to_string(msg->real_time_factor) + "x real time"
                                      : std::string("pace: as fast as possible"));
      }
      break;
    case aula::sim_control_t::STEP:
      step_pending_ = paused_;  // one tick, then paused again
      break;
    case aula::sim_control_t::RESET:
      resetWorld();
      log("world reset");
      break;
    case aula::sim_control_t::SET_POSE: {
      const int robot = physics_->robotIndex(msg->robot);
      const auto problem = poseProblem(msg->x, msg->y, msg->yaw);
      if (robot < 0) {
        ++rejected_controls_;
        log(channel + ": SET_POSE for unknown robot '" + msg->robot + "' rejected");
      } else if (problem) {
        ++rejected_controls_;
        log(channel + ": SET_POSE of '" + msg->robot + "' rejected: " + *problem);
      } else {
        physics_->setRobotPose(robot, msg->x, msg->y, msg->yaw);
        log("robot '" + msg->robot + "' teleported");
      }
      break;
    }
    default:
      ++rejected_controls_;
      log(channel + ": unknown command " + std::to_string(msg->command) + " rejected");
  }
}

namespace {
constexpr std::size_t kRefusedNamesLogged = 16;
}

template <class Message>
bool Simulator::fromThisRun(const std::string& channel, const Message& msg) {
  if (!key_) return true;  // outside grading any client may join (windows, a debugger, stock tools)
  const auto known = client_signers_.find(msg.client);
  if (known != client_signers_.end()) {
    if (auth::verify(known->second, channel, msg)) return true;
  } else {
    auth::Signer signer(auth::clientKey(*key_, msg.client));  // kept once it has spoken for the client
    if (auth::verify(signer, channel, msg)) {
      client_signers_.emplace(msg.client, signer);
      return true;
    }
  }
  // Named once each, and at most kRefusedNamesLogged names (a flood of names is not a flood of lines).
  if (refused_clients_.size() < kRefusedNamesLogged && refused_clients_.insert(msg.client).second) {
    log("lockstep client '" + msg.client + "' refused: " + channel + " not signed with this run's key for it (another run's client?)");
  }
  return false;
}

void Simulator::onRegister(const lcm::ReceiveBuffer*, const std::string& channel,
                           const aula::lockstep_register_t* msg) {
  if (!fromThisRun(channel, *msg)) return;
  if (msg->leave) {
    if (lockstep_.leave(msg->client)) log("lockstep client '" + msg->client + "' left");
    return;
  }
  if (msg->period_us <= 0) {
    log("lockstep client '" + msg->client + "' asked for period " +
        std::to_string(msg->period_us) + " us: ignored");
    return;
  }
  if (lockstep_.join(msg->client, msg->period_us, msg->pid)) {
    had_client_ = true;
    log("lockstep client '" + msg->client + "' joined, period " +
        std::to_string(msg->period_us / 1000.0) + " ms");
    // The newcomer must see (and ack) the current tick before the world moves on; the
    // re-published tick also tells it that it is listed. While it listens for another simulator
    // this one stays silent: its clients learn they are listed from its first tick.
    if (options_.lockstep && started_) lockstep_.tick(seq_, physics_->timeUs(), WallClock::now());
    if (!probing_) publishClock();
  }
}

void Simulator::onAck(const lcm::ReceiveBuffer*, const std::string& channel, const aula::lockstep_ack_t* msg) {
  if (!fromThisRun(channel, *msg)) return;
  lockstep_.ack(msg->client, msg->seq);
}

void Simulator::resetWorld() {
  physics_->reset();
  for (auto& d : drivers_) d->reset();
  lockstep_.resetSchedule();
}

aula::sim_clock_t Simulator::tickAt(int64_t utime_us) const {
  aula::sim_clock_t tick{};  // zeros: the hello is never stamped
  tick.utime = utime_us;
  // Before the run starts (lockstep, waiting for clients) ticks carry seq -1: they only tell
  // clients they are listed; nobody runs or acks on them.
  tick.seq = started_ ? seq_ : -1;
  tick.lockstep = options_.lockstep;
  tick.paused = paused_;
  tick.real_time_factor = measured_rtf_;
  tick.target_real_time_factor = options_.real_time_factor;
  tick.seed = options_.seed;
  tick.world = spec_.name;
  tick.world_sha256 = spec_.sha256;
  tick.clients = lockstep_.clients();
  tick.num_clients = static_cast<int32_t>(tick.clients.size());
  tick.rejected_controls = rejected_controls_;
  tick.instance = instance_;
  tick.ended = ended_because_;
  return tick;
}

void Simulator::publishClock() {
  aula::sim_clock_t tick = tickAt(physics_->timeUs());
  stamper_.stamp(lcmbus::kClockChannel, tick);
  bus_.publish(lcmbus::kClockChannel, &tick);
}

void Simulator::advanceToNextTick() {
  started_ = true;
  const int64_t now = physics_->timeUs();
  int64_t next = (now / options_.clock_period_us + 1) * options_.clock_period_us;
  // In lockstep with clients, tick only when some client is due: every tick costs each client
  // a wake-up, and nobody is waiting for the ones in between.
  if (options_.lockstep && lockstep_.size() > 0) next = lockstep_.nextDueAfter(now);
  // The period's sensor messages go out together with its tick, in one system call: each client
  // wakes once per tick, not once per message (the order on the wire is the same).
  bus_.hold();
  while (physics_->timeUs() < next) {
    physics_->step();
    const int64_t t = physics_->timeUs();
    for (auto& d : drivers_) d->step(t);
  }
  ++seq_;
  publishClock();
  bus_.flush();
}

void Simulator::driveWith(std::vector<lcmbus::RecordedMessage> commands) {
  recorded_commands_ = std::move(commands);
  next_recorded_command_ = 0;
}

void Simulator::injectDueCommands() {
  while (next_recorded_command_ < recorded_commands_.size() &&
         recorded_commands_[next_recorded_command_].tick_us <= physics_->timeUs()) {
    const lcmbus::RecordedMessage& command = recorded_commands_[next_recorded_command_++];
    bus_.inject(command.channel, command.bytes.data(), static_cast<unsigned int>(command.bytes.size()));
  }
}

// The wall-clock bookkeeping of one run(): where pacing counts from, the window the real-time
// factor is measured over, and when the clock and the viewer last went out.
struct Simulator::RunClocks {
  WallClock::time_point pace_origin;
  int64_t pace_origin_us;
  WallClock::time_point rtf_window_start;
  int64_t rtf_window_us;
  WallClock::time_point last_publish;
  WallClock::time_point last_frame;
};

void Simulator::run(const std::function<bool()>& asked_to_stop, const std::function<bool()>& frame) {
  const int64_t duration_us = secondsToUs(options_.duration_s);
  const auto start = WallClock::now();
  RunClocks clocks{start, physics_->timeUs(), start, physics_->timeUs(), start, start};
  // Asked at most every kStopLook of wall time: it reads the signals' descriptor, and the loop
  // passes here about three times a tick.
  WallClock::time_point next_look{};
  bool stopping = false;  // once asked, for good
  const std::function<bool()> should_stop = [&] {
    if (stopping) return true;
    const auto now = WallClock::now();
    if (now < next_look) return false;
    next_look = now + kStopLook;
    stopping = asked_to_stop();
    return stopping;
  };
  while (!should_stop()) {
    if (duration_us > 0 && physics_->timeUs() >= duration_us) break;
    if (!drawFrameIfDue(frame, clocks)) break;
    while (bus_.handleTimeout(0) > 0) {
    }
    if (started_) injectDueCommands();
    const auto now = WallClock::now();
    if (clientProcessGone(now)) break;
    heartbeat(now, clocks);
    if (repace_) {  // a new pace counts from now, not from the start of the run
      clocks.pace_origin = now;
      clocks.pace_origin_us = physics_->timeUs();
      repace_ = false;
    }
    if (startIfReady(now, clocks) || holdWhilePausedOrWaiting(now, clocks)) continue;
    if (options_.lockstep && awaitLockstepAcks(now)) {
      if (!ended_because_.empty()) break;
      continue;
    }

    advanceToNextTick();
    clocks.last_publish = WallClock::now();
    if (options_.lockstep) lockstep_.tick(seq_, physics_->timeUs(), clocks.last_publish);
    measureRealTimeFactor(clocks);
    paceToRealTime(clocks, should_stop);
  }
}

bool Simulator::drawFrameIfDue(const std::function<bool()>& frame, RunClocks& clocks) {
  constexpr auto kFramePeriod = std::chrono::milliseconds(33);  // about 30 frames per wall second
  if (frame && WallClock::now() - clocks.last_frame >= kFramePeriod) {
    if (!frame()) return false;
    clocks.last_frame = WallClock::now();
  }
  return true;
}

bool Simulator::waitingForClients() const {
  return !started_ && options_.lockstep && static_cast<int>(lockstep_.size()) < options_.lockstep_wait_clients;
}

bool Simulator::startIfReady(WallTime now, RunClocks& clocks) {
  if (started_ || waitingForClients()) return false;
  // Tick 0, once every expected client is listening: sensors at t = 0, then the clock, so
  // each client sees the same first messages whatever the order the processes started in.
  // Started paused (Simulator.StartPaused), it then holds there: the clients see the world at
  // 0 s (a window draws it; TeleTaxi plans on it) and the run goes on from it when resumed, as
  // it would have unpaused.
  started_ = true;
  for (auto& d : drivers_) d->step(physics_->timeUs());
  publishClock();
  clocks.last_publish = now;
  if (options_.lockstep) lockstep_.tick(seq_, physics_->timeUs(), now);
  return true;
}

bool Simulator::abandoned() const {
  return started_ && options_.lockstep && options_.lockstep_wait_clients > 0 && lockstep_.size() == 0;
}

bool Simulator::holdWhilePausedOrWaiting(WallTime now, RunClocks& clocks) {
  if (!paused_ && !waitingForClients() && !abandoned()) return false;
  if (paused_ && step_pending_ && started_ && !waitingForClients()) {
    step_pending_ = false;
    return false;  // this pass advances one tick
  }
  // Keep ticking the (unchanged) clock so clients see the pause and know they are listed.
  if (now - clocks.last_publish > std::chrono::milliseconds(100)) {
    publishClock();
    clocks.last_publish = now;
  }
  bus_.handleTimeout(20);
  clocks.pace_origin = WallClock::now();
  clocks.pace_origin_us = physics_->timeUs();
  return true;
}

bool Simulator::awaitLockstepAcks(WallTime now) {
  for (const LockstepServer::Silent& c : lockstep_.silent(now)) {
    char silent[160];
    std::snprintf(silent, sizeof silent, "lockstep client '%s' silent for %.1f s", c.client.c_str(),
                  c.silent_for.count() / 1000.0);
    if (graded_) {
      // A graded run never goes on without the student's component or the referee. A process
      // that is gone is seen at once by the launcher (its child); one that only computes or
      // sleeps is judged by its own budgets of CPU time. Silence this long is a starved
      // machine's backstop (Simulator.Lockstep.DropAfterMs), never a mark.
      ended_because_ = process::machineReason(std::string(silent) + " of wall time");
      log(ended_because_ + ": a graded run does not go on without it; the run ends");
      return true;
    }
    if (c.pid > 0 && !process::processGone(c.pid)) {
      log(std::string(silent) + " (wall): waiting while its process " + std::to_string(c.pid) +
          " lives (stopped in a debugger?)");
      repace_ = true;  // when it resumes, real time counts from then: no rush to catch up
      continue;
    }
    lockstep_.leave(c.client);
    log(std::string(silent) + " (wall) and its process is gone: dropped");
  }
  if (!lockstep_.waiting()) return false;
  const int ready = bus_.handleTimeout(static_cast<int>(options_.lockstep_resend.count()));
  if (ready == 0 && lockstep_.waiting()) publishClock();  // a tick or an ack was lost
  return true;
}

bool Simulator::clientProcessGone(WallTime now) {
  if (!options_.watch_client_processes || now - last_process_check_ < kProcessCheckPeriod) return false;
  last_process_check_ = now;
  for (const auto& [client, pid] : lockstep_.pids()) {
    if (!process::processGone(pid)) continue;
    lockstep_.leave(client);  // the last ticks no longer list it: its peers see which one is gone
    ended_because_ = "lockstep client '" + client + "' (pid " + std::to_string(pid) + ") is gone without leaving the run";
    log(ended_because_ + ": the run ends");
    return true;
  }
  return false;
}

void Simulator::heartbeat(WallTime now, RunClocks& clocks) {
  if (!started_ || now - clocks.last_publish < kHeartbeat) return;
  publishClock();  // the current tick again: a client acks it again, runs nothing
  clocks.last_publish = now;
}

void Simulator::announceEnd() {
  if (ended_because_.empty()) return;
  for (int i = 0; i < 3; ++i) {
    if (i > 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    publishClock();
  }
}

// Real-time factor over the last second of wall time, published in the clock.
void Simulator::measureRealTimeFactor(RunClocks& clocks) {
  const auto now = WallClock::now();
  const double window_s = std::chrono::duration<double>(now - clocks.rtf_window_start).count();
  if (window_s >= 1.0) {
    measured_rtf_ = (physics_->timeUs() - clocks.rtf_window_us) / 1e6 / window_s;
    clocks.rtf_window_start = now;
    clocks.rtf_window_us = physics_->timeUs();
  }
}

// Paced in lockstep too: the slowest of the clients and the real-time factor sets the pace.
void Simulator::paceToRealTime(RunClocks& clocks, const std::function<bool()>& should_stop) {
  if (options_.real_time_factor <= 0) return;
  const double sim_s = (physics_->timeUs() - clocks.pace_origin_us) / 1e6;
  const auto target = clocks.pace_origin + std::chrono::duration_cast<WallClock::duration>(
                                               std::chrono::duration<double>(sim_s / options_.real_time_factor));
  // Sleep by waiting on the bus, so commands are handled while we wait; a slow pace still
  // ticks every kHeartbeat.
  while (!should_stop()) {
    const auto now = WallClock::now();
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(target - now);
    if (left.count() <= 0) break;
    heartbeat(now, clocks);
    const auto beat = std::chrono::duration_cast<std::chrono::milliseconds>(clocks.last_publish + kHeartbeat - now);
    bus_.handleTimeout(static_cast<int>(std::max<long long>(1, std::min(left.count(), beat.count()))));
  }
}

}  // namespace aula::sim
