#include "aula/grade/grade_worlds.hpp"

#include <aula/config/paths.hpp>
#include <aula/grade/calibration.hpp>
#include <aula/process/child_process.hpp>
#include <aula/settings/tables.hpp>
#include <aula/version.hpp>
#include <aula/world/world_spec.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>

namespace aula::grade {
namespace fs = std::filesystem;
using config::ConfigError;

namespace {

// The rubric preset the grade's runs use: the teacher's override, else the exercise's default.
std::string rubricPreset(const GradeRequest& request, const settings::Exercise& ex) {
  const std::string key = ex.section + ".Referee.Rubric";
  for (const auto& [k, value] : request.overrides) {
    if (k == key) return value;
  }
  return ex.referee_settings != nullptr && ex.referee_settings->declares(key) ? "default" : "";
}

// What the calibration depends on besides the world: its seeds, the grade's settings, the version.
std::string calibrationKey(const GradeRequest& request, const std::string& world_sha256) {
  std::string text = world_sha256 + "\nseeds";
  for (long long seed : request.calibration_seeds) text += " " + std::to_string(seed);
  auto overrides = request.overrides;
  std::sort(overrides.begin(), overrides.end());
  for (const auto& [key, value] : overrides) text += "\n" + key + "=" + value;
  return world::sha256Hex(text + "\n" + kVersion);
}

// Whether a grade with `overrides` must calibrate the world itself: nullopt when the rubric the
// world has fits the grade's context (duration, noise, speed limits, destination), else why not
// ("" for a world that has none). A world's own calibration file (the teacher's, W.rubric.cfg)
// fits when made with the grade's values; Aula's own worlds carry a rubric made with the shipped
// .cfg, which fits when the grade changes no context key but the destination.
std::optional<std::string> unfitCalibration(const CalibrationSpec& spec, const std::string& world_path,
                                            const std::string& shipped, const std::vector<std::pair<std::string, std::string>>& overrides) {
  const std::string own = calibrationPathOf(world_path);
  const bool has_own = fs::exists(own);
  if (!has_own && world_path.rfind(shipped, 0) != 0) return std::string();
  // A file that records nothing stands for the shipped rubric (contextMismatch: the shipped values).
  const config::Config made = has_own ? config::Config::fromFile(own) : config::Config();
  const auto mismatch = contextMismatch(made, spec, runSettingsOf(spec, overrides));
  if (!mismatch) return std::nullopt;
  return (has_own ? fs::path(own).filename().string() + " was calibrated" : std::string("Aula's rubric for it was made")) +
         " for " + mismatch->key + " = " + mismatch->made + ", and this grade's is " + mismatch->now;
}

// The grade's settings for one graded world: its own, and the world's destination.
std::vector<std::pair<std::string, std::string>> overridesFor(const GradeRequest& request, const GradedWorld& graded) {
  auto overrides = request.overrides;
  if (!graded.destination.empty()) {
    const auto equals = graded.destination.find('=');
    overrides.emplace_back(graded.destination.substr(0, equals), graded.destination.substr(equals + 1));
  }
  return overrides;
}

// Whether the grade calibrates `graded` itself, and why (as unfitCalibration says); nullopt when
// the world's rubric is used as it is (or the grade calibrates nothing).
std::optional<std::string> gradeCalibrates(const GradeRequest& request, const GradedWorld& graded) {
  const settings::Exercise* ex = settings::exerciseNamed(request.exercise);
  const auto spec = calibrationSpecOf(request.exercise);
  if (request.calibration_seeds.empty() || ex == nullptr || !spec) return std::nullopt;
  if (rubricPreset(request, *ex) != "default") return std::nullopt;  // fixed, original: no world's scale
  const std::string shipped = fs::path(config::dataDir() + "/worlds").lexically_normal().string() + "/";
  return unfitCalibration(*spec, graded.path, shipped, overridesFor(request, graded));
}

void calibrateWorlds(GradeRequest& request, const std::string& bin_dir) {
  for (const GradedWorld& graded : gradedWorlds(request)) {
    const std::string& world_path = graded.path;
    const auto unfit = gradeCalibrates(request, graded);
    if (!unfit) continue;  // the world's own calibration (applied by aula run), or Aula's rubric made for it
    if (!unfit->empty()) std::cout << fs::path(world_path).filename().string() << ": " << *unfit << ": calibrating for this grade\n";
    const auto overrides = overridesFor(request, graded);
    GradeRequest keyed = request;
    keyed.overrides = overrides;
    const std::string name = fs::path(graded.name).stem().string() + "-" + calibrationKey(keyed, graded.sha256).substr(0, 12);
    const fs::path file = fs::path(request.out_dir) / "calibrations" / (name + ".rubric.cfg");
    if (!fs::exists(file)) {
      std::cout << "calibrating " << world_path << " (" << request.calibration_seeds.size() << " seeds)\n" << std::flush;
      CalibrationRequest calibration;
      calibration.exercise = request.exercise;
      calibration.world = world_path;
      calibration.seeds = request.calibration_seeds;
      calibration.jobs = request.jobs;
      calibration.out_dir = (fs::path(request.out_dir) / "calibrations" / name).string();
      calibration.overrides = overrides;
      const std::string command = "aula grade " + request.exercise + " (calibrating " + fs::path(world_path).filename().string() + ")";
      config::writeFileAtomically(file.string(), calibrationText(calibrate(calibration, bin_dir), command), "calibration");
    }
    request.calibrations[graded.key] = file.string();
  }
}

// Every world as `aula run` will take it with the grade's settings (`aula config` resolves exactly
// what `aula run` does): a world or setting of the teacher's that cannot run (a malformed world,
// no robot, a destination inside a building) stops the grade here, before any student's run.
void checkWorlds(const GradeRequest& request, const std::string& bin_dir) {
  const std::string log = (fs::path(request.out_dir) / "world-check.log").string();
  for (const std::string& world : request.worlds) {  // each readable first (gradedWorlds reads them)
    try {
      world::loadWorld(world);
    } catch (const world::WorldError& e) {
      throw ConfigError("aula grade: no run can start on " + world + " (no student's run started): " + e.what());
    }
  }
  for (const GradedWorld& graded : gradedWorlds(request)) {
    const std::string& world = graded.path;
    std::vector<std::string> argv = {bin_dir + "/aula", "config", request.exercise, "--world=" + world};
    for (const auto& [key, value] : overridesFor(request, graded)) argv.push_back("--" + key + "=" + value);
    // A world the grade calibrates for itself: its calibration file (made for other settings) is checked then, not here.
    if (gradeCalibrates(request, graded)) {
      argv.push_back("--" + settings::requireExercise(request.exercise).section + ".Referee.Rubric=fixed");
    }
    process::ChildProcess child(argv, log, log);
    const auto code = child.wait(std::chrono::seconds(120));
    if (code == 0) continue;
    std::ifstream in(log);
    std::string said;
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("aula: ", 0) == 0) said += (said.empty() ? "" : "; ") + line.substr(6);
    }
    throw ConfigError("aula grade: no run can start on " + world + (graded.destination.empty() ? "" : " with " + graded.destination) +
                      " (no student's run started): " +
                      (said.empty() ? "aula config exited with " + (code ? std::to_string(*code) : std::string("no code")) : said));
  }
  fs::remove(log);
}

}  // namespace

void prepareWorlds(GradeRequest& request, const std::string& bin_dir) {
  for (const WorldsToGenerate& what : request.generate) {
    try {
      const auto worlds = generateWorlds(what, request.out_dir, "python3", bin_dir + "/aula-mapgen");
      request.worlds.insert(request.worlds.end(), worlds.begin(), worlds.end());
    } catch (const std::runtime_error& e) {
      throw ConfigError(std::string("aula grade --worlds=generate:") + what.kind + ": " + e.what());
    }
  }
  request.generate.clear();
  checkWorlds(request, bin_dir);
  calibrateWorlds(request, bin_dir);
}

}  // namespace aula::grade
