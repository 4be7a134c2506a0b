#pragma once
// Running manifest entries: each run is `aula run ... --headless` on its own LCM port, with a
// wall-time limit; its result (the referee's report plus who, what and why it failed) goes to
// runs/<student>/<world>-seed<k>.json. A run that crashes, hangs or runs out of time is
// recorded with its reason and the batch goes on. An out folder that can take no more (a full
// disk, a quota) stops the batch instead (GradeStopped): that is not any student's failure.

#include <aula/grade/grade_plan.hpp>

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

namespace aula::grade {

// The grade cannot go on: a run's result could not be written (the message names the file and
// the system's reason), or a run failed while the out folder had less than kRoomForARunBytes free
// (a report that could not be written is no verdict on the student). The runs under way are
// stopped and leave no file; every run finished before keeps its result.
struct GradeStopped : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// What a run needs in the out folder beyond its recorded log: its capped output (at most 320 KiB),
// the referee's report, picture and trace, and its result.
constexpr uint64_t kRoomForARunBytes = 1u << 20;

// Is the run's result already there for the same plugin, world, seed and settings (resume)? A
// run that ended for the machine's reason, not the algorithm's (a process starved past the
// lockstep's wall-clock limits, the run's wall budget), is run again: a run is the same run
// whenever it runs (sim time is its only clock), so this costs time, never a mark.
bool upToDate(const PlannedRun& run);
// The run's failure when this grade found it the machine's (the result's `machine_reason`, which
// only resultOf() writes, from what the grade and the launcher saw), or "".
std::string machineFailureOf(const nlohmann::json& result);
// How many times a run that ended for the machine's reason is run again before it is left out
// of the grade as not completed (grades.hpp: runs_incomplete; the grade then exits 1).
constexpr size_t kMachineRetries = 2;

// Runs one entry to its end (Slurm's `aula grade-task MANIFEST INDEX`). Returns the result;
// throws GradeStopped.
nlohmann::ordered_json runOne(const PlannedRun& run);

// Runs the entries that are not up to date, at most `jobs` at once. `on_done(run, result,
// done, total)` after each. Throws GradeStopped once every run under way is stopped.
struct Progress {
  int done = 0, total = 0, failed = 0, skipped = 0;
};
void runLocal(const Manifest& manifest, int jobs,
              const std::function<void(const PlannedRun&, const nlohmann::ordered_json&, const Progress&)>& on_done);

// The failure of a result, or "" when the run went to its end.
std::string failureOf(const nlohmann::json& result);
// "" or what the referee caught someone forging in the run: "tampering: ROOMBA_POSE 1532, SIM_CONTROL 1"
// (the report's "tampering"). Such a run keeps the mark of its true behaviour, and is flagged.
std::string tamperingOf(const nlohmann::json& result);

}  // namespace aula::grade
