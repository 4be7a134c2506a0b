#include "aula/referee/truth_gate.hpp"

#include <aula/lcm/bus.hpp>

namespace aula::referee {

bool TruthGate::inSequence(const std::string& channel, int64_t seq) {
  const auto last = last_seq_.find(channel);
  if (last == last_seq_.end()) {  // the first one seen: whatever came before is not ours to count
    last_seq_[channel] = seq;
    return true;
  }
  if (seq <= last->second) {
    if (!signer_) return true;  // without a key nothing tells a replay from a stray: as before
    ++tampering_[channel];   // signed, but seen already: a replay of the simulator's message
    return false;
  }
  if (seq > last->second + 1) gaps_[channel] += seq - last->second - 1;
  last->second = seq;
  return true;
}

bool TruthGate::acceptTick(const std::string& channel, const aula::sim_clock_t& tick) {
  if (!accept(channel, tick)) return false;
  simulator_rejected_controls_ = tick.rejected_controls;
  return true;
}

bool TruthGate::contradictsEpisode(const std::string& channel, const aula::episode_t& msg) {
  if (!signer_) return false;  // with windows a reload starts a new episode, GO! picks a goal
  if (!first_episode_) {
    first_episode_ = msg;
    return false;
  }
  aula::episode_t& first = *first_episode_;
  // What the component fills in later (the start, the goal) is taken once, then must not change.
  if (first.started_utime < 0) first.started_utime = msg.started_utime;
  if (!first.goal_set && msg.goal_set) {
    first.goal_set = true;
    first.goal_x = msg.goal_x;
    first.goal_y = msg.goal_y;
  }
  const bool contradicts = msg.generation != first.generation || msg.exercise != first.exercise ||
                           (msg.started_utime >= 0 && msg.started_utime != first.started_utime) ||
                           (msg.goal_set && (msg.goal_x != first.goal_x || msg.goal_y != first.goal_y));
  if (contradicts) ++tampering_[channel];
  return contradicts;
}

std::map<std::string, long long> TruthGate::tampering() const {
  std::map<std::string, long long> all = tampering_;
  if (simulator_rejected_controls_ > 0) all[lcmbus::kControlChannel] += simulator_rejected_controls_;
  return all;
}

void TruthGate::addTo(Report& report) const {
  if (!tampering().empty()) report.set("tampering", tampering());
  if (!escapes_.empty()) report.set("escape_attempts", escapes_);
  if (!gaps_.empty()) report.set("truth_gaps", gaps_);
}

std::string TruthGate::summary() const {
  std::string out;
  for (const auto& [channel, count] : tampering()) {
    out += "  TAMPERING: " + std::to_string(count) + " forged or refused messages on " + channel + "\n";
  }
  for (const auto& [what, count] : escapes_) {
    out += "  TAMPERING: the algorithm tried to get out of the run: " + what + " (" + std::to_string(count) + " times)\n";
  }
  for (const auto& [channel, count] : gaps_) {
    out += "  " + std::to_string(count) + " messages of " + channel + " were lost before the referee saw them\n";
  }
  return out;
}

}  // namespace aula::referee
