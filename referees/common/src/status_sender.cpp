#include "aula/referee/status_sender.hpp"

#include <aula/referee_status_t.hpp>

#include <algorithm>

namespace aula::referee {

void StatusSender::tick(int64_t utime, const EpisodeStatus& status) {
  // The end is said once, as it was when the referee ended the episode (its report's numbers).
  if (last_finished_ && status.generation == last_generation_) return;
  const bool changed = status.generation != last_generation_ || status.started != last_started_ ||
                       status.finished != last_finished_;
  if (!changed && utime - last_utime_ < 1'000'000) return;
  send(utime, status);
}

void StatusSender::send(int64_t utime, const EpisodeStatus& status) {
  aula::referee_status_t msg;
  msg.utime = utime;
  msg.exercise = exercise_;
  msg.generation = status.generation;
  msg.started = status.started;
  msg.elapsed_s = status.elapsed_s;
  msg.time_left_s = std::max(0.0, status.time_left_s);
  msg.finished = status.finished;
  msg.ending = status.finished ? status.ending : "";
  msg.summary = status.summary;
  bus_.publish(channel_, &msg);
  last_utime_ = utime;
  last_generation_ = status.generation;
  last_started_ = status.started;
  last_finished_ = status.finished;
}

}  // namespace aula::referee
