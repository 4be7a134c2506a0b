#pragma once
// What a referee learns about a run besides the robot's truth: the algorithm's name, a fault
// that halted the student's algorithm (from the component's episode messages), motor commands
// it refused, and an abort from the launcher (a process died, execute() hung). A fault or an
// abort ends the grading: the report keeps the mark earned so far and says why it stopped,
// with "finished": false.
//
// A new generation in the episode messages is a new episode (the student reloaded their
// algorithm): the referee grades it from scratch, and the fault of the previous build is gone.

#include <aula/referee/report.hpp>
#include <aula/referee/status_sender.hpp>
#include <aula/referee/truth_gate.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace aula::referee {

class RunOutcome {
 public:
  // True when `generation` starts a new episode: the caller then resets its grading.
  // `status`: what the algorithm last said of where it stands (episode_t.status).
  // `not_the_seeds_run`: why the run is no longer its seed's graded run (teleoperated, stopped,
  // reloaded, out of lockstep), or "" (episode_t's).
  bool onEpisode(const std::string& algorithm, const std::string& fault, int64_t non_finite_commands, int generation,
                 const std::string& status = "", const std::string& not_the_seeds_run = "");
  void abort(const std::string& reason);  // the first reason wins
  // The algorithm's fault told by the launcher (a crash's line), as if the episode had said it.
  void algorithmFailed(const std::string& fault);

  bool ended() const { return !fault_.empty() || !aborted_.empty(); }
  // Calls `hook` once: the first time `over` holds (graded to the end, or ended early).
  void announceOnce(bool over, const std::function<void()>& hook);
  const std::string& algorithm() const { return algorithm_; }
  const std::string& fault() const { return fault_; }
  const std::string& algorithmStatus() const { return status_; }
  const std::string& aborted() const { return aborted_; }
  const std::string& notTheSeedsRun() const { return not_the_seeds_run_; }
  int generation() const { return generation_; }
  // The motor commands the component refused so far (not finite numbers, sent as 0).
  int64_t nonFiniteCommands() const { return non_finite_commands_; }
  // What was let through to grading and what was forged (a graded run's key, set by the node).
  TruthGate& truth() { return truth_; }
  const TruthGate& truth() const { return truth_; }
  // The report's fields: algorithm, and when they apply algorithm_status, algorithm_error, aborted,
  // non_finite_commands, reloads, not_the_seeds_run, tampering, truth_gaps; "finished" becomes false when the run
  // ended early.
  void addTo(Report& report) const;
  // The windows' status of an episode of `length_s` sim seconds: finished when graded to its end
  // (`graded_ending`: "Time's up", "Arrived"...) or ended early ("Stopped"). The summary is the caller's.
  EpisodeStatus episodeStatus(bool started, double elapsed_s, double length_s, bool graded_to_end,
                              const std::string& graded_ending) const;
  // "" or one line per reason, for the printed summary.
  std::string summary() const;
  // The caption lines of a picture of the run: which world, seed and algorithm, then summary().
  std::vector<std::string> pictureNotes(const std::string& world_file, long long seed) const;

 private:
  std::string algorithm_ = "unknown", fault_, aborted_, status_, not_the_seeds_run_;
  int64_t non_finite_commands_ = 0;
  int generation_ = 0;
  bool announced_ = false;
  TruthGate truth_;
};

}  // namespace aula::referee
