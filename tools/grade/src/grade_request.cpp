#include "aula/grade/grade_plan.hpp"

#include <aula/config/paths.hpp>
#include <aula/grade/lms_export.hpp>
#include <aula/grade/zip_archive.hpp>
#include <aula/settings/tables.hpp>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>
#include <thread>

// What a teacher asks of `aula grade`, checked: the exercise, the submissions, the worlds, the seeds.
namespace aula::grade {
namespace fs = std::filesystem;
using config::ConfigError;

namespace {

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

long long parseInteger(const std::string& text, const std::string& what) {
  size_t used = 0;
  long long value = 0;
  try {
    value = std::stoll(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) throw ConfigError(what + ": '" + text + "' is not a whole number");
  return value;
}

// The exercise's own world: its .cfg's (or the declared default) <Section>.World.
std::string defaultWorld(const settings::Exercise& ex) {
  const config::Config cfg = componentSettings(ex);
  const std::string key = ex.section + ".World";
  return config::resolveWorldPath(cfg.getString(key), cfg.origin(key) + ": " + key);
}

}  // namespace

config::Config componentSettings(const settings::Exercise& ex) {
  const config::Config file = config::Config::fromFile(config::dataPath(ex.config_file));
  std::vector<const config::SettingsTable*> siblings;
  for (const auto* t : ex.tables()) {
    if (t != ex.component_settings.get()) siblings.push_back(t);
  }
  return ex.component_settings->resolve(file, siblings);
}

std::vector<long long> parseSeeds(const std::string& text, const std::string& option) {
  std::vector<long long> seeds;
  const std::string named = option + "=" + text;
  for (const std::string& item : splitList(text)) {
    const auto dash = item.find('-', 1);
    long long from = 0, to = 0;
    if (dash == std::string::npos) {
      from = to = parseInteger(item, option);
    } else {
      from = parseInteger(item.substr(0, dash), option);
      to = parseInteger(item.substr(dash + 1), option);
    }
    // The seeds a run takes (aula run --seed): never negative, and far from the end of the range.
    if (from < 0 || to < 0) throw ConfigError(named + ": '" + item + "': a seed is 0 or more");
    if (from > kMaxSeed || to > kMaxSeed) {
      throw ConfigError(named + ": '" + item + "': a seed is at most " + std::to_string(kMaxSeed));
    }
    if (from > to) throw ConfigError(named + ": '" + item + "' counts down (write " + std::to_string(to) + "-" + std::to_string(from) + ")");
    if (to - from >= kMaxSeeds) throw ConfigError(named + ": '" + item + "' is more than " + std::to_string(kMaxSeeds) + " seeds");
    for (long long seed = from; seed <= to; ++seed) {
      if (std::find(seeds.begin(), seeds.end(), seed) == seeds.end()) seeds.push_back(seed);
      if (seeds.size() > static_cast<size_t>(kMaxSeeds)) {
        throw ConfigError(named + ": more than " + std::to_string(kMaxSeeds) + " seeds in all");
      }
    }
  }
  if (seeds.empty()) throw ConfigError(named + ": no seed (e.g. " + option + "=1-5 or " + option + "=1,4,9)");
  return seeds;
}

namespace {

// --known=DIR: its folders with a MyAlgorithm.cpp or .py (the teacher's solutions), sorted.
std::vector<std::string> knownFolders(const std::string& given, bool similarity) {
  const fs::path dir = fs::absolute(given).lexically_normal();
  if (!fs::is_directory(dir)) throw ConfigError("aula grade --known=" + given + ": not a folder");
  if (!similarity) throw ConfigError("aula grade --known=" + given + ": compared only with --similarity=on (or auto, for 3 or more)");
  std::vector<std::string> folders;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_directory() && (fs::exists(entry.path() / "MyAlgorithm.cpp") || fs::exists(entry.path() / "MyAlgorithm.py"))) {
      folders.push_back(entry.path().string());
    }
  }
  if (folders.empty()) throw ConfigError("aula grade --known=" + given + ": no folder with MyAlgorithm.cpp or MyAlgorithm.py in it");
  std::sort(folders.begin(), folders.end());
  return folders;
}

}  // namespace

