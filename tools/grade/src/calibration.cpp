#include "aula/grade/calibration.hpp"

#include <aula/config/paths.hpp>
#include <aula/grade/grade_plan.hpp>
#include <aula/grade/grade_runner.hpp>
#include <aula/grade/grades.hpp>
#include <aula/settings/tables.hpp>
#include <aula/version.hpp>
#include <aula/world/world_spec.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace aula::grade {
namespace fs = std::filesystem;
using config::ConfigError;

namespace {

// Six significant digits: enough for a mark's scale, and the same text on every machine.
std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string numbers(const std::vector<double>& values) {
  std::string out;
  for (double v : values) out += (out.empty() ? "" : ", ") + number(v);
  return out;
}

// The nearest-rank percentile of `values` (q in 0..1).
double percentile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<size_t>(std::ceil(q * static_cast<double>(values.size())));
  return values[std::min(values.size() - 1, rank == 0 ? 0 : rank - 1)];
}

// Each seed's measure for one algorithm's runs; a failed run stops the calibration, naming its log.
MeasuredAlgorithm measure(const Manifest& manifest, const std::string& who, const std::string& algorithm,
                          const std::string& field) {
  MeasuredAlgorithm m;
  m.algorithm = algorithm;
  for (const PlannedRun& run : manifest.runs) {
    if (run.student != who) continue;
    std::ifstream in(run.result_path);
    const nlohmann::json result = nlohmann::json::parse(in, nullptr, false);
    const std::string failure = result.is_discarded() ? "no result" : failureOf(result);
    if (!failure.empty() || !result.contains(field) || !result[field].is_number()) {
      throw ConfigError("aula calibrate: the " + algorithm + " run of seed " + std::to_string(run.seed) + " on " +
                        run.world_name + " gave no " + field + (failure.empty() ? "" : " (" + failure + ")") + "; see " +
                        run.log_path);
    }
    m.values.push_back(result[field].get<double>());
  }
  m.median = median(m.values);
  m.p10 = percentile(m.values, 0.1);
  m.p90 = percentile(m.values, 0.9);
  return m;
}

std::vector<std::pair<std::string, std::string>> rubricOf(const CalibrationSpec& spec, const MeasuredAlgorithm& baseline,
                                                          const MeasuredAlgorithm& anchor) {
  // A line through two points, the baseline's median at a 5 and the anchor's at a 10 (vacuum:
  // HalfMarkCoverage, FullMarkCoverage); or one point, the anchor's (TeleTaxi: FullMarkTime).
  if (spec.baseline.empty()) return {{spec.rubric_keys.at(0), number(anchor.median)}};
  return {{spec.rubric_keys.at(0), number(baseline.median)}, {spec.rubric_keys.at(1), number(anchor.median)}};
}

// Two values of one setting are the same: numbers (and lists of them) to within 1e-9, else as text.
bool sameSetting(const config::Config& a, const std::string& a_key, const config::Config& b, const std::string& b_key) {
  try {
    const std::vector<double> x = a.getDoubleList(a_key), y = b.getDoubleList(b_key);
    return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(), [](double p, double q) { return std::abs(p - q) < 1e-9; });
  } catch (const ConfigError&) {
    return a.getString(a_key) == b.getString(b_key);
  }
}

// The context keys' values in the calibration's runs; a world's declared destination is where its
// runs drive when no setting names one (as aula run does).
std::vector<std::pair<std::string, std::string>> contextOf(const CalibrationSpec& spec, const settings::Exercise& ex,
                                                           const world::WorldSpec& world,
                                                           const std::vector<std::pair<std::string, std::string>>& overrides) {
  const config::Config settings = runSettingsOf(spec, overrides);
  std::vector<std::pair<std::string, std::string>> context;
  for (const std::string& key : spec.context_keys) {
    const bool named = std::any_of(overrides.begin(), overrides.end(), [&](const auto& s) { return s.first == key; });
    if (key == ex.section + ".Destination" && !named && !world.destinations.empty()) {
      context.emplace_back(key, world::settingValue(world.destinations.front()));
    } else {
      context.emplace_back(key, settings.getString(key));
    }
  }
  return context;
}

// A run's progress line. A failed run is said as such, never as a result (it stops the
// calibration); an anchor run says whether it succeeded, as soon as it is known.
void sayProgress(const PlannedRun& run, const nlohmann::ordered_json& result, const Progress& p,
                 const CalibrationSpec& spec) {
  const std::string failure = failureOf(result);
  const std::string note = failure.empty() && run.student == "anchor" ? anchorNote(result, spec) : "";
  std::cout << "[" << p.done << "/" << p.total << "] " << run.plugin << " seed " << run.seed << ": "
            << (failure.empty() ? number(result.value("mark", 0.0)) + note : "failed: " + failure) << "\n" << std::flush;
}

}  // namespace

