#include "aula/component/control_loop.hpp"

namespace aula::component {

ControlLoop::ControlLoop(lcmbus::Bus& bus, const std::string& client_name, int64_t period_us,
                         MotorsProxy& motors, std::function<void()> step, const std::optional<auth::Key>& client_key)
    : motors_(motors),
      step_(std::move(step)),
      period_us_(period_us),
      client_(bus, client_name, period_us, [this](int64_t utime) { tick(utime); }, client_key) {}

void ControlLoop::setRunning(bool running) {
  if (running_ && !running) motors_.stop();
  running_ = running;
}

void ControlLoop::tick(int64_t utime) {
  if (running_ && step_) step_();
  // Published every period, running or not: teleoperation works and the watchdog stays fed.
  motors_.publish(utime);
  if (on_tick_) on_tick_(utime);
}

}  // namespace aula::component
