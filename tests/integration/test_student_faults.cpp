// A student's algorithm that goes wrong, run as a plugin the way a student runs it:
// `aula run vacuum --headless --algorithm=PATH.so`, real processes on a private LCM URL. Each
// fault (tests/data/plugins) must end the run the way issue #10 says, with the exit code, the
// message on stderr and the report's field, and leave no Aula process behind:
//   an exception, a crash, an endless loop, NaN commands, no command at all, and every way a
//   plugin can fail to load (exit 2 at once).
// The runs are short (20 s of sim time, a few seconds of wall time each).
#include "test_support.hpp"

#include <aula/process/child_process.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace std::chrono_literals;
using aula::testing::jsonNumber;
using aula::testing::readFile;

namespace {

namespace fs = std::filesystem;

struct RunResult {
  std::optional<int> code;  // the launcher's exit code; nullopt: still running at the deadline
  double wall_s = 0;
  std::string out, err;     // the launcher's stdout and stderr (its processes' too)
  std::string report;       // the referee's JSON report ("" when it wrote none)
};

// `aula run vacuum --headless --algorithm=<algorithm>` with an episode of `episode_s` (sim
// seconds), and `extra` options.
RunResult runVacuum(const std::string& algorithm, const std::string& tag, std::vector<std::string> extra = {},
                    std::chrono::seconds deadline = 60s, int episode_s = 20) {
  const std::string base = ::testing::TempDir() + "student_faults_" + tag;
  const std::string report = base + ".json";
  std::remove(report.c_str());
  std::vector<std::string> argv = {std::string(AULA_BIN_DIR) + "/aula", "run", "vacuum", "--headless",
                                   "--algorithm=" + algorithm,
                                   "--Vacuum.Referee.Duration=" + std::to_string(episode_s),
                                   "--report=" + report, "--lcm-url=" + aula::testing::privateLcmUrl()};
  argv.insert(argv.end(), extra.begin(), extra.end());
  RunResult run;
  const auto start = std::chrono::steady_clock::now();
  {
    aula::process::ChildProcess launcher(argv, base + ".out", base + ".err");
    run.code = launcher.wait(deadline);
    run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }  // a launcher still running at the deadline is stopped here (and the test fails on its code)
  run.out = readFile(base + ".out");
  run.err = readFile(base + ".err");
  run.report = fs::exists(report) ? readFile(report) : "";
  return run;
}

std::string describe(const RunResult& run) {
  return "exit " + (run.code ? std::to_string(*run.code) : std::string("(none: still running)")) + " after " +
         std::to_string(run.wall_s) + " s\n--- stderr:\n" + run.err + "--- stdout:\n" + run.out +
         "--- report:\n" + run.report;
}

// A string field of the report, or nullopt.
std::optional<std::string> jsonString(const std::string& json, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(json, m, std::regex("\"" + key + "\": \"([^\"]*)\""))) return std::nullopt;
  return m[1].str();
}

bool hasField(const std::string& json, const std::string& key) {
  return json.find("\"" + key + "\":") != std::string::npos;
}

size_t countLines(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  size_t n = 0;
  for (std::string line; std::getline(in, line);) n += line.find(needle) != std::string::npos;
  return n;
}

// The processes still alive that were started for this test process's runs: every Aula program
// the launcher starts gets our private --lcm-url (one port per test process, so a parallel test
// never counts). Waits up to `grace` for them to go.
std::vector<std::string> aulaProcessesLeft(std::chrono::milliseconds grace = 1000ms) {
  const std::string url = aula::testing::privateLcmUrl();
  const auto until = std::chrono::steady_clock::now() + grace;
  for (;;) {
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator("/proc")) {
      const std::string pid = entry.path().filename().string();
      if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
      std::string cmdline = readFile(entry.path().string() + "/cmdline");
      for (char& c : cmdline) c = c == '\0' ? ' ' : c;
      if (cmdline.find(url) == std::string::npos) continue;
      std::string state = readFile(entry.path().string() + "/stat");
      left.push_back(pid + ": " + cmdline + " (stat: " + state.substr(0, 60) + ")");
    }
    if (left.empty() || std::chrono::steady_clock::now() >= until) return left;
    std::this_thread::sleep_for(50ms);
  }
}

