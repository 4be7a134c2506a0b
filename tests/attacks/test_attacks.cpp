// Attacks on a graded run (issue 15, "Truth the component cannot forge"): `aula run vacuum
// --headless` with the do-nothing template, a 60 s episode, real processes on a private LCM
// port; an attacker process (aula-test-attacker) joins the bus once the run has started and
// forges one kind of traffic. Each case compares with the same run unattacked (same seed): the
// report must be the unattacked one's, plus the "tampering" it counted when the attack is one
// the referee or the simulator can tell; and the run must end well within its wall timeout.
#include "test_support.hpp"

#include <aula/process/child_process.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <regex>
#include <string>
#include <vector>

using namespace std::chrono_literals;
using aula::testing::jsonNumber;
using aula::testing::readFile;

namespace {

struct RunResult {
  std::optional<int> code;  // nullopt: still running at the wall timeout
  std::optional<int> attacker_code;
  double wall_s = 0;
  std::string report, log;
};

constexpr auto kWallTimeout = 120s;

// `aula run vacuum --headless` (seed 3, 60 s), attacked by `attack` ("" none) and running
// `algorithm` (the template by default: it stays still).
// `second_sim`: once the run is 5 s in, a second aula-sim on the run's URL (its exit code, wall
// time and output in `second`).
struct SecondSim {
  std::optional<int> code;
  double wall_s = 0;
  std::string output;
};
RunResult runVacuum(const std::string& dir, const std::string& attack, const std::string& algorithm = "student",
                    double duration_s = 60, SecondSim* second_sim = nullptr, const std::vector<std::string>& extra = {}) {
  std::string options;
  for (const std::string& option : extra) options += "-" + option.substr(option.find('=') + 1);
  const std::string tag = (attack.empty() ? "clean" : attack) + std::to_string(static_cast<int>(duration_s)) +
                          (second_sim != nullptr ? "-second-sim" : "") + options;
  const std::string report = dir + "/" + tag + ".json", log = dir + "/" + tag + ".log";
  const std::string url = aula::testing::privateLcmUrl();
  RunResult run;
  const auto start = std::chrono::steady_clock::now();
  {
    std::vector<std::string> argv = {std::string(AULA_BIN_DIR) + "/aula", "run", "vacuum", "--headless",
                                     "--algorithm=" + algorithm, "--seed=3",
                                     "--Vacuum.Referee.Duration=" + std::to_string(duration_s), "--report=" + report,
                                     "--lcm-url=" + url};
    argv.insert(argv.end(), extra.begin(), extra.end());
    aula::process::ChildProcess launcher(argv, log, log);
    std::optional<aula::process::ChildProcess> attacker;
    if (!attack.empty()) {
      attacker.emplace(std::vector<std::string>{AULA_ATTACKER, "--lcm-url=" + url, "--attack=" + attack, "--after-s=10"},
                       dir + "/attacker.log", dir + "/attacker.log");
    }
    if (second_sim != nullptr) {
      aula::process::ChildProcess cue({AULA_ATTACKER, "--lcm-url=" + url, "--attack=none", "--after-s=5"},
                                      dir + "/cue.log", dir + "/cue.log");
      if (cue.wait(40s) == 0) {
        const auto second_start = std::chrono::steady_clock::now();
        aula::process::ChildProcess second({std::string(AULA_BIN_DIR) + "/aula-sim", AULA_VACUUM_WORLD, "--lockstep",
                                            "--rtf=0", "--lcm-url=" + url},
                                           dir + "/second.log", dir + "/second.log");
        second_sim->code = second.wait(10s);
        second_sim->wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - second_start).count();
      }
      second_sim->output = readFile(dir + "/second.log") + readFile(dir + "/cue.log");
    }
    run.code = launcher.wait(kWallTimeout);
    if (attacker) run.attacker_code = attacker->wait(5s);
  }
  run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.report = readFile(report);
  run.log = readFile(log) + (attack.empty() ? "" : "--- attacker:\n" + readFile(dir + "/attacker.log"));
  return run;
}

