#include "aula/grade/grade_runner.hpp"

#include "run_result.hpp"

#include <aula/process/exit_codes.hpp>
#include <aula/process/machine_reason.hpp>

#include <aula/config/paths.hpp>
#include <aula/process/child_process.hpp>
#include <aula/process/cpu_affinity.hpp>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <thread>

#include <unistd.h>

namespace aula::grade {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

// A run that did not finish leaves nothing: its output, the referee's files, its recorded log
// (with its key) and any result from an earlier try (another plugin's) are removed.
void discardUnfinished(const PlannedRun& run) {
  const fs::path result(run.result_path);
  const std::string stem = result.stem().string() + ".";  // "vacuum-seed1.": not "vacuum-seed10."
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(result.parent_path(), error)) {
    if (entry.path().filename().string().rfind(stem, 0) == 0) fs::remove(entry.path(), error);
  }
}

// One run under way: `aula run ...` as a child, with the run's wall-time limit.
class RunInProgress {
 public:
  // `cpu` >= 0: the run's processes run on that CPU only (given before the launcher starts, which
  // keeps it: see aula/process/cpu_affinity.hpp).
  // `earlier`: why the earlier tries of this run ended (the machine's reasons), for its result.
  RunInProgress(const PlannedRun& run, int cpu, std::vector<std::string> earlier = {})
      : run_(run), started_(Clock::now()), cpu_(cpu), earlier_(std::move(earlier)) {
    fs::create_directories(fs::path(run.result_path).parent_path());
    // A report or picture from an earlier try must not pass for this one's.
    fs::remove(run.report_path);
    fs::remove(fs::path(run.result_path).replace_extension(".png"));
    fs::remove(fs::path(run.result_path).replace_extension(".trace.json"));
    fs::remove(fs::path(run.result_path).replace_extension(".trace.z"));  // the grade's compact copy (run_page.hpp)
    fs::remove(fs::path(run.result_path).replace_extension(".html"));  // its page holds the earlier trace
    if (run.compile_error.empty()) {
      child_ = std::make_unique<process::ChildProcess>(run.argv, run.log_path, run.log_path, std::vector<int>{},
                                                       process::Placement{cpu, false});
    }
  }

  int cpu() const { return cpu_; }
  // The result once the run is over (and written to its file).
  std::optional<nlohmann::ordered_json> poll() {
    std::optional<int> code;
    bool timed_out = false;
    if (child_) {
      code = child_->poll();
      const double wall_s = std::chrono::duration<double>(Clock::now() - started_).count();
      if (!code && wall_s > run_.wall_limit_s) {
        code = child_->stop(std::chrono::milliseconds(5000));  // the launcher stops its own children
        timed_out = true;
      }
      if (!code) return std::nullopt;
    }
    const double wall_s = std::chrono::duration<double>(Clock::now() - started_).count();
    auto result = resultOf(run_, code, timed_out, wall_s);
    if (!earlier_.empty()) {  // a retry is said, never hidden: how many and why
      result["retried"] = earlier_.size();
      result["retried_because"] = earlier_;
    }
    const fs::path folder = fs::path(run_.result_path).parent_path();
    std::error_code error;
    const uint64_t free_bytes = fs::space(folder, error).available;
    if (!failureOf(result).empty() && !error && free_bytes < kRoomForARunBytes) {
      discardUnfinished(run_);
      throw GradeStopped(folder.string() + ": its file system is full (" + std::to_string(free_bytes / 1024) +
                         " KiB free); the run of " + run_.student + " on " + run_.world_name + " seed " +
                         std::to_string(run_.seed) + " ended without its report (" + failureOf(result) +
                         "), which is not the student's failure");
    }
    try {
      config::writeFileAtomically(run_.result_path, result.dump(2) + "\n", "the run's result");
    } catch (const std::runtime_error& e) {
      discardUnfinished(run_);
      throw GradeStopped(e.what());
    }
    return result;
  }

 private:
  const PlannedRun& run_;
  Clock::time_point started_;
  int cpu_;
  std::vector<std::string> earlier_;
  std::unique_ptr<process::ChildProcess> child_;
};

}  // namespace

std::string failureOf(const nlohmann::json& result) {
  return result.contains("failure") ? result["failure"].get<std::string>() : "";
}