// A run that went to the end of its 20 s episode, exit 0, with no fault in its report.
void expectFinishedWithoutFault(const RunResult& run) {
  ASSERT_TRUE(run.code.has_value()) << describe(run);
  EXPECT_EQ(*run.code, 0) << describe(run);
  ASSERT_FALSE(run.report.empty()) << describe(run);
  EXPECT_NE(run.report.find("\"finished\": true"), std::string::npos) << describe(run);
  EXPECT_DOUBLE_EQ(jsonNumber(run.report, "sim_time_s"), 20.0) << describe(run);
  EXPECT_FALSE(hasField(run.report, "algorithm_error")) << describe(run);
  EXPECT_FALSE(hasField(run.report, "aborted")) << describe(run);
}

#define EXPECT_NO_AULA_PROCESS_LEFT()                                                       \
  do {                                                                                      \
    const auto left = aulaProcessesLeft();                                                  \
    EXPECT_TRUE(left.empty()) << "still running after the launcher ended:\n"                \
                              << ::testing::PrintToString(left);                            \
  } while (0)

}  // namespace

// 1. execute() throws: the fault is contained, the robot stopped, and the run graded so far.
TEST(StudentFaults, ExceptionEndsTheRunWithAlgorithmError) {
  const RunResult run = runVacuum(AULA_PLUGIN_THROWS, "throws");
  ASSERT_TRUE(run.code.has_value()) << describe(run);
  EXPECT_NE(*run.code, 0) << describe(run);
  // Named where it was thrown, in the student's file (the plugin is built with -g).
  EXPECT_NE(run.err.find("vacuum-cleaner: the student's algorithm failed: execute() threw std::runtime_error: boom "
                         "(thrown at throws.cpp:12)"),
            std::string::npos)
      << describe(run);
  ASSERT_FALSE(run.report.empty()) << describe(run);
  const auto error = jsonString(run.report, "algorithm_error");
  ASSERT_TRUE(error.has_value()) << describe(run);
  EXPECT_NE(error->find("boom (thrown at throws.cpp:12)"), std::string::npos) << describe(run);
  EXPECT_NE(run.report.find("\"finished\": false"), std::string::npos) << describe(run);
  EXPECT_EQ(run.report.find("\"finished\": true"), std::string::npos) << describe(run);
  EXPECT_GE(jsonNumber(run.report, "mark"), 0.0) << describe(run);
  // Graded at the fault, not at the end of the 20 s episode.
  EXPECT_LT(jsonNumber(run.report, "sim_time_s"), 20.0) << describe(run);
  EXPECT_NO_AULA_PROCESS_LEFT();
}

// 1b. An exception the C++ runtime throws from inside the library (vector::at) is named at the
// student's line that called it, not in the library's header.
TEST(StudentFaults, LibraryExceptionNamesTheStudentsLine) {
  const RunResult run = runVacuum(AULA_PLUGIN_OUT_OF_RANGE, "out_of_range");
  ASSERT_TRUE(run.code.has_value()) << describe(run);
  EXPECT_NE(*run.code, 0) << describe(run);
  EXPECT_NE(run.err.find("execute() threw std::out_of_range: vector::_M_range_check: __n (which is 500) >= "
                         "this->size() (which is 180) (thrown at out_of_range.cpp:13)"),
            std::string::npos)
      << describe(run);
  const auto error = jsonString(run.report, "algorithm_error");
  ASSERT_TRUE(error.has_value()) << describe(run);
  EXPECT_NE(error->find("(thrown at out_of_range.cpp:13)"), std::string::npos) << describe(run);
  EXPECT_NO_AULA_PROCESS_LEFT();
}

