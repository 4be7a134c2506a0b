#pragma once
// Plays a recorded run (LCM log) onto a bus on the log's own sim clock: every event whose sim
// time has come is published, in the log's order. An event's sim time is the last SIM_CLOCK
// tick at or before it. Seeking back starts again from the log's start (the viewers that
// consumed the events are restarted by the caller).

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace aula::replay {

class LogPlayer {
 public:
  using Publish = std::function<void(const lcm::LogEvent&)>;
  // Throws config::ConfigError naming `path` when it is not a readable LCM log. `episode_channel`:
  // where the recorded component said which algorithm ran (episode_t).
  LogPlayer(std::string path, Publish publish, const std::string& episode_channel);

  int64_t durationUs() const { return duration_us_; }  // the last tick's sim time
  int64_t positionUs() const { return position_us_; }  // sim time of what has been published
  bool atEnd() const { return next_ == nullptr; }
  // The recorded run's algorithm ("reference", "libmy_algorithm.so"), or "" when the log has no
  // episode message (the component never started).
  const std::string& algorithm() const { return algorithm_; }

  // Publishes the events up to sim time `target_us`, at most `max_events` of them (a bound per
  // call keeps UDP from overflowing the viewers' buffers). Returns how many it published.
  int playUntil(int64_t target_us, int max_events);
  // Back to the log's start (nothing published yet).
  void rewind();

 private:
  void readNext();

  std::string path_;
  Publish publish_;
  std::unique_ptr<lcm::LogFile> log_;
  const lcm::LogEvent* next_ = nullptr;
  int64_t next_sim_us_ = 0;  // the sim time of `next_`
  int64_t clock_us_ = 0;     // the last tick read
  int64_t position_us_ = 0;
  int64_t duration_us_ = 0;
  std::string algorithm_;
};

}  // namespace aula::replay
