// aula calibrate's judgement of its anchor runs (calibration.hpp), on result files written here:
// a run that failed by its exercise's declaration (Autopark not parked, a vacuum cleaner wedged)
// is refused with a message naming the world, the seed, the field and the run's log; each anchor
// run's progress line says how it went.
#include <aula/config/config.hpp>
#include <aula/grade/calibration.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace aula::grade;

namespace {

std::string scratch() {
  std::string pattern = (fs::temp_directory_path() / "aula_calibration_XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

CalibrationSpec specOf(const std::string& exercise) {
  const auto spec = calibrationSpecOf(exercise);
  if (!spec) throw std::runtime_error(exercise + " declares no calibration");
  return *spec;
}

// The anchor's runs on house.world, one per result (seeds 1, 2...), each result written as its run's file.
Manifest anchorRuns(const std::string& dir, const std::vector<nlohmann::json>& results) {
  Manifest m;
  for (size_t i = 0; i < results.size(); ++i) {
    PlannedRun run;
    run.student = "anchor";
    run.world_name = "house.world";
    run.seed = static_cast<long long>(i) + 1;
    run.result_path = dir + "/house-seed" + std::to_string(run.seed) + ".json";
    run.log_path = dir + "/house-seed" + std::to_string(run.seed) + ".log";
    std::ofstream(run.result_path) << results[i].dump();
    m.runs.push_back(run);
  }
  return m;
}

// The refusal's message, or "" when the anchor runs may set the scale.
std::string refusal(const Manifest& m, const CalibrationSpec& spec, const std::string& anchor) {
  try {
    requireAnchorSucceeded(m, spec, anchor);
    return "";
  } catch (const aula::config::ConfigError& e) {
    return e.what();
  }
}

}  // namespace

TEST(CalibrationAnchor, AWedgedCleanerIsRefusedNamingTheWorldTheSeedTheFieldAndTheLog) {
  const std::string dir = scratch();
  const CalibrationSpec vacuum = specOf("vacuum");
  const nlohmann::json cleaning = {{"mark", 10.0}, {"coverage_percent", 86.0}, {"wedged", false}, {"stuck_at_end_s", 0.0}};
  const nlohmann::json wedged = {{"mark", 9.0}, {"coverage_percent", 70.0}, {"wedged", true}, {"stuck_at_end_s", 240.0}};
  EXPECT_EQ(refusal(anchorRuns(dir, {cleaning, cleaning}), vacuum, "reference"), "");
  const std::string said = refusal(anchorRuns(dir, {cleaning, cleaning, wedged}), vacuum, "reference");
  EXPECT_EQ(said,
            "aula calibrate: the anchor (reference) ended wedged (its report's wedged is true) on house.world with seed 3: "
            "it cannot set the scale, and no rubric was written; try another anchor, e.g. --anchor=classic; see " +
                dir + "/house-seed3.log");
  // The classic itself wedged: no suggestion to try the classic.
  EXPECT_EQ(refusal(anchorRuns(dir, {wedged}), vacuum, "classic").find("--anchor="), std::string::npos);
  // Only the anchor's runs set the scale: a wedged baseline is a baseline.
  Manifest with_baseline = anchorRuns(dir, {cleaning});
  with_baseline.runs.front().student = "baseline";
  std::ofstream(with_baseline.runs.front().result_path) << wedged.dump();
  EXPECT_EQ(refusal(with_baseline, vacuum, "reference"), "");
  fs::remove_all(dir);
}

TEST(CalibrationAnchor, AnAutoparkAnchorThatDidNotParkIsRefusedAsBefore) {
  const std::string dir = scratch();
  const CalibrationSpec autopark = specOf("autopark");
  EXPECT_EQ(autopark.failure, "");
  const nlohmann::json parked = {{"mark", 7.5}, {"park_time_s", 120.0}, {"parked", true}};
  const nlohmann::json not_parked = {{"mark", 1.0}, {"park_time_s", 300.0}, {"parked", false}};
  EXPECT_EQ(refusal(anchorRuns(dir, {parked}), autopark, "reactive"), "");
  EXPECT_EQ(refusal(anchorRuns(dir, {parked, not_parked}), autopark, "reactive"),
            "aula calibrate: the anchor (reactive) did not succeed (its report's parked is not true) on house.world with "
            "seed 2: it cannot set the scale, and no rubric was written; try another anchor, e.g. --anchor=planner; see " +
                dir + "/house-seed2.log");
  const nlohmann::json no_mark = {{"mark", 0.0}, {"park_time_s", 100.0}, {"parked", true}};
  EXPECT_NE(refusal(anchorRuns(dir, {no_mark}), autopark, "reactive").find("(reactive) earned no mark on house.world"),
            std::string::npos);
  fs::remove_all(dir);
}

TEST(CalibrationAnchor, EachAnchorRunsLineSaysHowItWent) {
  const CalibrationSpec vacuum = specOf("vacuum"), autopark = specOf("autopark");
  EXPECT_EQ(anchorNote({{"mark", 9.0}, {"wedged", true}}, vacuum), " (wedged)");
  EXPECT_EQ(anchorNote({{"mark", 10.0}, {"wedged", false}}, vacuum), " (not wedged)");
  EXPECT_EQ(anchorNote({{"mark", 7.5}, {"parked", true}}, autopark), " (parked)");
  EXPECT_EQ(anchorNote({{"mark", 1.0}, {"parked", false}}, autopark), " (not parked)");
  CalibrationSpec neither = vacuum;
  neither.failure = "";
  EXPECT_EQ(anchorNote({{"mark", 10.0}}, neither), "");
}