namespace {

// The 1-based line of `file` that holds `text`: a test names the real line of a statement, read
// from the source (0 when it is not there).
int lineOf(const std::string& file, const std::string& text) {
  std::istringstream in(readFile(file));
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (line.find(text) != std::string::npos) return n;
  }
  return 0;
}

// 2. execute() crashes the component: it names the student's line, the launcher says who, how,
// where and running what; the referee still writes its report, the line as its algorithm_error.
void expectCrashNamedAtItsLine(const RunResult& run) {
  ASSERT_TRUE(run.code.has_value()) << describe(run);
  EXPECT_NE(*run.code, 0) << describe(run);
  const int line = lineOf(std::string(AULA_TEST_DATA_DIR) + "/plugins/segfault.cpp", "*nowhere = calls_;");
  ASSERT_GT(line, 0);
  const std::string where = "segfault.cpp:" + std::to_string(line) + " (Segfault::execute)";
  const std::string plugin_name = fs::path(AULA_PLUGIN_SEGFAULT).filename().string();
  EXPECT_EQ(countLines(run.err, "ended the run"), 1u) << describe(run);
  std::smatch said;
  ASSERT_TRUE(std::regex_search(run.err, said, std::regex("aula: [^\n]*ended the run[^\n]*"))) << describe(run);
  EXPECT_NE(said.str().find("vacuum-cleaner"), std::string::npos) << said.str();
  EXPECT_NE(said.str().find(plugin_name), std::string::npos) << said.str();
  EXPECT_NE(said.str().find("ended the run: component crashed (SIGSEGV) at " + where), std::string::npos) << said.str();
  // The student's frames, resolved: no raw stack, no addr2line to run by hand.
  EXPECT_NE(run.err.find("vacuum-cleaner: crashed (SIGSEGV) in your algorithm at " + where + "\n"), std::string::npos)
      << describe(run);
  EXPECT_EQ(run.err.find("addr2line"), std::string::npos) << describe(run);
  ASSERT_FALSE(run.report.empty()) << describe(run);
  EXPECT_EQ(jsonString(run.report, "aborted").value_or("(no \"aborted\")"), "component crashed (SIGSEGV)")
      << describe(run);
  EXPECT_EQ(jsonString(run.report, "algorithm_error").value_or("(no \"algorithm_error\")"),
            "component crashed (SIGSEGV) at " + where)
      << describe(run);
  EXPECT_NE(run.report.find("\"finished\": false"), std::string::npos) << describe(run);
  EXPECT_GE(jsonNumber(run.report, "mark"), 0.0) << describe(run);
  EXPECT_NO_AULA_PROCESS_LEFT();
}

}  // namespace

TEST(StudentFaults, CrashNamesTheStudentsLineAndAbortsTheReport) {
  expectCrashNamedAtItsLine(runVacuum(AULA_PLUGIN_SEGFAULT, "segfault"));
}

// The same in the grading sandbox: addr2line and the plugin are visible inside, and the line
// reaches the launcher through its private pipe.
TEST(StudentFaults, CrashNamesTheStudentsLineInTheSandbox) {
  expectCrashNamedAtItsLine(runVacuum(AULA_PLUGIN_SEGFAULT, "segfault_sandboxed", {"--sandbox"}));
}

// 3. execute() never returns: the watchdog ends the component once the call has used its budget
// of CPU time (however busy the machine), instead of hanging.
TEST(StudentFaults, EndlessLoopEndsTheRunWithinTheBudget) {
  const RunResult run = runVacuum(AULA_PLUGIN_ENDLESS_LOOP, "endless_loop", {"--Component.ExecuteBudget=1"}, 300s);
  ASSERT_TRUE(run.code.has_value()) << "the run hung\n" << describe(run);
  EXPECT_NE(*run.code, 0) << describe(run);
  const std::string overran = "execute() used more than 1 s of CPU time (an endless loop?) (Component.ExecuteBudget)";
  EXPECT_NE(run.err.find("vacuum-cleaner: the student's algorithm: " + overran), std::string::npos) << describe(run);
  EXPECT_NE(run.err.find("ended the run: " + overran), std::string::npos) << describe(run);
  ASSERT_FALSE(run.report.empty()) << describe(run);
  const auto aborted = jsonString(run.report, "aborted");
  ASSERT_TRUE(aborted.has_value()) << describe(run);
  EXPECT_EQ(*aborted, overran) << describe(run);
  EXPECT_NE(run.report.find("\"finished\": false"), std::string::npos) << describe(run);
  EXPECT_NO_AULA_PROCESS_LEFT();
}

