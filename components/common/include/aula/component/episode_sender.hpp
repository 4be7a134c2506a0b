#pragma once
// The component's episode messages to the referee (episode_t): sent on every change and once
// per second of sim time, with what the algorithm host knows (its name, its fault, how many
// motor commands it refused). One sender for every exercise.

#include <aula/component/algorithm_host.hpp>

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace aula::component {

struct EpisodeState {
  bool running = false;
  int64_t started_utime = -1;                         // -1: not started
  std::optional<std::pair<double, double>> goal_xy_m;  // TeleTaxi's destination
  int generation = 0;                                 // algorithm (re)loads
};

class EpisodeSender {
 public:
  EpisodeSender(lcm::LCM& bus, std::string channel, std::string exercise, const AlgorithmHostBase& host)
      : bus_(bus), channel_(std::move(channel)), exercise_(std::move(exercise)), host_(host) {}

  void markChanged() { changed_ = true; }
  void tick(int64_t utime, const EpisodeState& state);

 private:
  lcm::LCM& bus_;
  std::string channel_, exercise_;
  const AlgorithmHostBase& host_;
  int64_t last_utime_ = -1'000'000'000;
  bool changed_ = true;
};

}  // namespace aula::component
