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

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

void writeBuildProject(const std::string& project, const std::string& exercise, const std::string& aula_config_dir) {
  // The teacher's path, in a bracket argument (nothing in it is evaluated); the exercise is one of
  // Aula's names. Nothing else varies.
  if (aula_config_dir.find("]==]") != std::string::npos || exercise.find_first_not_of("abcdefghijklmnopqrstuvwxyz") != std::string::npos) {
    throw ConfigError("aula grade: cannot write a build project for " + aula_config_dir);
  }
  std::ostringstream cmake;
  cmake << "# A submission as a plugin (written by aula grade): every C++ source of the checked copy in src/.\n"
        << "cmake_minimum_required(VERSION 3.16)\n"
        << "project(aula_submission CXX)\n"
        << "find_package(Aula REQUIRED CONFIG PATHS [==[" << aula_config_dir << "]==] NO_DEFAULT_PATH)\n"
        << "file(GLOB sources LIST_DIRECTORIES false ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp\n"
        << "     ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cc ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cxx)\n"
        << "aula_add_algorithm(NAME my_algorithm EXERCISE " << exercise << " SOURCES ${sources})\n";
  // The same project is left as it is: a resumed grade does not make its plugin look older than
  // its project (aula run refuses a stale build).
  const fs::path path = fs::path(project) / "CMakeLists.txt";
  if (readAll(path) == cmake.str()) return;
  std::ofstream out(path);
  out << cmake.str();
  if (!out.flush()) throw ConfigError("aula grade: cannot write " + path.string());
}

AulaSdk findAulaSdk(const std::string& aula_prefix) {
  AulaSdk sdk;
  for (const fs::path& candidate : {fs::path(aula_prefix) / "lib" / "cmake" / "Aula", fs::path(aula_prefix)}) {
    if (fs::is_regular_file(candidate / "AulaConfig.cmake")) {
      sdk.config_dir = fs::absolute(candidate).lexically_normal().string();
      break;
    }
  }
  if (sdk.config_dir.empty()) {
    throw ConfigError("aula grade: no Aula package (AulaConfig.cmake) in " + aula_prefix + "/lib/cmake/Aula or " +
                      aula_prefix + ": is Aula installed whole?");
  }
  const fs::path import_prefix = fs::path(sdk.config_dir).parent_path().parent_path().parent_path();
  std::set<std::string> includes;
  for (const auto& entry : fs::directory_iterator(sdk.config_dir)) {
    const std::string name = entry.path().filename().string();
    const bool package = (name.rfind("Aula", 0) == 0 && entry.path().extension() == ".cmake") || entry.path().extension() == ".in";
    if (!entry.is_regular_file() || !package) continue;
    sdk.files.push_back(entry.path().string());
    // The include folders its targets name ("${_IMPORT_PREFIX}/include" when installed).
    std::istringstream text(readAll(entry.path()));
    for (std::string line; std::getline(text, line);) {
      const auto key = line.find("INTERFACE_INCLUDE_DIRECTORIES \"");
      if (key == std::string::npos) continue;
      const auto open = line.find('"', key), close = line.rfind('"');
      std::stringstream list(line.substr(open + 1, close - open - 1));
      for (std::string dir; std::getline(list, dir, ';');) {
        const std::string token = "${_IMPORT_PREFIX}";
        if (dir.rfind(token, 0) == 0) dir = import_prefix.string() + dir.substr(token.size());
        if (fs::is_directory(dir)) includes.insert(fs::path(dir).lexically_normal().string());
      }
    }
  }
  std::sort(sdk.files.begin(), sdk.files.end());
  sdk.include_dirs.assign(includes.begin(), includes.end());
  sdk.lib_dir = config::libDir();
  return sdk;
}

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
      // A hand-in is bounded before anything of it is read or copied (hand_in.hpp).
      const auto refused_hand_in = request.refused_hand_ins.find(s.folder);
      std::string bounded = refused_hand_in != request.refused_hand_ins.end() ? refused_hand_in->second : "";
      if (bounded.empty()) bounded = checkHandIn({{s.folder, ""}}, request.hand_in_limits);
      if (!bounded.empty()) {
        s.compile_error = bounded;
        s.language = "";
        continue;
      }
      const SubmissionFiles files = submissionFiles(s.folder);
      if (!files.refused.empty()) {  // a row, mark 0, with the reason; nothing of it is built
        s.compile_error = files.refused;
        s.language = isPythonSubmission(s.folder) ? "Python" : "C++";
        continue;
      }
      if (fs::exists(fs::path(s.folder) / "MyAlgorithm.cpp") && fs::exists(fs::path(s.folder) / "MyAlgorithm.py")) {
        // Which one the student meant is theirs to say: the grade never picks one silently.
        s.compile_error = "both MyAlgorithm.cpp and MyAlgorithm.py handed in: which one to grade is the student's to say";
        s.language = "";
        continue;
      }
      if (isPythonSubmission(s.folder)) {  // nothing to compile
        preparePython(s, files, project);
        continue;
      }
      if (!fs::is_regular_file(fs::path(s.folder) / "MyAlgorithm.cpp")) {  // nothing to grade: a row, mark 0
        // Never the teacher's folder: this text goes to the student's page and the LMS.
        s.compile_error = fs::is_directory(s.folder) && fs::is_empty(s.folder) ? "nothing handed in" : "no MyAlgorithm.py or MyAlgorithm.cpp handed in";
        s.language = "";
        continue;
      }
      if (!sdk && request.build_sandbox && sandbox::bubblewrapPath().empty()) {
        throw ConfigError("aula grade: a C++ submission is built in a sandbox, which needs bubblewrap (/usr/bin/bwrap): "
                          "apt install bubblewrap");
      }
      if (!sdk) sdk = findAulaSdk(aula_prefix);
      Compiling c = startBuild(index, s, files, request, *sdk, project);
      if (c.child) running.push_back(std::move(c));
    }
    for (auto it = running.begin(); it != running.end();) {
      std::optional<int> code = it->child->poll();
      const bool overdue = !code && std::chrono::steady_clock::now() - it->started > kBuildWallBackstop;
      if (!code && !overdue) {
        ++it;
        continue;
      }
      if (overdue) it->child->stop(std::chrono::milliseconds(500));
      finishBuild(out[it->index], *it, code, request.build_sandbox);
      it = running.erase(it);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return out;
}

}  // namespace aula::grade
