#pragma once
// What a referee lets through to its grading, and what it counts of the rest.
//
// In a graded run (the launcher's key, `--key-fd`) the referee grades only what the simulator
// signed (aula_auth): the robot's pose and bumper and the clock. A message that is not signed
// with the run's key, or that repeats an auth_seq already seen (a replay of a real one), is not
// graded and is counted as tampering on its channel. The simulator's own count of SIM_CONTROL
// requests it refused comes in its signed clock and is reported the same way. The episode
// messages come from the component and cannot be signed: in a graded run the first episode
// (its generation, start and goal) is kept, and a later one that contradicts it is not followed
// and is counted (a graded run has no hot reload, one start and one goal).
//
// In every run, the auth_seq of the messages let through counts the ones lost in between
// ("truth_gaps"). Without a key (windows, three terminals, a regrade) everything is let through,
// as before. The report gains "tampering" and "truth_gaps" only when they are not empty, so an
// unattacked run's report is unchanged.

#include <aula/auth/run_key.hpp>
#include <aula/episode_t.hpp>
#include <aula/referee/report.hpp>
#include <aula/sim_clock_t.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace aula::referee {

class TruthGate {
 public:
  explicit TruthGate(const std::optional<auth::Key>& key = std::nullopt) {
    if (key) signer_.emplace(*key);
  }
  bool keyed() const { return signer_.has_value(); }

  // True when `msg` (a type with auth_seq and auth) on `channel` may be graded; otherwise it
  // was counted as tampering.
  template <class Message>
  bool accept(const std::string& channel, const Message& msg) {
    if (signer_ && !auth::verify(*signer_, channel, msg)) {
      ++tampering_[channel];
      return false;
    }
    return inSequence(channel, msg.auth_seq);
  }
  // accept() for the clock, which also carries the simulator's count of refused SIM_CONTROL.
  bool acceptTick(const std::string& channel, const aula::sim_clock_t& tick);
  // True (and counted on `channel`) when, in a graded run, `msg` contradicts the episode the
  // first one described: the caller then ignores it.
  bool contradictsEpisode(const std::string& channel, const aula::episode_t& msg);

  // What the student's code tried to get out of the run, as the launcher saw it ("escape WHAT"):
  // a system call only an escape needs, which the graded component's watch refused
  // (sandbox/forbidden_calls.hpp: "mount"), or a datagram sent outside the run's LCM channel
  // ("datagram to port 9"). Counted by what; the run is flagged.
  void escapeAttempt(const std::string& what) { ++escapes_[what]; }
  const std::map<std::string, long long>& escapeAttempts() const { return escapes_; }

  bool tampered() const { return !tampering().empty() || !escapes_.empty(); }
  // Forged or refused messages by channel (the referee's and the simulator's counts together).
  std::map<std::string, long long> tampering() const;
  const std::map<std::string, long long>& gaps() const { return gaps_; }
  void addTo(Report& report) const;
  // "" or one line per finding, for the printed summary.
  std::string summary() const;

 private:
  bool inSequence(const std::string& channel, int64_t seq);

  std::optional<auth::Signer> signer_;  // the run's key, prepared
  std::map<std::string, int64_t> last_seq_;
  std::map<std::string, long long> tampering_, gaps_, escapes_;
  long long simulator_rejected_controls_ = 0;
  std::optional<aula::episode_t> first_episode_;
};

}  // namespace aula::referee
