#include "log_player.hpp"

#include <aula/lcm/bus.hpp>
#include <aula/lcm/log_replay.hpp>
#include <aula/episode_t.hpp>
#include <aula/sim_clock_t.hpp>

#include <algorithm>

namespace aula::replay {

namespace {

// The tick's sim time when `event` is a SIM_CLOCK tick, else -1.
int64_t tickUs(const lcm::LogEvent& event) {
  if (event.channel != lcmbus::kClockChannel) return -1;
  aula::sim_clock_t tick;
  if (tick.decode(event.data, 0, static_cast<int>(event.datalen)) < 0) return -1;
  return tick.utime;
}

}  // namespace

LogPlayer::LogPlayer(std::string path, Publish publish, const std::string& episode_channel)
    : path_(std::move(path)), publish_(std::move(publish)) {
  lcmbus::requireLog(path_);
  // One pass for the length of the run and its algorithm, then back to the start.
  lcm::LogFile scan(path_, "r");
  for (const lcm::LogEvent* e = scan.readNextEvent(); e != nullptr; e = scan.readNextEvent()) {
    duration_us_ = std::max(duration_us_, tickUs(*e));
    aula::episode_t episode;
    if (algorithm_.empty() && e->channel == episode_channel &&
        episode.decode(e->data, 0, static_cast<int>(e->datalen)) >= 0) {
      algorithm_ = episode.algorithm;
    }
  }
  rewind();
}

void LogPlayer::rewind() {
  log_ = std::make_unique<lcm::LogFile>(path_, "r");
  clock_us_ = position_us_ = 0;
  readNext();
}

void LogPlayer::readNext() {
  next_ = log_->readNextEvent();
  if (next_ == nullptr) return;
  const int64_t tick = tickUs(*next_);
  if (tick >= 0) clock_us_ = tick;
  next_sim_us_ = clock_us_;
}

int LogPlayer::playUntil(int64_t target_us, int max_events) {
  int published = 0;
  while (next_ != nullptr && next_sim_us_ <= target_us && published < max_events) {
    publish_(*next_);
    position_us_ = next_sim_us_;
    ++published;
    readNext();
  }
  if (published < max_events && next_ != nullptr) position_us_ = std::max(position_us_, std::min(target_us, next_sim_us_));
  return published;
}

}  // namespace aula::replay
