#pragma once
// Runs the student's algorithm every control period of SIMULATED time (<Exercise>.Period), in
// lockstep with the simulator when it is in lockstep: the tick is acknowledged only after the
// algorithm ran and the motor command was published.

#include <aula/component/proxies.hpp>
#include <aula/lcm/lockstep_client.hpp>

#include <functional>
#include <memory>
#include <string>

namespace aula::component {

class ControlLoop {
 public:
  // `step` runs at every due tick while running (the student's execute()).
  // `client_key`: a graded run's key for this lockstep client (LockstepClient's).
  ControlLoop(lcmbus::Bus& bus, const std::string& client_name, int64_t period_us, MotorsProxy& motors,
              std::function<void()> step, const std::optional<auth::Key>& client_key = std::nullopt);

  void setRunning(bool running);  // stopping also zeroes the motors
  bool running() const { return running_; }
  void poll() { client_.poll(); }  // housekeeping: lockstep re-registration
  void leave() { client_.leave(); }

  int64_t simTimeUs() const { return client_.simTimeUs(); }
  bool clockSeen() const { return client_.clockSeen(); }
  bool inLockstep() const { return client_.lockstep(); }  // the simulator waits for this tick's ack
  int64_t periodUs() const { return period_us_; }
  int64_t seed() const { return client_.lastTick().seed; }  // the run's seed (from SIM_CLOCK)
  // The simulator holds the world at its start (paused at sim time 0: `aula run` with windows
  // starts it so, and the first Run or teleoperation resumes it).
  bool heldAtStart() const { return client_.clockSeen() && client_.paused() && client_.simTimeUs() == 0; }
  std::string simulatorGone() const { return client_.simulatorGone(); }  // LockstepClient's
  void watchedByLauncher() { client_.watchedByLauncher(); }
  // Optional hook after every due tick, running or not (GUI model updates, recorders).
  void setOnTick(std::function<void(int64_t utime)> hook) { on_tick_ = std::move(hook); }

 private:
  void tick(int64_t utime);

  MotorsProxy& motors_;
  std::function<void()> step_;
  std::function<void(int64_t)> on_tick_;
  int64_t period_us_;
  bool running_ = false;
  lcmbus::LockstepClient client_;
};

}  // namespace aula::component