std::optional<CalibrationSpec> calibrationSpecOf(const std::string& exercise) {
  const settings::Exercise* ex = settings::exerciseNamed(exercise);
  if (ex == nullptr || !ex->calibration) return std::nullopt;
  return CalibrationSpec{*ex->calibration, exercise};  // the exercise's own declaration
}

Calibration calibrate(const CalibrationRequest& request, const std::string& bin_dir) {
  const auto spec = calibrationSpecOf(request.exercise);
  const settings::Exercise* ex = settings::exerciseNamed(request.exercise);
  if (!spec || ex == nullptr) {
    throw ConfigError("aula calibrate: the " + request.exercise +
                      " exercise has no world-dependent scale to calibrate");
  }
  Calibration c;
  c.spec = *spec;
  c.world = fs::absolute(request.world).string();
  const world::WorldSpec world = world::loadWorld(c.world);
  c.world_sha256 = world.sha256;
  c.seeds = request.seeds;
  if (spec->baseline.empty() && !request.baseline.empty()) {
    throw ConfigError("aula calibrate --baseline=" + request.baseline + ": the " + request.exercise +
                      " scale has one point, the anchor's (" + spec->measure + ")");
  }
  const std::string baseline = request.baseline.empty() ? spec->baseline : request.baseline;
  const std::string anchor = request.anchor.empty() ? spec->anchor : request.anchor;
  GradeRequest runs;
  runs.exercise = request.exercise;
  runs.worlds = {c.world};
  runs.seeds = request.seeds;
  runs.jobs = request.jobs;
  runs.out_dir = request.out_dir;
  const std::string rubric_key = ex->section + ".Referee.Rubric";
  for (const auto& setting : request.overrides) {
    if (setting.first != rubric_key) runs.overrides.push_back(setting);
  }
  runs.overrides.emplace_back(rubric_key, "fixed");  // an older calibration plays no part
  Submission b, a;
  b.student = "baseline";
  b.plugin = baseline;
  a.student = "anchor";
  a.plugin = anchor;
  std::vector<Submission> algorithms = {a};
  if (!baseline.empty()) algorithms.insert(algorithms.begin(), b);
  const Manifest manifest = planRuns(runs, algorithms, bin_dir);
  runLocal(manifest, request.jobs, [&](const PlannedRun& run, const nlohmann::ordered_json& result, const Progress& p) {
    sayProgress(run, result, p, *spec);
  });
  c.context = contextOf(*spec, *ex, world, request.overrides);
  c.anchor = measure(manifest, "anchor", anchor, spec->measure);
  requireAnchorSucceeded(manifest, *spec, anchor);
  if (baseline.empty()) {
    c.rubric = rubricOf(*spec, c.baseline, c.anchor);
    return c;
  }
  c.baseline = measure(manifest, "baseline", baseline, spec->measure);
  if (!(c.anchor.median > c.baseline.median)) {
    throw ConfigError("aula calibrate: on " + request.world + " the anchor (" + anchor + ", median " + spec->measure + " " +
                      number(c.anchor.median) + ") does not beat the baseline (" + baseline + ", " +
                      number(c.baseline.median) + "): no scale can put one at a 5 and the other at a 10");
  }
  c.rubric = rubricOf(*spec, c.baseline, c.anchor);
  return c;
}

std::string calibrationText(const Calibration& c, const std::string& command) {
  std::ostringstream out;
  out << "# The " << c.spec.exercise << " rubric calibrated for " << fs::path(c.world).filename().string()
      << (c.spec.baseline.empty() ? ": the anchor's median " + c.spec.measure + " is worth a 10.\n"
                                  : ": the baseline's median " + c.spec.measure + " is worth a 5, the anchor's a 10.\n")
      << "# Written by `" << command << "`; aula run and aula grade apply it with the default rubric\n"
      << "# (--" << settings::exerciseNamed(c.spec.exercise)->section
      << ".Referee.Rubric=fixed or =original ignore it). docs/grading.md, \"Calibration\".\n";
  std::string seeds;
  for (long long s : c.seeds) seeds += (seeds.empty() ? "" : ", ") + std::to_string(s);
  out << "Calibration.Exercise = " << c.spec.exercise << "\n"
      << "Calibration.WorldSha256 = " << c.world_sha256 << "\n"
      << "Calibration.AulaVersion = " << kVersion << "\n"
      << "Calibration.Seeds = " << seeds << "\n"
      << "Calibration.Measure = " << c.spec.measure << "\n";
  for (const auto& [key, value] : c.context) out << "Calibration.Setting." << key << " = " << value << "\n";
  for (const auto& [role, m] : {std::pair<std::string, const MeasuredAlgorithm*>{"Baseline", &c.baseline},
                                {"Anchor", &c.anchor}}) {
    if (m->algorithm.empty()) continue;  // a scale of one point has no baseline
    out << "Calibration." << role << " = " << m->algorithm << "\n"
        << "Calibration." << role << "Values = " << numbers(m->values) << "\n"
        << "Calibration." << role << "Median = " << number(m->median) << "\n"
        << "Calibration." << role << "P10P90 = " << number(m->p10) << ", " << number(m->p90) << "\n";
  }
  for (const auto& [key, value] : c.rubric) out << key << " = " << value << "\n";
  return out.str();
}