// 4. NaN speeds: refused (the robot stays still), counted in the report, said once.
TEST(StudentFaults, NanCommandsAreCountedAndTheRobotStaysStill) {
  const RunResult run = runVacuum(AULA_PLUGIN_NAN_COMMANDS, "nan_commands");
  expectFinishedWithoutFault(run);
  EXPECT_GT(jsonNumber(run.report, "non_finite_commands"), 0.0) << describe(run);
  // The robot's own footprint only (0.16 % of the floor); a moving robot covers far more.
  EXPECT_LT(jsonNumber(run.report, "coverage_percent"), 0.5) << describe(run);
  EXPECT_EQ(countLines(run.err, "not a finite number"), 1u) << describe(run);
  EXPECT_NO_AULA_PROCESS_LEFT();
}

// 5. No command at all: an ordinary finished run, marked like the template that sends zeros.
TEST(StudentFaults, NoCommandsIsAnOrdinaryRunWithTheDoNothingMark) {
  const RunResult run = runVacuum(AULA_PLUGIN_DOES_NOTHING, "does_nothing");
  expectFinishedWithoutFault(run);
  EXPECT_FALSE(hasField(run.report, "non_finite_commands")) << describe(run);
  // The launcher says only which bus the run has, nothing about the run.
  EXPECT_EQ(run.err.find("aula: ", run.err.find("aula: the run's bus is ") == 0 ? 1 : 0), std::string::npos) << describe(run);
  EXPECT_NO_AULA_PROCESS_LEFT();

  // The in-tree template stands still too (it sends zeros): the same mark.
  const RunResult still = runVacuum("student", "student_template");
  ASSERT_EQ(still.code.value_or(-1), 0) << describe(still);
  EXPECT_DOUBLE_EQ(jsonNumber(run.report, "mark"), jsonNumber(still.report, "mark")) << describe(run)
                                                                                      << describe(still);
  EXPECT_LT(jsonNumber(run.report, "coverage_percent"), 0.5) << describe(run);
}

// 6. A plugin that cannot be used: exit 2 at once, one message naming the file and the reason.
// "At once" is the processes' start-up: about 2 s on an idle 2-core machine (the component loads
// the world before the plugin), up to 4.5 s beside another integration test; the bound leaves
// room for a loaded CI machine. The episode is an hour of sim time: a run that went on
// regardless would take about 16 s (900 s of sim is about 4 s of wall time).
class StudentFaultsLoad : public ::testing::Test {
 protected:
  void expectLoadError(const std::string& plugin, const std::string& tag, const std::string& reason) {
    const RunResult run = runVacuum(plugin, tag, {}, 60s, 3600);
    ASSERT_TRUE(run.code.has_value()) << describe(run);
    EXPECT_EQ(*run.code, 2) << describe(run);
    EXPECT_LT(run.wall_s, 8.0) << describe(run);
    EXPECT_EQ(countLines(run.err, reason), 1u) << "expected one line with \"" << reason << "\"\n" << describe(run);
    EXPECT_NE(run.err.find(fs::path(plugin).filename().string() + ": "), std::string::npos) << describe(run);
    // A run that never started has no mark: no report, and no mark printed (the referee says
    // "no mark: the run never started", or nothing when it was stopped while starting up).
    EXPECT_EQ(run.report, "") << describe(run);
    EXPECT_EQ(run.out.find("cleaner mark"), std::string::npos) << describe(run);
    EXPECT_NO_AULA_PROCESS_LEFT();
  }
};

TEST_F(StudentFaultsLoad, MissingFile) {
  const std::string missing = aula::testing::privateDir() + "/libnot_built_yet.so";
  expectLoadError(missing, "missing", "no such plugin file");
}

