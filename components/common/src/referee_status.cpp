#include "aula/component/referee_status.hpp"

#include <aula/lcm/bus.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace aula::component {

RefereeStatusListener::RefereeStatusListener(lcmbus::Bus& bus, const std::string& channel, std::string program,
                                             std::function<int()> generation)
    : bus_(bus), program_(std::move(program)), generation_(std::move(generation)) {
  subscription_ = bus_.subscribe(channel, &RefereeStatusListener::onStatus, this);
}

RefereeStatusListener::~RefereeStatusListener() { bus_.unsubscribe(subscription_); }

std::optional<aula::referee_status_t> RefereeStatusListener::latest() const {
  if (!latest_ || latest_->generation != generation_()) return std::nullopt;
  return latest_;
}

void RefereeStatusListener::onStatus(const lcm::ReceiveBuffer*, const std::string&, const aula::referee_status_t* msg) {
  if (msg->generation != generation_()) return;  // about an episode before a reload
  latest_ = *msg;
  if (msg->finished && finished_generation_ != msg->generation) {
    finished_generation_ = msg->generation;
    std::cerr << program_ << ": the referee ended the episode at " << msg->elapsed_s << " s: " << msg->ending << ": "
              << msg->summary << std::endl;
    if (on_finished_) on_finished_(*msg);
  }
}

std::string refereeStatusLine(const std::optional<aula::referee_status_t>& status, const std::string& start_action) {
  if (!status) return "no word from the referee yet";
  if (status->finished) return status->ending + ": " + status->summary;
  if (!status->started) return "the referee's clock starts at " + start_action;
  const long left_s = std::lround(std::floor(std::max(0.0, status->time_left_s)));
  char clock[64];
  std::snprintf(clock, sizeof clock, "time left %ld:%02ld", left_s / 60, left_s % 60);
  return status->summary.empty() ? std::string(clock) : std::string(clock) + " - " + status->summary;
}

}  // namespace aula::component
