#pragma once
// A submission's files, checked, and its build, boxed (docs/grading.md, "The build is part of the
// exam"). A student's folder is untrusted: its file names are never pasted into a build file or a
// command line, and its C++ is compiled inside the run's kind of sandbox (aula_sandbox).
//
// - The files: only a plain source name (kPlainSourceName) that is a regular file (not a link) is
//   taken, copied into the grade's own folder for that student; a name that ends as a source
//   does but is not plain (a quote, a newline, a space...), a link, or a source larger than
//   kMaxSourceBytes refuses the whole submission with that reason (the student's row, mark 0).
//   Anything else (a scaffolded project's CMakeLists.txt and build/, a README, subfolders) is not
//   used, and compile.log lists it.
// - The build project is fixed text: it globs the copied folder, so no name is in it.
// - The build: cmake and the compiler in bubblewrap as the student's uid-65534 user, seeing the
//   system's /usr, Aula's SDK (its package files and the API's include folders, never lib/aula:
//   no built-in algorithm's plugin), the project (read-only) and a build folder (writable); no
//   network, no classmate, no out folder, no /etc/machine-id or /etc/hostname, no home. Its CPU
//   time, memory and files (the log included) are bounded (kBuildLimits); a build still going
//   after kBuildWallBackstop is stopped and said to be the machine's reason.

#include <aula/sandbox/sandbox.hpp>

#include <chrono>
#include <string>
#include <vector>

namespace aula::grade {

// The names a submission's source may have: a letter, digit or '_' first, then letters,
// digits, '_', '.', '-', and a C++ or Python source's extension.
constexpr const char* kPlainSourceName = R"(^[A-Za-z0-9_][A-Za-z0-9_.-]*\.(cpp|cc|cxx|hpp|h|hh|py)$)";
constexpr uint64_t kMaxSourceBytes = 1ull << 20;  // one source file: 1 MiB

// What a build may use: memory (RLIMIT_AS) and CPU time of each of its processes, and the largest
// file it writes (each object, the plugin, and compile.log itself).
inline sandbox::Limits buildLimits() {
  sandbox::Limits limits;
  limits.memory_bytes = 2ull << 30;
  limits.cpu_s = 300;
  limits.file_bytes = 64ull << 20;
  limits.processes = 64;
  return limits;
}
constexpr std::chrono::seconds kBuildWallBackstop{900};

// A name as a person may read it in a row or a log: printable ASCII as is, any other byte and the
// quotes and backslash as \xNN, at most 80 characters ("MyAlgorithm.cpp\x22)\x0afile(STRINGS...").
std::string printableName(const std::string& name);

bool isPlainSourceName(const std::string& name);

// A submission folder's files, sorted by name: what is taken, what is not used, and why the
// submission is refused ("" when it is not).
struct SubmissionFiles {
  std::vector<std::string> sources;  // plain names of regular files, each at most kMaxSourceBytes
  std::vector<std::string> unused;   // printable names of what is not taken ("build/", "CMakeLists.txt")
  std::string refused;               // "refused: MyAlgorithm.cpp\")... is not a plain source name (...)"
};
SubmissionFiles submissionFiles(const std::string& folder);

// Copies `files.sources` of `folder` into `into` (made if missing) and removes what else it holds;
// a file whose bytes are already there is left as it is (a resumed grade rebuilds nothing).
// Returns "" or why it could not.
std::string copySources(const std::string& folder, const SubmissionFiles& files, const std::string& into);

// The build project of a C++ submission: `project`/CMakeLists.txt (written only when it changes),
// which builds every .cpp/.cc/.cxx of `project`/src into `project`/build/libmy_algorithm.so for
// `exercise` against the Aula package in `aula_config_dir`. No name of the student's is in it.
void writeBuildProject(const std::string& project, const std::string& exercise, const std::string& aula_config_dir);

// Aula's SDK as a build needs it, found from Aula's prefix: the folder of AulaConfig.cmake (an
// installed prefix's lib/cmake/Aula, or a build tree), its package files, and the include folders
// its targets name. Throws config::ConfigError when there is no Aula package there.
struct AulaSdk {
  std::string config_dir;
  std::vector<std::string> files;         // AulaConfig.cmake, AulaTargets.cmake... (bound one by one)
  std::vector<std::string> include_dirs;  // the API's headers
  std::string lib_dir;                    // <prefix>/lib/aula: hidden where /usr would show it
};
AulaSdk findAulaSdk(const std::string& aula_prefix);

// The sandboxed build's confinement for `project` (see above).
sandbox::Confinement buildConfinement(const AulaSdk& sdk, const std::string& project);

// The command that configures and builds `project` (fixed words and the project's paths, as the
// shell's arguments): where the sandbox shows it when `boxed`, else at its own path.
std::vector<std::string> buildCommand(const std::string& project, bool boxed);

}  // namespace aula::grade
