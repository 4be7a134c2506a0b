#include "aula/grade/submission_build.hpp"

#include <aula/process/machine_reason.hpp>

#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>
#include <aula/grade/grade_plan.hpp>
#include <aula/grade/python_check.hpp>
#include <aula/process/child_process.hpp>
#include <aula/world/world_spec.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <unistd.h>

namespace aula::grade {
namespace fs = std::filesystem;
using config::ConfigError;

namespace {

// Where the build sees its project (the grade's OUT/build/<student>, read-only) and its build
// folder (writable): fixed paths, so that neither the student's name nor the teacher's folders
// reach cmake or the compiler.
constexpr const char* kProjectInside = "/aula/project";

}  // namespace

sandbox::Confinement buildConfinement(const AulaSdk& sdk, const std::string& project) {
  sandbox::Confinement c;
  c.limits = buildLimits();
  c.read_only = sdk.files;
  c.read_only.insert(c.read_only.end(), sdk.include_dirs.begin(), sdk.include_dirs.end());
  // Aula's runtime is no part of a build: where a system folder holds it (installed under /usr),
  // an empty folder in its place (the built-in algorithms' plugins are there).
  if (sdk.lib_dir.rfind("/usr/", 0) == 0) c.hidden.push_back(sdk.lib_dir);
  const std::string inside = kProjectInside;
  c.read_only_at = {{project, inside}};
  c.writable_at = {{(fs::path(project) / "build").string(), inside + "/build"}};
  c.own_network = true;
  c.working_dir = inside;
  return c;
}

std::vector<std::string> buildCommand(const std::string& project, bool boxed) {
  const std::string at = boxed ? kProjectInside : project;
  // The paths are arguments of the shell's, never part of its line.
  return {"sh", "-c", "cmake -S \"$0\" -B \"$1\" && cmake --build \"$1\"", at, at + "/build"};
}

namespace {

// The compiler's first error lines, for the student's row, with the files named as in the
// student's folder ("MyAlgorithm.cpp:2:15: error: ..."): `sources` is where the build saw them.
std::string firstErrors(const std::string& log_path, const std::string& sources) {
  std::ifstream in(log_path);
  std::string line, errors;
  int kept = 0;
  while (std::getline(in, line) && kept < 3) {
    if (line.find("error") == std::string::npos) continue;
    for (size_t at = line.find(sources + "/"); at != std::string::npos; at = line.find(sources + "/")) {
      line.erase(at, sources.size() + 1);
    }
    errors += (errors.empty() ? "" : " | ") + line.substr(0, 300);
    ++kept;
  }
  return errors.empty() ? "see " + log_path : errors;
}

// Says at the end of compile.log what of the folder was not used.
void writeUnused(const std::string& log_path, const std::vector<std::string>& unused) {
  if (unused.empty()) return;
  std::ofstream log(log_path, std::ios::app);
  log << "aula grade: not used (only the folder's own C++ and Python sources are):";
  for (const std::string& name : unused) log << " " << name;
  log << "\n";
}

bool isPythonSubmission(const std::string& folder) {
  return !fs::exists(fs::path(folder) / "MyAlgorithm.cpp") && fs::is_regular_file(fs::path(folder) / "MyAlgorithm.py");
}

// A Python submission (MyAlgorithm.py, no MyAlgorithm.cpp): its sources copied into `project`,
// the copy of MyAlgorithm.py to run.
void preparePython(Submission& s, const SubmissionFiles& files, const fs::path& project) {
  s.language = "Python";
  const std::string copied = copySources(s.folder, files, project.string());
  if (!copied.empty()) {
    s.compile_error = copied;
    return;
  }
  // Every way of not running is the same 0 with its reason, as a C++ compile error is.
  const std::string not_runnable = pythonNotRunnable((project / "MyAlgorithm.py").string(), (project / "check.log").string());
  if (!not_runnable.empty()) {
    s.compile_error = not_runnable;
    return;
  }
  s.plugin = (project / "MyAlgorithm.py").string();
  s.plugin_sha256 = world::sha256OfFile(s.plugin);
}

// One build under way.
struct Compiling {
  size_t index;
  std::string log;
  std::unique_ptr<process::ChildProcess> child;
  std::chrono::steady_clock::time_point started;
  std::vector<std::string> unused;  // what of the folder was not used (said in the log)
};

// Starts the build of `s`, whose checked sources are `files`, in `project`.
Compiling startBuild(size_t index, Submission& s, const SubmissionFiles& files, const GradeRequest& request,
                     const AulaSdk& sdk, const fs::path& project) {
  const std::string log = (project / "compile.log").string();
  const std::string copied = copySources(s.folder, files, (project / "src").string());
  if (!copied.empty()) {
    s.compile_error = copied;
    return {index, log, nullptr, {}, {}};
  }
  fs::create_directories(project / "build");
  writeBuildProject(project.string(), request.exercise, sdk.config_dir);
  s.plugin = (project / "build" / "libmy_algorithm.so").string();
  std::vector<std::string> command = buildCommand(project.string(), request.build_sandbox);
  std::vector<int> passed;
  if (request.build_sandbox) {
    passed.push_back(sandbox::seccompProgram());
    command = sandbox::wrap(command, process::ChildProcess::passedFd(0), buildConfinement(sdk, project.string()));
  }
  Compiling c{index, log, nullptr, std::chrono::steady_clock::now(), files.unused};
  try {
    c.child = std::make_unique<process::ChildProcess>(command, log, log, passed);
  } catch (const std::runtime_error& e) {
    s.compile_error = std::string("the build could not start: ") + e.what();
    s.plugin.clear();
  }
  for (const int fd : passed) ::close(fd);
  return c;
}

// The build of `s` ended with `code` (nullopt: stopped at the wall-clock backstop).
void finishBuild(Submission& s, const Compiling& c, std::optional<int> code, bool boxed) {
  writeUnused(c.log, c.unused);
  if (!code) {
    s.compile_error = process::machineReason("the build ran past " + std::to_string(kBuildWallBackstop.count()) +
                                             " s of wall time (the same command builds it again)");
    s.build_machine = true;
    s.plugin.clear();
  } else if (*code != 0 || !fs::is_regular_file(s.plugin)) {
    const std::string sources = boxed ? std::string(kProjectInside) + "/src" : (fs::path(c.log).parent_path() / "src").string();
    s.compile_error = "did not compile: " + firstErrors(c.log, sources);
    s.plugin.clear();
  } else {
    s.plugin_sha256 = world::sha256OfFile(s.plugin);
  }
}

// Whether `s` is a C++ build to start; when not, it is settled here: refused (its row says why,
// mark 0), or a Python submission prepared to run. `files`: its checked sources.
bool needsBuild(Submission& s, const GradeRequest& request, const fs::path& project, SubmissionFiles& files) {
  // A hand-in is bounded before anything of it is read or copied (hand_in.hpp).
  const auto refused_hand_in = request.refused_hand_ins.find(s.folder);
  std::string bounded = refused_hand_in != request.refused_hand_ins.end() ? refused_hand_in->second : "";
  if (bounded.empty()) bounded = checkHandIn({{s.folder, ""}}, request.hand_in_limits);
  if (!bounded.empty()) {
    s.compile_error = bounded;
    s.language = "";
    return false;
  }
  files = submissionFiles(s.folder);
  if (!files.refused.empty()) {  // a row, mark 0, with the reason; nothing of it is built
    s.compile_error = files.refused;
    s.language = isPythonSubmission(s.folder) ? "Python" : "C++";
    return false;
  }
  if (fs::exists(fs::path(s.folder) / "MyAlgorithm.cpp") && fs::exists(fs::path(s.folder) / "MyAlgorithm.py")) {
    // Which one the student meant is theirs to say: the grade never picks one silently.
    s.compile_error = "both MyAlgorithm.cpp and MyAlgorithm.py handed in: which one to grade is the student's to say";
    s.language = "";
    return false;
  }
  if (isPythonSubmission(s.folder)) {  // nothing to compile
    preparePython(s, files, project);
    return false;
  }
  if (!fs::is_regular_file(fs::path(s.folder) / "MyAlgorithm.cpp")) {  // nothing to grade: a row, mark 0
    // Never the teacher's folder: this text goes to the student's page and the LMS.
    s.compile_error = fs::is_directory(s.folder) && fs::is_empty(s.folder) ? "nothing handed in" : "no MyAlgorithm.py or MyAlgorithm.cpp handed in";
    s.language = "";
    return false;
  }
  return true;
}

// Finishes the builds of `running` that have ended, or run past the backstop.
void reapBuilds(std::vector<Compiling>& running, std::vector<Submission>& out, bool boxed) {
  for (auto it = running.begin(); it != running.end();) {
    std::optional<int> code = it->child->poll();
    const bool overdue = !code && std::chrono::steady_clock::now() - it->started > kBuildWallBackstop;
    if (!code && !overdue) {
      ++it;
      continue;
    }
    if (overdue) it->child->stop(std::chrono::milliseconds(500));
    finishBuild(out[it->index], *it, code, boxed);
    it = running.erase(it);
  }
}

}  // namespace

std::vector<Submission> compileSubmissions(const GradeRequest& request, const std::string& aula_prefix) {
  std::vector<Submission> out;
  for (const std::string& folder : request.submissions) {
    Submission s;
    s.folder = folder;
    s.student = fs::path(folder).filename().string();
    out.push_back(s);
  }
  std::optional<AulaSdk> sdk;
  std::vector<Compiling> running;
  size_t next = 0;
  while (next < out.size() || !running.empty()) {
    while (next < out.size() && static_cast<int>(running.size()) < request.jobs) {
      Submission& s = out[next];
      const fs::path project = fs::path(request.out_dir) / "build" / s.student;
      const size_t index = next++;
      SubmissionFiles files;
      if (!needsBuild(s, request, project, files)) continue;
      if (!sdk && request.build_sandbox && sandbox::bubblewrapPath().empty()) {
        throw ConfigError("aula grade: a C++ submission is built in a sandbox, which needs bubblewrap (/usr/bin/bwrap): "
                          "apt install bubblewrap");
      }
      if (!sdk) sdk = findAulaSdk(aula_prefix);
      Compiling c = startBuild(index, s, files, request, *sdk, project);
      if (c.child) running.push_back(std::move(c));
    }
    reapBuilds(running, out, request.build_sandbox);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return out;
}

void dropBuildTrees(const std::string& out_dir) {
  for (const fs::path& builds : {fs::path(out_dir) / "build", fs::path(out_dir) / "known" / "build"}) {
    std::error_code error;
    if (!fs::is_directory(builds, error)) continue;
    for (const auto& project : fs::directory_iterator(builds, error)) {
      const fs::path tree = project.path() / "build";
      // Never through a link: only the grade's own folders are removed.
      if (!project.is_symlink() && fs::is_directory(fs::symlink_status(tree))) fs::remove_all(tree, error);
    }
  }
}

}  // namespace aula::grade