// The report without its "tampering" line: what the grading itself says.
std::string graded(const std::string& report) {
  const std::string field = "\"tampering\": \\{[^}]*\\}";
  const std::string last = std::regex_replace(report, std::regex(",\n  " + field + "\n"), "\n");
  return std::regex_replace(last, std::regex("  " + field + ",\n"), "");
}

std::string tampering(const std::string& report) {
  std::smatch m;
  return std::regex_search(report, m, std::regex("\"tampering\": (\\{[^}]*\\})")) ? m[1].str() : "";
}

class Attacks : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = aula::testing::privateDir();
    clean_ = runVacuum(dir_, "");
    ASSERT_EQ(clean_.code, 0) << clean_.log;
    ASSERT_EQ(tampering(clean_.report), "") << "an unattacked run's report has no tampering field";
  }
  // The attacked run ended by itself, its grading is the clean run's, and it counted `expected`.
  void expectGradedAsCleanWith(const std::string& attack, const std::string& expected) {
    const RunResult run = runVacuum(dir_, attack);
    ASSERT_TRUE(run.code.has_value()) << "the attacked run hung:\n" << run.log;
    EXPECT_EQ(run.attacker_code, 0) << "the attack was not sent:\n" << run.log;
    EXPECT_EQ(*run.code, 0) << run.log;
    EXPECT_EQ(graded(run.report), clean_.report) << run.log;
    EXPECT_EQ(tampering(run.report), expected) << run.report;
  }
  std::string dir_;
  RunResult clean_;
};

}  // namespace

// Forged poses sweeping the house (99 % coverage if graded): none is graded, each is counted.
TEST_F(Attacks, APoseFloodIsNotGradedAndIsCounted) {
  const RunResult run = runVacuum(dir_, "pose-flood");
  ASSERT_TRUE(run.code.has_value()) << run.log;
  EXPECT_EQ(run.attacker_code, 0) << run.log;
  EXPECT_EQ(graded(run.report), clean_.report) << run.log;
  EXPECT_NEAR(jsonNumber(run.report, "coverage_percent"), jsonNumber(clean_.report, "coverage_percent"), 1e-9);
  // Three sweeps of 37 x 37 poses; the kernel may drop some of a burst, never add any.
  std::smatch m;
  const std::string counted = tampering(run.report);
  ASSERT_TRUE(std::regex_search(counted, m, std::regex("\"ROOMBA_POSE\": ([0-9]+)"))) << run.report;
  EXPECT_GT(std::stol(m[1]), 1000) << run.report;
  EXPECT_LE(std::stol(m[1]), 3 * 37 * 37) << run.report;
}

// A teleport, a pause and a reset from outside: the simulator obeys none of them.
TEST_F(Attacks, SimControlTeleportPauseAndResetAreRefusedAndCounted) {
  expectGradedAsCleanWith("control", "{\"SIM_CONTROL\": 3}");
}

// Ticks of the referee's own signed clock only: a forged SIM_CLOCK far in the future moves
// nothing it grades.
TEST_F(Attacks, AForgedClockIsIgnoredByTheRefereeAndCounted) {
  expectGradedAsCleanWith("clock", "{\"SIM_CLOCK\": 20}");
}

// A forged reload and a later start on VACUUM_EPISODE: a graded run has one episode.
TEST_F(Attacks, AForgedEpisodeDoesNotRestartTheGradingAndIsCounted) {
  expectGradedAsCleanWith("episode", "{\"VACUUM_EPISODE\": 2}");
}

// Acks and a leave in the component's name: not told apart from the component's own (it has no
// key), so nothing is counted; the run must still end by itself with a still robot's grade.
TEST_F(Attacks, ForgedLockstepAckAndLeaveDoNotHangTheRun) { expectGradedAsCleanWith("lockstep", ""); }

// 10,000 random packets over every channel: nothing decodes as signed truth, nothing hangs.
TEST_F(Attacks, GarbageOnEveryChannelChangesNoMarkAndHangsNothing) {
  const RunResult run = runVacuum(dir_, "garbage");
  ASSERT_TRUE(run.code.has_value()) << run.log;
  EXPECT_EQ(run.attacker_code, 0) << run.log;
  EXPECT_EQ(*run.code, 0) << run.log;
  EXPECT_EQ(jsonNumber(run.report, "mark"), jsonNumber(clean_.report, "mark")) << run.report;
  EXPECT_EQ(jsonNumber(run.report, "coverage_percent"), jsonNumber(clean_.report, "coverage_percent")) << run.report;
}

