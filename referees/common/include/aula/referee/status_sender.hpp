#pragma once
// The referee's status to the windows (referee_status_t on <EXERCISE>_REFEREE): the episode's
// time left on the referee's own sim-time clock and, at the end, how it ended. The referee is
// the one authority on the episode's clock; the component's window only shows what it is sent.
// Sent at every change (started, finished, a new episode), and once per second of sim time.

#include <aula/lcm/bus.hpp>
#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <string>

namespace aula::referee {

struct EpisodeStatus {
  int generation = 0;       // the episode graded (counts hot reloads)
  bool started = false;     // its clock runs
  double elapsed_s = 0;     // sim seconds since its start
  double time_left_s = 0;   // sim seconds until the referee ends it
  bool finished = false;
  std::string ending;       // "Time's up", "Arrived", "Parked", "Stopped" (only when finished)
  std::string summary;      // one line of the referee's numbers
};

class StatusSender {
 public:
  StatusSender(lcmbus::Bus& bus, std::string channel, std::string exercise)
      : bus_(bus), channel_(std::move(channel)), exercise_(std::move(exercise)) {}

  // At a clock tick or an episode message: sends when the status changed state or a sim second
  // has passed; after a finished status, nothing more about that episode.
  void tick(int64_t utime, const EpisodeStatus& status);
  // Now, whatever the time (the end of a run that the launcher aborted).
  void send(int64_t utime, const EpisodeStatus& status);

 private:
  lcmbus::Bus& bus_;
  std::string channel_, exercise_;
  int64_t last_utime_ = -1'000'000'000;
  int last_generation_ = -1;
  bool last_started_ = false, last_finished_ = false;
};

}  // namespace aula::referee
