#include "aula/referee/run_outcome.hpp"

#include <sstream>

namespace aula::referee {

bool RunOutcome::onEpisode(const std::string& algorithm, const std::string& fault, int64_t non_finite_commands,
                           int generation, const std::string& status, const std::string& not_the_seeds_run) {
  const bool new_episode = generation > generation_;
  if (new_episode) {
    generation_ = generation;
    fault_.clear();
    announced_ = false;
  }
  algorithm_ = algorithm;
  status_ = status;
  // The component's reasons only grow (a reload keeps them): the latest says them all.
  if (!not_the_seeds_run.empty()) not_the_seeds_run_ = not_the_seeds_run;
  if (fault_.empty()) fault_ = fault;
  non_finite_commands_ = non_finite_commands;
  return new_episode;
}

void RunOutcome::algorithmFailed(const std::string& fault) {
  if (fault_.empty()) fault_ = fault;
}

void RunOutcome::abort(const std::string& reason) {
  if (aborted_.empty()) aborted_ = reason;
}

void RunOutcome::announceOnce(bool over, const std::function<void()>& hook) {
  if (!over || announced_) return;
  announced_ = true;
  if (hook) hook();
}

void RunOutcome::addTo(Report& report) const {
  report.set("algorithm", algorithm_);
  if (ended()) report.set("finished", false);
  // What the algorithm said last (a reference that gives up says why and where), as it said it.
  if (!status_.empty()) report.set("algorithm_status", status_);
  if (!fault_.empty()) report.set("algorithm_error", fault_);
  if (!aborted_.empty()) report.set("aborted", aborted_);
  if (non_finite_commands_ > 0) report.set("non_finite_commands", static_cast<long long>(non_finite_commands_));
  // Graded is the episode after this many hot reloads of the algorithm.
  if (generation_ > 0) report.set("reloads", static_cast<long long>(generation_));
  // A windowed run that is not what the headless run of its seed is, and why.
  if (!not_the_seeds_run_.empty()) report.set("not_the_seeds_run", validUtf8(not_the_seeds_run_));
  truth_.addTo(report);
}

EpisodeStatus RunOutcome::episodeStatus(bool started, double elapsed_s, double length_s, bool graded_to_end,
                                        const std::string& graded_ending) const {
  EpisodeStatus s;
  s.generation = generation_;
  s.started = started;
  s.elapsed_s = started ? elapsed_s : 0.0;
  s.time_left_s = length_s - s.elapsed_s;
  s.finished = graded_to_end || ended();
  if (s.finished) s.ending = ended() ? "Stopped" : graded_ending;
  return s;
}

std::string RunOutcome::summary() const {
  std::string out;
  if (!status_.empty()) out += "  the algorithm said: " + validUtf8(status_) + "\n";
  if (!fault_.empty()) out += "  the student's algorithm failed: " + fault_ + "\n";
  if (!aborted_.empty()) out += "  the run was aborted: " + aborted_ + "\n";
  if (!not_the_seeds_run_.empty()) out += "  not its seed's graded run: " + validUtf8(not_the_seeds_run_) + "\n";
  if (non_finite_commands_ > 0) {
    out += "  " + std::to_string(non_finite_commands_) + " motor commands were not finite numbers (set to 0)\n";
  }
  return out + truth_.summary();
}

std::vector<std::string> RunOutcome::pictureNotes(const std::string& world_file, long long seed) const {
  std::vector<std::string> out = {"world " + world_file + ", seed " + std::to_string(seed) + ", algorithm " + algorithm_ +
                                  (generation_ > 0 ? ", after " + std::to_string(generation_) + " reloads" : "")};
  std::istringstream lines(summary());
  for (std::string line; std::getline(lines, line);) out.push_back(line.substr(line.find_first_not_of(' ')));
  return out;
}

}  // namespace aula::referee