std::string tamperingOf(const nlohmann::json& result) {
  std::string text = "tampering:";
  for (const char* kind : {"tampering", "escape_attempts"}) {
    if (!result.contains(kind) || !result[kind].is_object()) continue;
    const std::string prefix = std::string(kind) == "tampering" ? "" : "escape: ";
    for (const auto& [name, count] : result[kind].items()) {
      text += (text.back() == ':' ? " " : ", ") + prefix + name + " " + count.dump();
    }
  }
  return text == "tampering:" ? "" : text;
}

std::string machineFailureOf(const nlohmann::json& result) {
  const auto verdict = result.find("machine_reason");
  if (verdict == result.end() || !verdict->is_boolean() || !verdict->get<bool>()) return "";
  const std::string failure = result.value("failure", std::string());
  return failure.empty() ? process::machineReason("the run did not complete") : failure;
}

bool upToDate(const PlannedRun& run) {
  const auto result = readJson(run.result_path);
  if (!result || !machineFailureOf(*result).empty()) return false;
  auto same = [&](const char* key, const nlohmann::ordered_json& value) { return result->contains(key) && (*result)[key] == value; };
  return same("plugin_sha256", run.plugin_sha256) && same("world_sha256", run.world_sha256) && same("seed", run.seed) &&
         same("student", run.student) && same("settings", run.settings);
}

nlohmann::ordered_json runOne(const PlannedRun& run) {
  RunInProgress running(run, -1);  // where the engine (Slurm) placed this task
  for (;;) {
    if (auto result = running.poll()) return *result;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

namespace {

// Runs at once take different CPUs, as long as there are CPUs enough: each run's processes share
// one (they take turns), and two runs on one CPU would leave another idle.
class CpuShares {
 public:
  int quietest() {
    if (cpus_.empty()) return -1;
    const auto at = std::min_element(runs_on_.begin(), runs_on_.end()) - runs_on_.begin();
    ++runs_on_[at];
    return cpus_[at];
  }
  void release(int cpu) {
    const auto at = std::find(cpus_.begin(), cpus_.end(), cpu) - cpus_.begin();
    if (at < static_cast<long>(cpus_.size())) --runs_on_[at];
  }

 private:
  std::vector<int> cpus_ = process::allowedCpus();
  std::vector<int> runs_on_ = std::vector<int>(cpus_.size(), 0);
};

}  // namespace

void runLocal(const Manifest& manifest, int jobs,
              const std::function<void(const PlannedRun&, const nlohmann::ordered_json&, const Progress&)>& on_done) {
  Progress progress;
  progress.total = static_cast<int>(manifest.runs.size());
  std::vector<const PlannedRun*> pending;
  for (const PlannedRun& run : manifest.runs) {
    if (upToDate(run)) {
      ++progress.done;
      ++progress.skipped;
      if (!failureOf(*readJson(run.result_path)).empty()) ++progress.failed;
    } else {
      pending.push_back(&run);
    }
  }
  CpuShares cpus;
  std::vector<std::pair<const PlannedRun*, std::unique_ptr<RunInProgress>>> running;
  std::map<const PlannedRun*, std::vector<std::string>> retried_because;
  size_t next = 0;
  while (next < pending.size() || !running.empty()) {
    while (next < pending.size() && static_cast<int>(running.size()) < jobs) {
      running.emplace_back(pending[next],
                           std::make_unique<RunInProgress>(*pending[next], cpus.quietest(), retried_because[pending[next]]));
      ++next;
    }
    for (auto it = running.begin(); it != running.end();) {
      std::optional<nlohmann::ordered_json> result;
      try {
        result = it->second->poll();
      } catch (const GradeStopped&) {
        for (auto& [planned, under_way] : running) {
          under_way.reset();  // stops the run's launcher, which stops its processes
          discardUnfinished(*planned);
        }
        throw;
      }
      if (!result) {
        ++it;
        continue;
      }
      cpus.release(it->second->cpu());
      // Ended for the machine's reason (a process starved past the lockstep's limits), as the
      // launcher or this grade saw it: the same run again (the same command, seed and world:
      // nothing tells it apart), twice at most; it gives the same result whenever it runs.
      const std::string machine = machineFailureOf(*result);
      if (!machine.empty() && retried_because[it->first].size() < kMachineRetries) {
        retried_because[it->first].push_back(machine);
        std::cerr << "aula grade: " << it->first->student << " " << it->first->world_name << " seed " << it->first->seed
                  << " ended for " << machine << ": running it again\n";
        pending.push_back(it->first);
        it = running.erase(it);
        continue;
      }
      ++progress.done;
      if (!failureOf(*result).empty()) ++progress.failed;
      on_done(*it->first, *result, progress);
      it = running.erase(it);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace aula::grade