GradeRequest parseRequest(const GradeOptions& options) {
  GradeRequest r;
  r.exercise = options.exercise;
  const settings::Exercise* ex = settings::exerciseNamed(r.exercise);
  if (ex == nullptr || ex->referee_settings == nullptr) {
    throw ConfigError("aula grade: '" + r.exercise + "' is not an exercise with a referee (" + settings::exerciseNames(false) + ")");
  }
  std::set<std::string> students;
  for (const std::string& given : options.submissions) {
    const fs::path folder = fs::absolute(given).lexically_normal();
    const std::string student = (folder.has_filename() ? folder : folder.parent_path()).filename().string();
    // A typo of the teacher's stops the grade; a student's folder without a submission (empty, a
    // link elsewhere) is that student's row ("no MyAlgorithm.py or MyAlgorithm.cpp").
    if (!fs::exists(folder)) throw ConfigError("aula grade: submission " + given + ": not a folder (there is no such path)");
    // An LMS's export comes as its zip too (lms_export.hpp): its students are read when it is unpacked.
    const bool export_zip = fs::is_regular_file(folder) && looksLikeZip(folder.string());
    if (!fs::is_directory(folder) && !export_zip) throw ConfigError("aula grade: submission " + given + ": not a folder nor an LMS's export zip");
    if (!students.insert(student).second) {
      throw ConfigError("aula grade: two submissions are named '" + student + "' (a student is named after the folder)");
    }
    r.submissions.push_back(folder.string());
  }
  const std::vector<std::string> worlds = splitList(options.worlds);
  for (size_t i = 0; i < worlds.size(); ++i) {
    if (isGenerateItem(worlds[i])) {  // "generate:house:5" and, maybe, its "seed=7"
      const bool seeded = i + 1 < worlds.size() && worlds[i + 1].rfind("seed=", 0) == 0;
      r.generate.push_back(parseGenerate(worlds[i], seeded ? worlds[i + 1] : "", r.exercise));
      i += seeded ? 1 : 0;
    } else {
      r.worlds.push_back(config::resolveWorldPath(worlds[i], "--worlds"));
    }
  }
  if (r.worlds.empty() && r.generate.empty()) r.worlds.push_back(defaultWorld(*ex));
  if (options.calibration_seeds != "off" && !options.calibration_seeds.empty()) {
    r.calibration_seeds = parseSeeds(options.calibration_seeds, "--calibration-seeds");
  }
  r.seeds = parseSeeds(options.seeds, "--seeds");
  r.jobs = options.jobs > 0 ? static_cast<int>(options.jobs) : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  r.wall_limit_s = options.wall_limit_s;
  r.engine = options.engine;
  r.out_dir = fs::absolute(options.out_dir).lexically_normal().string();
  r.overrides = options.overrides;
  r.lms = options.lms;
  r.lms_assignment = options.lms_assignment.empty() ? "aula " + r.exercise : options.lms_assignment;
  r.hand_in_limits = options.hand_in_limits;
  r.record = options.record;
  r.keep_builds = options.keep_builds;
  r.build_sandbox = options.build_sandbox;
  // An export is a class: auto is on for it until its students are counted (gradeClass).
  const bool an_export = std::any_of(r.submissions.begin(), r.submissions.end(), [](const std::string& s) {
    return !fs::is_directory(s) || !exportLayout(s).empty();
  });
  r.similarity_auto = options.similarity == "auto";
  r.similarity = options.similarity == "on" || (r.similarity_auto && (r.submissions.size() >= 3 || an_export));
  r.similarity_rules = options.similarity_rules;
  if (!options.known.empty()) r.known = knownFolders(options.known, r.similarity);
  return r;
}

}  // namespace aula::grade