// The same pose flood and a teleport from inside the student's execute(), on the run's bus found
// in the component's command line. Inside the component (Component.OwnProcess=off): graded as
// the still robot it is, and the report shows what it tried. In its own process (Component.OwnProcess=on) it
// cannot open a socket: nothing reaches the run, and the run is the clean one.
TEST_F(Attacks, APluginThatForgesFromExecuteIsGradedOnItsRealBehaviour) {
  const RunResult run = runVacuum(dir_, "", AULA_CHEAT_PLUGIN, 60, nullptr, {"--Component.OwnProcess=off"});
  ASSERT_EQ(run.code, 0) << run.log;
  EXPECT_EQ(jsonNumber(run.report, "mark"), jsonNumber(clean_.report, "mark")) << run.report;
  EXPECT_EQ(jsonNumber(run.report, "coverage_percent"), jsonNumber(clean_.report, "coverage_percent")) << run.report;
  const std::string counted = tampering(run.report);
  EXPECT_NE(counted.find("\"ROOMBA_POSE\": "), std::string::npos) << run.report;
  EXPECT_NE(counted.find("\"SIM_CONTROL\": 1"), std::string::npos) << run.report;

  const RunResult boxed = runVacuum(dir_, "", AULA_CHEAT_PLUGIN, 60, nullptr, {"--Component.OwnProcess=on"});
  ASSERT_EQ(boxed.code, 0) << boxed.log;
  EXPECT_EQ(jsonNumber(boxed.report, "mark"), jsonNumber(clean_.report, "mark")) << boxed.report;
  EXPECT_EQ(tampering(boxed.report), "") << boxed.report;
}

// A forged clock from another simulator instance, far ahead: the component (and the referee's
// own clock) follow only the instance that listed them, so nothing moves, nothing hangs; the
// simulator hears another instance on its clock channel and says so.
TEST_F(Attacks, AClockOfAnotherSimulatorInstanceIsIgnored) {
  const RunResult run = runVacuum(dir_, "clock-instance");
  ASSERT_TRUE(run.code.has_value()) << "the attacked run hung:\n" << run.log;
  EXPECT_EQ(run.attacker_code, 0) << run.log;
  EXPECT_EQ(*run.code, 0) << run.log;
  EXPECT_LT(run.wall_s, clean_.wall_s + 10) << run.log;
  EXPECT_EQ(graded(run.report), clean_.report) << run.log;
  // Unsigned: the referee's gate counts those sent before the run ended (20 go out over 200 ms).
  EXPECT_TRUE(std::regex_match(tampering(run.report), std::regex("\\{\"SIM_CLOCK\": ([1-9]|1[0-9]|20)\\}"))) << run.report;
  EXPECT_NE(run.log.find("vacuum-cleaner: ignoring SIM_CLOCK ticks of another simulator"), std::string::npos) << run.log;
  EXPECT_TRUE(std::regex_search(run.log, std::regex("another simulator \\(instance [0-9]+, world '[^']*'\\) publishes on udpm://")))
      << run.log;
}

// A second aula-sim started on a running run's URL hears the run's clock before its own first
// tick and exits 2 at once (on a loaded machine, where its first listen may miss the run's
// clock: at the run's first tick it hears, having no client of its own); the run it would have
// disturbed grades as if it had never started.
TEST_F(Attacks, ASecondSimulatorOnTheSameUrlExits2AndChangesNothing) {
  // Long enough that the run is still going when the second simulator has loaded its world.
  constexpr double kLongEpisodeS = 300;
  const RunResult clean = runVacuum(dir_, "", "student", kLongEpisodeS);
  ASSERT_EQ(clean.code, 0) << clean.log;
  SecondSim second;
  const RunResult run = runVacuum(dir_, "", "student", kLongEpisodeS, &second);
  ASSERT_TRUE(run.code.has_value()) << "the run hung:\n" << run.log;
  EXPECT_EQ(*run.code, 0) << run.log;
  ASSERT_EQ(second.code, 2) << second.output;
  EXPECT_TRUE(std::regex_search(second.output,
                                std::regex("aula-sim: another simulator \\(instance [0-9]+, world [^)]+\\) is already "
                                           "running on udpm://")))
      << second.output;
  EXPECT_EQ(run.report, clean.report) << run.log;
}

