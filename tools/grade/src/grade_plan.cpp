#include "aula/grade/grade_plan.hpp"

#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>
#include <aula/settings/tables.hpp>
#include <aula/world/world_spec.hpp>

#include <algorithm>
#include <filesystem>
#include <random>

namespace aula::grade {
namespace fs = std::filesystem;

std::vector<GradedWorld> gradedWorlds(const GradeRequest& request) {
  std::vector<GradedWorld> worlds;
  const settings::Exercise* ex = settings::exerciseNamed(request.exercise);
  const std::string destination_key = ex != nullptr ? ex->section + ".Destination" : "";
  const bool destination_given = std::any_of(request.overrides.begin(), request.overrides.end(),
                                             [&](const auto& setting) { return setting.first == destination_key; });
  for (const std::string& path : request.worlds) {
    const world::WorldSpec spec = world::loadWorld(path);
    const bool declares = ex != nullptr && ex->component_settings->declares(destination_key) && !destination_given;
    if (!declares || spec.destinations.empty()) {
      worlds.push_back({path, fs::path(path).filename().string(), spec.sha256, "", path});
      continue;
    }
    for (const world::Destination& d : spec.destinations) {  // graded over each, as a world of its own
      const fs::path file(path);
      worlds.push_back({path, file.stem().string() + "-" + d.name + file.extension().string(), spec.sha256,
                        destination_key + "=" + world::settingValue(d), path + "#" + d.name});
    }
  }
  for (GradedWorld& w : worlds) {  // two different worlds of one file name: named apart by their hash
    const auto shared = std::count_if(worlds.begin(), worlds.end(), [&](const GradedWorld& other) {
      return fs::path(other.path).filename() == fs::path(w.path).filename() && other.sha256 != w.sha256;
    });
    const fs::path file(w.name);
    if (shared > 0) w.name = file.stem().string() + "-" + w.sha256.substr(0, 8) + file.extension().string();
  }
  return worlds;
}

std::vector<Submission> builtInAlgorithms(const std::string& exercise) {
  std::vector<Submission> builtins;
  const settings::Exercise* ex = settings::exerciseNamed(exercise);
  if (ex == nullptr) return builtins;
  const config::SettingSpec* algorithm = ex->component_settings->find(ex->section + ".Algorithm");
  if (algorithm == nullptr) return builtins;
  for (const std::string& name : algorithm->choices) {
    if (name == "student") continue;  // the template everyone starts from: never a likeness
    Submission s;
    s.student = "reference '" + name + "'";
    s.language = "built-in";
    s.plugin = name;  // aula run --algorithm=NAME
    s.known = true;
    s.dir_name = "reference-" + name;
    // Its sources, installed for similarity to compare a class with by code (references/ in the
    // data folder, a copy of what its plugin is built from); "" when this install has none.
    try {
      const std::string sources = config::dataPath("references/" + exercise + "/" + name);
      if (fs::is_directory(sources)) s.folder = sources;
    } catch (const config::ConfigError&) {  // no data folder (a unit test's program): by behaviour alone
    }
    builtins.push_back(s);
  }
  return builtins;
}

void markKnown(std::vector<Submission>& subs) {
  for (Submission& s : subs) {
    s.dir_name = "known-" + s.student;
    s.student = "known '" + s.student + "'";
    s.known = true;
  }
}

Manifest planRuns(const GradeRequest& request, const std::vector<Submission>& submissions, const std::string& bin_dir) {
  Manifest m;
  m.exercise = request.exercise;
  m.out_dir = request.out_dir;
  if (request.similarity) {  // for a later `aula grade --collect` (after Slurm, after a full disk)
    m.submissions = request.submissions;
    m.known = request.known;
    m.similarity_rules = request.similarity_rules;
  }
  // Each run on its own port, so runs at once never hear each other (a group alone is not
  // enough: engineering.md). A random base keeps two batches on one machine apart too.
  std::random_device random;
  const std::vector<GradedWorld> worlds = gradedWorlds(request);
  int index = 0;
  for (const Submission& s : submissions) {
    for (const GradedWorld& world : worlds) {
      const std::string& world_path = world.path;
      for (long long seed : request.seeds) {
        PlannedRun r;
        r.index = index;
        r.student = s.student;
        r.world_name = world.name;
        r.world_sha256 = world.sha256;
        r.seed = seed;
        r.plugin = s.plugin;
        r.plugin_sha256 = s.plugin_sha256;
        r.compile_error = s.compile_error;
        r.build_machine = s.build_machine;
        r.language = s.language;
        r.wall_limit_s = request.wall_limit_s;
        const fs::path stem = fs::path(request.out_dir) / (s.known ? "known" : "runs") / (s.known ? s.dir_name : s.student) /
                              (fs::path(world.name).stem().string() + "-seed" + std::to_string(seed));
        r.result_path = stem.string() + ".json";
        r.report_path = stem.string() + ".report.json";
        r.log_path = stem.string() + ".log";
        if (s.compile_error.empty()) {
          // --sandbox: the student's code in bubblewrap (docs/grading.md, "What a student's code can do").
          r.argv = {bin_dir + "/aula", "run", request.exercise, "--headless", "--sandbox", "--algorithm=" + s.plugin,
                    "--world=" + world_path, "--seed=" + std::to_string(seed), "--report=" + r.report_path,
                    "--picture=" + stem.string() + ".png", "--trace=" + stem.string() + ".trace.json",
                    // Port 0: the launcher takes one the OS hands out, where and when the run starts.
                    "--lcm-url=udpm://239.255.76.67:0?ttl=0"};
          if (request.record) r.argv.push_back("--record=" + stem.string() + ".lcmlog");
          for (const auto& [key, value] : request.overrides) r.settings.push_back("--" + key + "=" + value);
          if (!world.destination.empty()) r.settings.push_back("--" + world.destination);
          const auto calibration = request.calibrations.find(world.key);
          if (calibration != request.calibrations.end()) r.settings.push_back("--calibration=" + calibration->second);
          r.argv.insert(r.argv.end(), r.settings.begin(), r.settings.end());
        }
        m.runs.push_back(r);
        ++index;
      }
    }
  }
  return m;
}

}  // namespace aula::grade