std::string calibrationPathOf(const std::string& world_path) {
  return (fs::path(world_path).parent_path() / (fs::path(world_path).stem().string() + ".rubric.cfg")).string();
}

config::Config readCalibration(const std::string& exercise, const std::string& world_path, const std::string& world_sha256,
                               const std::string& file_given, const config::Config* run) {
  config::Config rubric;
  const std::string path = file_given.empty() ? calibrationPathOf(world_path) : file_given;
  std::error_code error;
  if (!fs::is_regular_file(path, error)) {
    if (file_given.empty()) return rubric;
    throw ConfigError("--calibration=" + path + ": no such file");
  }
  const config::Config file = config::Config::fromFile(path);
  const auto spec = calibrationSpecOf(exercise);
  const std::string of = file.getString("Calibration.Exercise", "");
  if (!spec || of != exercise) {
    throw ConfigError(path + ": a calibration for " + (of.empty() ? "no exercise" : "the " + of + " exercise") +
                      ", beside a world the " + exercise + " exercise runs on; `aula calibrate " + exercise +
                      " --world=" + world_path + "` writes the right one");
  }
  if (file.getString("Calibration.WorldSha256", "") != world_sha256) {
    throw ConfigError((file.has("Calibration.WorldSha256") ? file.origin("Calibration.WorldSha256") : path) +
                      ": calibrated for another version of " + world_path + " (its files changed since): run `aula calibrate " +
                      exercise + " --world=" + world_path + "` again, or delete the file for the fixed rubric");
  }
  if (run != nullptr) {
    if (const auto mismatch = contextMismatch(file, *spec, *run)) {
      throw ConfigError(mismatch->made_origin + ": calibrated for " + mismatch->key + " = " + mismatch->made + ", and this run's is " +
                        mismatch->now + " (" + mismatch->now_origin + "): `aula calibrate " + exercise + " --world=" + world_path +
                        " --" + mismatch->key + "=" + mismatch->now + " --output=FILE` calibrates it, or --" +
                        settings::exerciseNamed(exercise)->section + ".Referee.Rubric=fixed grades without one");
    }
  }
  for (const std::string& key : file.keys()) {
    if (key.rfind("Calibration.", 0) == 0) continue;
    if (std::find(spec->rubric_keys.begin(), spec->rubric_keys.end(), key) == spec->rubric_keys.end()) {
      throw ConfigError(file.origin(key) + ": '" + key + "' is not a calibrated rubric setting of " + exercise);
    }
    rubric.set(key, file.getString(key), "calibration " + file.origin(key));
  }
  return rubric;
}

config::Config runSettingsOf(const CalibrationSpec& spec, const std::vector<std::pair<std::string, std::string>>& overrides) {
  const settings::Exercise& ex = settings::requireExercise(spec.exercise);
  config::Config given;
  for (const auto& [key, value] : overrides) given.set(key, value, "--" + key);
  return settings::mergedSettings(
      settings::resolveProcesses(ex, config::Config::fromFile(config::dataPath(ex.config_file)), given));
}

std::optional<ContextMismatch> contextMismatch(const config::Config& file, const CalibrationSpec& spec, const config::Config& run) {
  std::optional<config::Config> shipped;  // the shipped .cfg's settings, read when a key is not recorded
  for (const std::string& key : spec.context_keys) {
    if (!run.has(key)) continue;
    const std::string recorded = "Calibration.Setting." + key;
    if (file.has(recorded)) {
      if (sameSetting(file, recorded, run, key)) continue;
      return ContextMismatch{key, file.getString(recorded), file.origin(recorded), run.getString(key), run.origin(key)};
    }
    if (key == settings::requireExercise(spec.exercise).section + ".Destination") continue;  // always recorded
    if (!shipped) shipped = runSettingsOf(spec, {});
    if (sameSetting(*shipped, key, run, key)) continue;
    return ContextMismatch{key, shipped->getString(key),
                           (file.has("Calibration.Exercise") ? file.origin("Calibration.Exercise") : std::string("the calibration")) +
                               " (made before Aula recorded " + key + ": the shipped value)",
                           run.getString(key), run.origin(key)};
  }
  return std::nullopt;
}

}  // namespace aula::grade