TEST_F(StudentFaultsLoad, NotASharedLibrary) {
  const std::string garbage = aula::testing::privateDir() + "/libgarbage.so";
  std::ofstream(garbage) << "this is not an ELF file, just some text a student saved as .so\n";
  expectLoadError(garbage, "garbage", "not a shared library");
}

TEST_F(StudentFaultsLoad, PluginOfAnotherExercise) {
  expectLoadError(AULA_PLUGIN_TELETAXI_STILL, "teletaxi_in_vacuum", "wrong exercise");
}

TEST_F(StudentFaultsLoad, AbiMismatch) {
  expectLoadError(AULA_PLUGIN_ABI_MISMATCH, "abi_mismatch", "ABI mismatch");
}

TEST_F(StudentFaultsLoad, UndefinedSymbol) {
  expectLoadError(AULA_PLUGIN_UNDEFINED_SYMBOL, "undefined_symbol", "undefined symbol");
  // dlerror's text names what is missing.
  const std::string err = readFile(::testing::TempDir() + "student_faults_undefined_symbol.err");
  EXPECT_NE(err.find("aula_test_function_that_does_not_exist"), std::string::npos) << err;
}

// The algorithm in a process of its own (Component.OwnProcess=on, issue 39): it holds its
// socket, its private line and the three standard descriptors, none of the teacher's
// environment, not the component's command line (the run's bus, its world), it may open no
// socket and make no system call off its list (memfd_create), each refusal said once on its
// output. Inside the component (off), the same plugin has all of them.
TEST(StudentFaults, TheAlgorithmsOwnProcessHoldsOnlyWhatTheApiGives) {
  ::setenv("AULA_TEST_TEACHERS_SECRET", "the held-out world is in /srv/exam", 1);
  const RunResult boxed = runVacuum(AULA_PLUGIN_WHAT_IT_HOLDS, "what_it_holds", {"--Component.OwnProcess=on"});
  const RunResult inside = runVacuum(AULA_PLUGIN_WHAT_IT_HOLDS, "what_it_holds_inside", {"--Component.OwnProcess=off"});
  ::unsetenv("AULA_TEST_TEACHERS_SECRET");
  EXPECT_EQ(jsonString(boxed.report, "algorithm_error").value_or("").rfind("execute() threw std::runtime_error: holds: "
                                                                           "fds=5 secret=no bus=no socket=no memfd=no (thrown at what_it_holds.cpp:", 0),
            0u)
      << describe(boxed);
  for (const char* call : {"socket", "memfd_create"}) {
    const std::string said = std::string("the algorithm's process may not call ") + call + "(): refused\n";
    EXPECT_NE(boxed.err.find(said), std::string::npos) << describe(boxed);
  }
  const std::string seen = jsonString(inside.report, "algorithm_error").value_or("");
  EXPECT_NE(seen.find("secret=yes bus=yes socket=yes memfd=yes"), std::string::npos) << describe(inside);
  EXPECT_EQ(seen.find("fds=5 "), std::string::npos) << describe(inside);
  EXPECT_NO_AULA_PROCESS_LEFT();
}

// An algorithm in its own process that runs its own program again (the exam's re-exec): the new
// image has no socket to its component (closed on exec), so it ends at once as a forbidden try,
// and the run ends with that reason, flagged (exit code 5), instead of both ends waiting.
TEST(StudentFaults, AnAlgorithmsProcessStartedAgainEndsTheRunAsAForbiddenTry) {
  const RunResult run = runVacuum(AULA_PLUGIN_REEXEC, "reexec", {"--Component.OwnProcess=on"});
  ASSERT_TRUE(run.code.has_value()) << describe(run);
  EXPECT_NE(run.err.find("the algorithm tried to run the algorithm's process again"), std::string::npos) << describe(run);
  EXPECT_NE(*run.code, 0) << describe(run);
  EXPECT_NO_AULA_PROCESS_LEFT();
}
