#pragma once
// The client half of the simulator's lockstep handshake.
//
// The simulator publishes sim_clock_t ticks. A registered client whose period divides the
// tick's utime must acknowledge it (after handling the sensor data published before the tick
// and publishing its own outputs); until every due client has acked, the world does not
// advance. Registration and acks are re-sent after a short wall-clock wait, so one lost UDP
// packet never stalls a run; a simulator that starts after the client (its SIM_HELLO) is sent the
// registration again at once.

#include <aula/auth/run_key.hpp>
#include <aula/sim_clock_t.hpp>

#include "aula/lcm/bus.hpp"
#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace aula::lcmbus {

class LockstepClient {
 public:
  // on_tick(utime) runs at every tick that is due for this client (every period_us of sim time),
  // in lockstep or not; in lockstep the ack follows when on_tick returns.
  using TickHandler = std::function<void(int64_t utime)>;

  // `client_key`: in a graded run, the key this client signs its registration and acks with
  // (aula_auth's clientKey); the simulator of a graded run takes no client unsigned.
  LockstepClient(lcmbus::Bus& bus, std::string client_name, int64_t period_us, TickHandler on_tick,
                 const std::optional<auth::Key>& client_key = std::nullopt);
  ~LockstepClient();
  LockstepClient(const LockstepClient&) = delete;
  LockstepClient& operator=(const LockstepClient&) = delete;

  // Call regularly (e.g. every 50 ms wall, or after each lcm.handle()): re-sends the
  // registration until the simulator lists this client.
  void poll();
  // A client that must run on the same world as the simulator (a referee grading it): ticks
  // of another world are not followed, and the next poll() throws config::ConfigError saying
  // which world each side has.
  void expectWorld(const std::string& sha256, const std::string& path);
  // Ticks that `accept(channel, tick)` refuses are not followed at all (a referee's check that
  // the clock is its simulator's: a forged tick must not move its time).
  using TickFilter = std::function<bool(const std::string& channel, const aula::sim_clock_t& tick)>;
  void setTickFilter(TickFilter accept) { accept_ = std::move(accept); }
  // Leave lockstep (the simulator stops waiting). Also done by the destructor.
  void leave();

  int64_t simTimeUs() const { return last_utime_; }
  bool registered() const { return registered_; }
  bool lockstep() const { return lockstep_; }
  bool paused() const { return paused_; }
  bool clockSeen() const { return last_seq_ >= 0; }
  double realTimeFactor() const { return rtf_; }
  // The simulator this client follows: the instance of the first tick that listed it. Ticks of
  // any other instance (a second simulator on the same URL, or a forgery) are then ignored,
  // counted and logged (one line, repeated at most every 10 s of wall time).
  bool instanceLocked() const { return instance_locked_; }
  int64_t instance() const { return instance_; }
  long long foreignTicks() const { return foreign_ticks_; }
  // The latest tick as received (world name, seed, clients...).
  const aula::sim_clock_t& lastTick() const { return last_tick_; }
  // Why the simulator this client follows is gone, or "" while it runs (or before it listed this
  // client): its last tick said it ended the run (sim_clock_t.ended), or it has not ticked for
  // kSimulatorSilence of wall time (killed, crashed: a running simulator ticks at least every
  // 100 ms, paused, paced or waiting).
  // The silence counts only while this client watches: a look more than kLookGap after the
  // previous one means this process itself was stopped (a debugger, SIGSTOP) or starved, and
  // what the simulator sent meanwhile is still queued, unread; the silence is then counted from
  // that look on, never across the process's own absence. Looks come from the component's
  // housekeeping, every 50 ms or so.
  static constexpr std::chrono::seconds kSimulatorSilence{2};
  static constexpr std::chrono::seconds kLookGap{1};
  // Under a launcher (`aula run`), which sees at once when the simulator's process is gone,
  // silence is never taken for its end: a stopped or starved simulator is waited for.
  void watchedByLauncher() { silence_means_gone_ = false; }
  std::string simulatorGone(std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now()) const;

 private:
  void onClock(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t* tick);
  void onHello(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t* hello);
  void sendRegister(bool leave);
  void noteForeignTick(const aula::sim_clock_t& tick);
  void sendAck(int64_t seq, int64_t utime);

  lcmbus::Bus& bus_;
  std::optional<auth::Signer> signer_;  // the client's key, in a graded run
  lcm::Subscription* subscription_ = nullptr;
  lcm::Subscription* hello_subscription_ = nullptr;
  std::string name_;
  int64_t period_us_;
  TickHandler on_tick_;
  TickFilter accept_;
  int64_t last_seq_ = -1;
  int64_t last_utime_ = 0;
  int64_t next_due_us_ = 0;
  bool registered_ = false;
  bool lockstep_ = false;
  bool paused_ = false;
  bool left_ = false;
  double rtf_ = 0.0;
  aula::sim_clock_t last_tick_{};
  bool instance_locked_ = false;
  int64_t instance_ = 0;
  long long foreign_ticks_ = 0;
  int64_t last_logged_foreign_ = 0;
  std::chrono::steady_clock::time_point last_foreign_log_{};
  std::chrono::steady_clock::time_point last_register_{};
  std::chrono::steady_clock::time_point last_clock_{};  // wall time of our simulator's last tick
  mutable std::chrono::steady_clock::time_point last_look_{};     // simulatorGone()'s previous call
  mutable std::chrono::steady_clock::time_point watched_from_{};  // silence counts from here at the earliest
  std::string expected_world_sha256_, expected_world_path_;
  std::string world_mismatch_;  // set by a tick of another world
  bool silence_means_gone_ = true;
};

}  // namespace aula::lcmbus
