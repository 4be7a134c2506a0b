#pragma once
// Running manifest entries: each run is `aula run ... --headless` on its own LCM port, with a
// wall-time limit; its result (the referee's report plus who, what and why it failed) goes to
// runs/<student>/<world>-seed<k>.json. A run that crashes, hangs or runs out of time is
// recorded with its reason and the batch goes on.

#include <aula/grade/grade_plan.hpp>

#include <functional>
#include <string>

namespace aula::grade {

// Is the run's result already there for the same plugin, world and seed (resume)?
bool upToDate(const PlannedRun& run);

// Runs one entry to its end (Slurm's `aula grade-task MANIFEST INDEX`). Returns the result.
nlohmann::ordered_json runOne(const PlannedRun& run);

// Runs the entries that are not up to date, at most `jobs` at once. `on_done(run, result,
// done, total)` after each.
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
