#pragma once
// The algorithm's belief (devices.hpp: its own pose, its own map) on the bus, after each
// execute() that set it (belief_t): its pose every time, its map's cells only when the algorithm
// changed it and at most once per `map_period_us` of sim time. Never read by the referee's
// marks: the window draws it beside the truth, the run's log keeps it.

#include <aula/component/devices.hpp>
#include <aula/lcm/bus.hpp>

#include <cstdint>
#include <string>

namespace aula::component {

class BeliefPublisher {
 public:
  BeliefPublisher(lcmbus::Bus& bus, std::string channel, const Belief& belief, int64_t map_period_us = 1'000'000)
      : bus_(bus), channel_(std::move(channel)), belief_(belief), map_period_us_(map_period_us) {}

  // After the execute() of sim time `utime`: publishes what the algorithm said, if anything.
  void publish(int64_t utime);

 private:
  lcmbus::Bus& bus_;
  std::string channel_;
  const Belief& belief_;
  int64_t map_period_us_;
  int64_t map_sent_version_ = 0;
  int64_t map_sent_utime_ = -1'000'000'000'000;
};

}  // namespace aula::component
