#pragma once
// The component's episode messages to the referee (episode_t): sent on every change and once
// per second of sim time, with what the algorithm host knows (its name, its fault, how many
// motor commands it refused). One sender for every exercise.
//
// A new episode (hot reload): the robot is sent back to its start pose (SIM_CONTROL SET_POSE) at
// once, and the next generation goes out at the next tick. The simulator cannot pass that tick
// before this component acknowledges it, which is after the SET_POSE was sent: every pose the
// referee sees later than the episode message's time is from the new episode.

#include <aula/component/algorithm_host.hpp>

#include <aula/lcm/bus.hpp>
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
  std::string status;  // what the algorithm says of where it stands (Autopark's api.status), or ""
  std::string not_the_seeds_run;  // why the run is no longer its seed's graded run, or ""
};

// Where a robot starts in the world: a new episode puts it back there.
struct StartPose {
  std::string robot;
  double x_m = 0, y_m = 0, yaw_rad = 0;
};

class EpisodeSender {
 public:
  EpisodeSender(lcmbus::Bus& bus, std::string channel, std::string exercise, const AlgorithmHostBase& host)
      : bus_(bus), channel_(std::move(channel)), exercise_(std::move(exercise)), host_(host) {}

  void markChanged() { changed_ = true; }
  void tick(int64_t utime, const EpisodeState& state);
  // Starts the next episode: the robot goes back to `start`, the generation counts up.
  void restart(const StartPose& start);
  int generation() const { return generation_; }

 private:
  lcmbus::Bus& bus_;
  std::string channel_, exercise_;
  const AlgorithmHostBase& host_;
  int64_t last_utime_ = -1'000'000'000;
  bool changed_ = true;
  std::string last_status_;  // the status last sent: a new one is a change
  std::string last_not_the_seeds_run_;
  int generation_ = 0;  // algorithm (re)loads: each is a new episode for the referee
};

}  // namespace aula::component
