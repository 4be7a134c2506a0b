#pragma once
// What the referee says about the episode (referee_status_t on <EXERCISE>_REFEREE), heard by the
// component: the referee's clock is the one clock of the episode, so the window shows the time
// left that the referee sends, and "Time's up" (or "Arrived", "Parked") when the referee ends it.
// When the referee ends the current episode, the component stops its algorithm: nothing after
// the end is graded, the robot stops, and the teleoperator is the student's again.

#include <aula/lcm/bus.hpp>
#include <aula/referee_status_t.hpp>

#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <optional>
#include <string>

namespace aula::component {

class RefereeStatusListener {
 public:
  // `generation`: the component's current episode; statuses about other episodes are ignored.
  // The end of an episode is said once in the log, as "<program>: the referee ended ...".
  RefereeStatusListener(lcmbus::Bus& bus, const std::string& channel, std::string program, std::function<int()> generation);
  ~RefereeStatusListener();
  RefereeStatusListener(const RefereeStatusListener&) = delete;
  RefereeStatusListener& operator=(const RefereeStatusListener&) = delete;

  // The referee's latest word on the current episode, if any.
  std::optional<aula::referee_status_t> latest() const;
  // Called once per episode, when the referee says it ended.
  void setOnFinished(std::function<void(const aula::referee_status_t&)> hook) { on_finished_ = std::move(hook); }

 private:
  void onStatus(const lcm::ReceiveBuffer*, const std::string&, const aula::referee_status_t* msg);

  lcmbus::Bus& bus_;
  lcm::Subscription* subscription_ = nullptr;
  std::string program_;
  std::function<int()> generation_;
  std::optional<aula::referee_status_t> latest_;
  int finished_generation_ = -1;  // the episode whose end was announced
  std::function<void(const aula::referee_status_t&)> on_finished_;
};

// The window's line: "time left 14:32 - coverage 12.30 %", "Time's up: coverage 67.30 %, mark
// 10.00 / 10", or what the referee waits for (`start_action`: "Run", "GO!").
std::string refereeStatusLine(const std::optional<aula::referee_status_t>& status, const std::string& start_action);

}  // namespace aula::component
