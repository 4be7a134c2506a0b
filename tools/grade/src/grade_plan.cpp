#include "aula/grade/grade_plan.hpp"

#include <aula/config/paths.hpp>
#include <aula/process/child_process.hpp>
#include <aula/settings/tables.hpp>
#include <aula/world/world_spec.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <thread>

#include <unistd.h>

namespace aula::grade {
namespace fs = std::filesystem;
using config::ConfigError;

namespace {


// The compiler's first error lines, for the student's row, with the files named as in the
// student's folder ("MyAlgorithm.cpp:2:15: error: ...").
std::string firstErrors(const std::string& log_path, const std::string& folder) {
  std::ifstream in(log_path);
  std::string line, errors;
  int kept = 0;
  while (std::getline(in, line) && kept < 3) {
    if (line.find("error") == std::string::npos) continue;
    for (size_t at = line.find(folder + "/"); at != std::string::npos; at = line.find(folder + "/")) {
      line.erase(at, folder.size() + 1);
    }
    errors += (errors.empty() ? "" : " | ") + line;
    ++kept;
  }
  return errors.empty() ? "see " + log_path : errors;
}

std::string writeBuildProject(const Submission& s, const std::string& exercise, const std::string& aula_prefix,
                              const fs::path& project) {
  std::vector<std::string> sources;
  for (const auto& entry : fs::directory_iterator(s.folder)) {
    if (entry.is_regular_file() && entry.path().extension() == ".cpp") sources.push_back(entry.path().string());
  }
  std::sort(sources.begin(), sources.end());
  fs::create_directories(project);
  std::ostringstream cmake;
  cmake << "# " << s.student << "'s submission as a plugin (written by aula grade).\n"
        << "cmake_minimum_required(VERSION 3.16)\n"
        << "project(aula_submission CXX)\n"
        << "find_package(Aula REQUIRED HINTS \"" << aula_prefix << "/lib/cmake/Aula\" \"" << aula_prefix << "\")\n"
        << "aula_add_algorithm(NAME my_algorithm EXERCISE " << exercise << " SOURCES";
  for (const auto& source : sources) cmake << "\n  \"" << source << "\"";
  cmake << ")\n";
  // The same project is left as it is: a resumed grade does not make its plugin look older than
  // its project (aula run refuses a stale build).
  const fs::path path = project / "CMakeLists.txt";
  std::ifstream before(path);
  if (std::string((std::istreambuf_iterator<char>(before)), std::istreambuf_iterator<char>()) != cmake.str()) {
    std::ofstream out(path);
    out << cmake.str();
    if (!out.flush()) throw ConfigError("aula grade: cannot write " + path.string());
  }
  return (project / "build" / "libmy_algorithm.so").string();
}

}  // namespace

namespace {

// A Python submission (MyAlgorithm.py, no MyAlgorithm.cpp): its .py files copied into
// `project`, the copy of MyAlgorithm.py to run; a folder that cannot be copied is its failure.
void preparePython(Submission& s, const fs::path& project) {
  s.language = "Python";
  std::error_code error;
  fs::remove_all(project, error);
  fs::create_directories(project, error);
  for (const auto& entry : fs::directory_iterator(s.folder, error)) {
    if (error) break;
    if (entry.path().extension() != ".py" || !entry.is_regular_file()) continue;
    fs::copy_file(entry.path(), project / entry.path().filename(), error);
    if (error) break;
  }
  if (error) {
    s.compile_error = "cannot copy " + s.folder + " into " + project.string() + ": " + error.message();
    return;
  }
  s.plugin = (project / "MyAlgorithm.py").string();
  s.plugin_sha256 = world::sha256OfFile(s.plugin);
}

bool isPythonSubmission(const std::string& folder) {
  return !fs::exists(fs::path(folder) / "MyAlgorithm.cpp") && fs::is_regular_file(fs::path(folder) / "MyAlgorithm.py");
}

}  // namespace

std::vector<Submission> compileSubmissions(const GradeRequest& request, const std::string& aula_prefix) {
  struct Compiling {
    size_t index;
    std::string log;
    std::unique_ptr<process::ChildProcess> child;
  };
  std::vector<Submission> out;
  for (const std::string& folder : request.submissions) {
    Submission s;
    s.folder = folder;
    s.student = fs::path(folder).filename().string();
    out.push_back(s);
  }
  std::vector<Compiling> running;
  size_t next = 0;
  while (next < out.size() || !running.empty()) {
    while (next < out.size() && static_cast<int>(running.size()) < request.jobs) {
      Submission& s = out[next];
      const fs::path project = fs::path(request.out_dir) / "build" / s.student;
      if (fs::exists(fs::path(s.folder) / "MyAlgorithm.cpp") && fs::exists(fs::path(s.folder) / "MyAlgorithm.py")) {
        // Which one the student meant is theirs to say: the grade never picks one silently.
        s.compile_error = "both MyAlgorithm.cpp and MyAlgorithm.py in " + s.folder + ": keep only the one to grade";
        s.language = "";
        ++next;
        continue;
      }
      if (isPythonSubmission(s.folder)) {  // nothing to compile
        preparePython(s, project);
        ++next;
        continue;
      }
      if (!fs::is_regular_file(fs::path(s.folder) / "MyAlgorithm.cpp")) {  // nothing to grade: a row, mark 0
        s.compile_error = "no MyAlgorithm.py or MyAlgorithm.cpp in " + s.folder;
        s.language = "";
        ++next;
        continue;
      }
      s.plugin = writeBuildProject(s, request.exercise, aula_prefix, project);
      const std::string build = (project / "build").string();
      const std::string log = (project / "compile.log").string();
      running.push_back({next, log,
                         std::make_unique<process::ChildProcess>(
                             std::vector<std::string>{"sh", "-c", "cmake -S \"$0\" -B \"$1\" && cmake --build \"$1\"",
                                                      project.string(), build},
                             log, log)});
      ++next;
    }
    for (auto it = running.begin(); it != running.end();) {
      const auto code = it->child->poll();
      if (!code) {
        ++it;
        continue;
      }
      Submission& s = out[it->index];
      if (*code != 0 || !fs::is_regular_file(s.plugin)) {
        s.compile_error = "did not compile: " + firstErrors(it->log, s.folder);
        s.plugin.clear();
      } else {
        s.plugin_sha256 = world::sha256OfFile(s.plugin);
      }
      it = running.erase(it);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return out;
}

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

Manifest planRuns(const GradeRequest& request, const std::vector<Submission>& submissions, const std::string& bin_dir) {
  Manifest m;
  m.exercise = request.exercise;
  m.out_dir = request.out_dir;
  if (request.similarity) {  // for a later `aula grade --collect` (after Slurm, after a full disk)
    m.submissions = request.submissions;
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
        r.language = s.language;
        r.wall_limit_s = request.wall_limit_s;
        const fs::path stem = fs::path(request.out_dir) / "runs" / s.student /
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
