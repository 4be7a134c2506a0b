#pragma once
// Marks that mean the same on every world: `aula calibrate` runs a baseline and an anchor
// algorithm on a world over seeds, and writes the rubric that puts the baseline's median at a 5
// and the anchor's at a 10 into W.rubric.cfg beside the world (docs/grading.md, "Calibration").
// `aula run` (and so `aula grade`) applies that file when the exercise's Rubric preset is
// "default"; "fixed" and "original" never look at it.

#include <aula/config/config.hpp>
#include <aula/grade/grade_plan.hpp>
#include <aula/settings/tables.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace aula::grade {

// What one exercise calibrates (its declaration's, aula/settings/tables.hpp): the report's measure
// that depends on the world, and the rubric settings computed from the baseline's and the
// anchor's medians of it.
struct CalibrationSpec : settings::ExerciseCalibration {
  std::string exercise;
};
// The spec of `exercise`; nullopt when it has none (the message says what it calibrates instead).
std::optional<CalibrationSpec> calibrationSpecOf(const std::string& exercise);

struct CalibrationRequest {
  std::string exercise, world;  // world: a path
  std::vector<long long> seeds;
  std::string baseline, anchor;  // "" for the spec's
  int jobs = 1;
  std::string out_dir;           // the runs go to OUT/runs/{baseline,anchor}/
  std::string command;           // how it was asked, for the file's header
  std::vector<std::pair<std::string, std::string>> overrides;  // settings for every run (a grade's), but the rubric
};

struct MeasuredAlgorithm {
  std::string algorithm;
  std::vector<double> values;  // per seed, in the request's order
  double median = 0, p10 = 0, p90 = 0;
};

struct Calibration {
  CalibrationSpec spec;
  std::string world, world_sha256;
  std::vector<long long> seeds;
  MeasuredAlgorithm baseline, anchor;
  std::vector<std::pair<std::string, std::string>> rubric;   // key, value
  std::vector<std::pair<std::string, std::string>> context;  // the context keys' values in the runs
};

// Runs both algorithms (headless, sandboxed, with the fixed rubric so that an older calibration
// plays no part), measures, and computes the rubric. Throws config::ConfigError when a run
// failed or the anchor does not beat the baseline on this world (no scale can be drawn).
Calibration calibrate(const CalibrationRequest& request, const std::string& bin_dir);

// Refuses the calibration when an anchor run of `manifest` (student "anchor") cannot set the scale:
// it earned no mark, or its report has the spec's success field not true ("parked") or its failure
// field true ("wedged"). The config::ConfigError names the world, the seed, the field, the spec's
// other anchor (unless that is `anchor`) and the run's log.
void requireAnchorSucceeded(const Manifest& manifest, const CalibrationSpec& spec, const std::string& anchor);
// How an anchor run went by the spec's success and failure fields, for its progress line:
// " (parked)", " (not parked)", " (wedged)", " (not wedged)"; "" when the spec declares neither.
std::string anchorNote(const nlohmann::ordered_json& result, const CalibrationSpec& spec);

// The calibration file: the rubric settings, what was measured (as Calibration.* keys), the
// world's SHA-256 and the Aula version.
std::string calibrationText(const Calibration& calibration, const std::string& command);
// W.rubric.cfg beside W.world.
std::string calibrationPathOf(const std::string& world_path);

// The rubric settings of the world's calibration file, each with its origin (file:line), or
// nothing when the world has none. `file`: the calibration to read ("" for the one beside the
// world; one named must exist). `run`: the run's settings, whose context keys must have the
// values the calibration was made with (every process's settings, merged; nullptr: not checked). Throws config::ConfigError naming
// the file and what is wrong when the file is for another exercise, another version of the world
// (its SHA-256) or another context (contextMismatch: another destination, duration, noise or
// speed limit), or holds a key that is not the
// exercise's calibrated rubric.
config::Config readCalibration(const std::string& exercise, const std::string& world_path, const std::string& world_sha256,
                               const std::string& file = "", const config::Config* run = nullptr);

// A setting that makes a calibration unfit for a run: what the calibration was made with, and
// the run's value, each with its origin.
struct ContextMismatch {
  std::string key;
  std::string made, made_origin;  // the file's Calibration.Setting.KEY (file:line), or the shipped .cfg's value
  std::string now, now_origin;
};
// The first of the spec's context keys whose value in `run` (every process's settings, merged:
// settings::mergedSettings) is not the one `file` (a calibration) was made with; nullopt when
// the calibration fits. A key the file does not record (made before Aula recorded it) counts as
// made with the exercise's shipped .cfg's value.
std::optional<ContextMismatch> contextMismatch(const config::Config& file, const CalibrationSpec& spec, const config::Config& run);
// The settings of a run of `spec`'s exercise with `overrides` (the exercise's .cfg under them),
// every process's, merged.
config::Config runSettingsOf(const CalibrationSpec& spec, const std::vector<std::pair<std::string, std::string>>& overrides);

}  // namespace aula::grade