// A plugin that tries to write outside, to see and ptrace the simulator and the referee, and to
// open TCP and Unix sockets: without the sandbox, inside the component, every try succeeds (so
// this test can fail);
// with `aula run --sandbox` (what `aula grade` runs) every one is refused, and the run is graded
// as usual (LCM's UDP multicast still works). The same tries from a student's MyAlgorithm.py
// (tests/attacks/python) meet the same walls.
class Sandbox : public ::testing::TestWithParam<std::string> {};

TEST_P(Sandbox, AStudentsAlgorithmCannotWriteSeeOrTraceOtherProcessesNorOpenOtherSockets) {
  // A folder outside /tmp (the sandbox has a /tmp of its own), beside the component's program,
  // where the attack looks for it (one per language: the two may run at once).
  const bool python = GetParam().size() > 3 && GetParam().compare(GetParam().size() - 3, 3, ".py") == 0;
  const std::string dir = std::string(AULA_BIN_DIR) + (python ? "/escape-target-python" : "/escape-target-cpp");
  std::filesystem::create_directories(dir);
  // What each try gives in the sandbox: a filesystem of only the run's own inputs (the folder is
  // not even there), the process namespace, seccomp.
  const std::vector<std::pair<std::string, std::string>> tries = {
      {"write a file outside", "No such file or directory"},
      {"see the simulator or the referee in /proc", "No such process"},
      {"open a TCP socket", "Permission denied"},
      {"open a Unix socket", "Permission denied"},
      {"ptrace another process", "Operation not permitted"}};
  // Open, sandboxed, and sandboxed with the algorithm in a process of its own.
  for (const int kind : {0, 1, 2}) {
    const bool sandboxed = kind > 0;
    SCOPED_TRACE(kind == 0 ? "no sandbox" : kind == 1 ? "--sandbox" : "--sandbox --Component.OwnProcess=on");
    const std::string report = dir + "/report.json", log = dir + "/run" + std::to_string(kind) + ".log";
    std::filesystem::remove(dir + "/escaped.txt");
    std::vector<std::string> argv = {std::string(AULA_BIN_DIR) + "/aula", "run", "vacuum", "--headless",
                                     "--algorithm=" + GetParam(), "--Vacuum.Referee.Duration=5",
                                     "--report=" + report, "--lcm-url=" + aula::testing::privateLcmUrl()};
    // Without the sandbox, the algorithm inside the component (in its own process it may open no
    // socket, nor trace its parent, which is not dumpable).
    argv.push_back(sandboxed ? "--sandbox" : "--Component.OwnProcess=off");
    if (kind == 2) argv.push_back("--Component.OwnProcess=on");
    aula::process::ChildProcess run(argv, log, log);
    ASSERT_EQ(run.wait(60s).value_or(-1), 0) << readFile(log);
    const std::string out = readFile(log);
    for (const auto& [what, why] : tries) {
      const std::string said = "escape: " + what + (sandboxed ? ": refused (" + why + ")" : ": done");
      EXPECT_NE(out.find(said), std::string::npos) << "expected '" << said << "' in\n" << out;
    }
    EXPECT_EQ(std::filesystem::exists(dir + "/escaped.txt"), !sandboxed);
    EXPECT_NE(readFile(report).find("\"finished\": true"), std::string::npos) << readFile(report);
  }
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(CppAndPython, Sandbox, ::testing::Values(AULA_ESCAPE_PLUGIN, AULA_ESCAPE_PYTHON),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param.size() > 3 && info.param.compare(info.param.size() - 3, 3, ".py") == 0
                                      ? "Python" : "Cpp";
                         });
