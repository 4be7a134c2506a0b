// A student's MyAlgorithm.py, run the way a student runs it: `aula run EXERCISE --headless
// --algorithm=DIR/MyAlgorithm.py`, real processes on a private LCM URL (issue 31).
// - One API, two languages: a Python port of a C++ test algorithm earns the same report for the
//   same seed, byte for byte but the algorithm's name.
// - Faults in the student's own lines: a SyntaxError, an exception's traceback, an endless loop
//   interrupted inside Python, NaN commands, a missing module; each on stderr and in the report.
// - Determinism: `random` and numpy seeded from the run's seed; the user's environment ignored;
//   a recorded run regrades to the same report.
// - Programs in RoboticsAcademy's shape (`import HAL, GUI`, `while True:`, `time.sleep`), unchanged,
//   each doing its job; the simulator's clock in both shapes; under `aula grade` (issue 41).
// - Every generation of the course's program, told from the file (issue 54): RoboticsAcademy
//   2021-23 (`from HAL import HAL`, MAP), 2025 (WebGUI, Frequency), JdeRobot-Academy 2017-18's
//   classes made with the original's devices; a hand-in of several files graded as a class
//   (issue 57); a program that dies at import gets 0 in every exercise; clock waits as sleeps.
#include "test_support.hpp"

#include <aula/belief_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <cmath>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <optional>
#include <regex>
#include <string>
#include <vector>

using namespace std::chrono_literals;
using aula::testing::jsonNumber;
using aula::testing::readFile;

namespace {

namespace fs = std::filesystem;

const std::string kPython = std::string(AULA_TEST_DATA_DIR) + "/python/";

struct PyRun {
  std::optional<int> code;
  std::string output;  // stderr, then stdout
  std::string report;  // "" when none was written
};

PyRun runHeadless(const std::string& exercise, const std::string& algorithm, std::vector<std::string> extra = {},
                std::chrono::seconds limit = 90s) {
  const std::string report = aula::testing::privateDir() + "/report.json";
  std::vector<std::string> argv = {std::string(AULA_BIN_DIR) + "/aula", "run", exercise, "--headless",
                                   "--algorithm=" + algorithm, "--report=" + report,
                                   "--lcm-url=" + aula::testing::privateLcmUrl()};
  argv.insert(argv.end(), extra.begin(), extra.end());
  const aula::testing::Outcome outcome = aula::testing::runToEnd(argv, limit);
  return {outcome.code, outcome.output, fs::exists(report) ? readFile(report) : ""};
}

std::string describe(const PyRun& run) {
  return "exit " + (run.code ? std::to_string(*run.code) : std::string("(none: still running)")) + "\n--- output:\n" +
         run.output + "--- report:\n" + run.report;
}

std::optional<std::string> jsonString(const std::string& json, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(json, m, std::regex("\"" + key + "\": \"((?:[^\"\\\\]|\\\\.)*)\""))) return std::nullopt;
  return m[1].str();
}

// The report without its "algorithm" line: what must not depend on the language.
std::string withoutAlgorithmName(const std::string& report) {
  return std::regex_replace(report, std::regex("\n *\"algorithm\": \"[^\"]*\",?"), "");
}

// A Python fault ends a 20 s vacuum run early: `message` on stderr (the component's line) and
// as the report's algorithm_error.
void expectPythonFault(const PyRun& run, const std::string& message) {
  ASSERT_TRUE(run.code.has_value()) << describe(run);
  EXPECT_NE(*run.code, 0) << describe(run);
  EXPECT_NE(run.output.find("vacuum-cleaner: the student's algorithm failed: " + message), std::string::npos)
      << "expected on stderr: " << message << "\n" << describe(run);
  ASSERT_FALSE(run.report.empty()) << describe(run);
  const auto error = jsonString(run.report, "algorithm_error");
  ASSERT_TRUE(error.has_value()) << describe(run);
  EXPECT_EQ(error->rfind(message, 0), 0u) << "algorithm_error: " << *error << "\nexpected it to start with: " << message;
  EXPECT_NE(run.report.find("\"finished\": false"), std::string::npos) << describe(run);
}

const std::vector<std::string> kShortVacuum = {"--Vacuum.Referee.Duration=20"};

}  // namespace

// One API, two languages: the vacuum bounce (no random draw) in C++ and in Python, 900 s each.
TEST(PythonAlgorithms, VacuumBouncePortEarnsTheCppReportByteForByte) {
  const PyRun cpp = runHeadless("vacuum", AULA_PLUGIN_VACUUM_BOUNCE, {"--seed=3"});
  const PyRun python = runHeadless("vacuum", kPython + "vacuum_bounce/MyAlgorithm.py", {"--seed=3"});
  ASSERT_EQ(cpp.code.value_or(-1), 0) << describe(cpp);
  ASSERT_EQ(python.code.value_or(-1), 0) << describe(python);
  EXPECT_NE(python.report.find("\"algorithm\": \"MyAlgorithm.py\""), std::string::npos) << python.report;
  // A bounce that moves and bumps: the comparison is not between two robots standing still.
  EXPECT_GT(jsonNumber(cpp.report, "coverage_percent"), 5.0) << cpp.report;
  EXPECT_GT(jsonNumber(cpp.report, "bumps"), 0.0) << cpp.report;
  EXPECT_EQ(withoutAlgorithmName(python.report), withoutAlgorithmName(cpp.report));
}

// TeleTaxi: the grid's wave and path (field and map as numpy arrays over the C++ grid), then
// the path followed to the destination.
TEST(PythonAlgorithms, TeletaxiPathFollowerPortEarnsTheCppReportByteForByte) {
  const std::vector<std::string> trip = {"--TeleTaxi.Destination=220,240"};
  const PyRun cpp = runHeadless("teletaxi", AULA_PLUGIN_TELETAXI_FOLLOW, trip);
  const PyRun python = runHeadless("teletaxi", kPython + "teletaxi_follow/MyAlgorithm.py", trip);
  ASSERT_EQ(cpp.code.value_or(-1), 0) << describe(cpp);
  ASSERT_EQ(python.code.value_or(-1), 0) << describe(python);
  EXPECT_NE(python.report.find("\"algorithm\": \"MyAlgorithm.py\""), std::string::npos) << python.report;
  EXPECT_GT(jsonNumber(cpp.report, "mark"), 0.0) << cpp.report;  // it drove somewhere
  EXPECT_EQ(withoutAlgorithmName(python.report), withoutAlgorithmName(cpp.report));
}

// Slow but correct: 1.5 s of CPU at load (its imports) and 3 s in generatePath(), with the
// default budgets (CPU time, never wall time): the fast planner's report, byte for byte.
TEST(PythonAlgorithms, ASlowButCorrectPlannerEarnsTheFastOnesReport) {
  const std::vector<std::string> trip = {"--TeleTaxi.Destination=220,240"};
  const PyRun fast = runHeadless("teletaxi", kPython + "teletaxi_follow/MyAlgorithm.py", trip);
  const PyRun slow = runHeadless("teletaxi", kPython + "teletaxi_slow/MyAlgorithm.py", trip, 600s);
  ASSERT_EQ(slow.code.value_or(-1), 0) << describe(slow);
  EXPECT_GT(jsonNumber(slow.report, "mark"), 0.0) << slow.report;
  EXPECT_EQ(slow.report, fast.report);
}

// Autopark: the slot found with the right laser, two reversing arcs, centred with the front and
// rear lasers (the mounts, the car's size and the status line read and written too).
TEST(PythonAlgorithms, AutoparkReverseParkPortEarnsTheCppReportByteForByte) {
  const PyRun cpp = runHeadless("autopark", AULA_PLUGIN_AUTOPARK_REVERSE);
  const PyRun python = runHeadless("autopark", kPython + "autopark_reverse/MyAlgorithm.py");
  ASSERT_EQ(cpp.code.value_or(-1), 0) << describe(cpp);
  ASSERT_EQ(python.code.value_or(-1), 0) << describe(python);
  EXPECT_NE(python.report.find("\"algorithm\": \"MyAlgorithm.py\""), std::string::npos) << python.report;
  EXPECT_NE(cpp.report.find("\"parked\": true"), std::string::npos) << cpp.report;  // it went into the slot
  EXPECT_EQ(withoutAlgorithmName(python.report), withoutAlgorithmName(cpp.report));
}

// A Python run recorded and graded again from the log alone: the same report, byte for byte.
TEST(PythonAlgorithms, RecordedRunRegradesToTheSameReport) {
  const std::string dir = aula::testing::privateDir();
  const PyRun live = runHeadless("vacuum", kPython + "vacuum_bounce/MyAlgorithm.py",
                                 {"--Vacuum.Referee.Duration=120", "--record=" + dir + "/run.lcmlog"});
  ASSERT_EQ(live.code.value_or(-1), 0) << describe(live);
  const aula::testing::Outcome again = aula::testing::runToEnd(
      {std::string(AULA_BIN_DIR) + "/aula", "regrade", dir + "/run.lcmlog", "--report=" + dir + "/again.json"});
  ASSERT_EQ(again.code.value_or(-1), 0) << again.output;
  EXPECT_EQ(readFile(dir + "/again.json"), live.report);
}

TEST(PythonAlgorithms, SyntaxErrorNamesTheLine) {
  const PyRun run = runHeadless("vacuum", kPython + "syntax_error/MyAlgorithm.py", kShortVacuum);
  expectPythonFault(run, "MyAlgorithm.py:7: SyntaxError: ");
  EXPECT_NE(run.output.find("(`if self.calls = 3:`)"), std::string::npos) << describe(run);
  EXPECT_EQ(jsonNumber(run.report, "sim_time_s"), 0.0) << describe(run);
}

TEST(PythonAlgorithms, ExceptionGivesTheTracebackInTheStudentsLines) {
  const PyRun run = runHeadless("vacuum", kPython + "raises/MyAlgorithm.py", kShortVacuum);
  expectPythonFault(run, "MyAlgorithm.py:8: ZeroDivisionError: float division by zero (traceback, most recent call "
                         "last: MyAlgorithm.py:18 in execute: `api.motors.sendV(self.speed(api))`; MyAlgorithm.py:8 "
                         "in speed: `return 1.0 / remaining`)");
  EXPECT_GT(jsonNumber(run.report, "sim_time_s"), 0.0) << describe(run);
  EXPECT_LT(jsonNumber(run.report, "sim_time_s"), 20.0) << describe(run);
}

// A MyAlgorithm.py tells its belief (api.belief) as C++ does: its pose after every call and its
// map (a numpy array) reach the run's log; a map of the wrong shape is the student's error, in
// their line.
TEST(PythonAlgorithms, TheBeliefReachesTheLogAndABadMapIsTheStudentsError) {
  const std::string recorded = aula::testing::privateDir() + "/belief.lcmlog";
  const PyRun run =
      runHeadless("vacuum", kPython + "belief/MyAlgorithm.py", {"--Vacuum.Referee.Duration=20", "--record=" + recorded});
  expectPythonFault(run, "MyAlgorithm.py:23: ValueError: Belief.setMap: cells must be a 2-D array (rows of y, columns of x)");
  lcm::LogFile in(recorded, "r");
  ASSERT_TRUE(in.good()) << recorded;
  int poses = 0, maps = 0;
  double last_x_m = 0, last_y_m = 0;
  for (const lcm::LogEvent* e = in.readNextEvent(); e != nullptr; e = in.readNextEvent()) {
    aula::belief_t belief{};
    if (e->channel != "VACUUM_BELIEF" || belief.decode(e->data, 0, e->datalen) <= 0) continue;
    ++poses;
    last_x_m = belief.x_m;
    last_y_m = belief.y_m;
    if (belief.map_width == 0) continue;
    ++maps;
    EXPECT_EQ(belief.map_width, 4);
    EXPECT_EQ(belief.map_height, 3);
    EXPECT_DOUBLE_EQ(belief.map_origin_y_m, -0.75);
    EXPECT_EQ(belief.map_cells, std::vector<uint8_t>(12, 128));
  }
  EXPECT_EQ(poses, 49) << "one belief after each call that returned";
  EXPECT_EQ(maps, 1);
  EXPECT_NEAR(std::hypot(last_x_m, last_y_m), 49 * 0.2 * 0.08, 0.05);  // its own odometry, straight ahead
}

// The execute budget raises inside the loop (even past `except Exception`): the run goes on to
// its report with the loop's line, instead of the process being ended.
TEST(PythonAlgorithms, EndlessLoopIsInterruptedAtItsLine) {
  const PyRun run = runHeadless("vacuum", kPython + "endless_loop/MyAlgorithm.py",
                              {"--Vacuum.Referee.Duration=20", "--Component.ExecuteBudget=1"}, 300s);
  ASSERT_TRUE(run.code.has_value()) << "the run hung\n" << describe(run);
  const auto error = jsonString(run.report, "algorithm_error");
  ASSERT_TRUE(error.has_value()) << describe(run);
  EXPECT_TRUE(std::regex_search(*error, std::regex("^MyAlgorithm\\.py:1[12]: execute\\(\\) used more than 1 s of CPU time "
                                                   "\\(an endless loop\\?\\) \\(Component\\.ExecuteBudget\\): interrupted here")))
      << *error;
  expectPythonFault(run, "MyAlgorithm.py:1");
  EXPECT_EQ(run.report.find("\"aborted\""), std::string::npos) << describe(run);
}

TEST(PythonAlgorithms, NanCommandsAreRefusedAndCounted) {
  const PyRun run = runHeadless("vacuum", kPython + "nan_commands/MyAlgorithm.py", kShortVacuum);
  ASSERT_EQ(run.code.value_or(-1), 0) << describe(run);
  EXPECT_GT(jsonNumber(run.report, "non_finite_commands"), 0.0) << describe(run);
  EXPECT_LT(jsonNumber(run.report, "coverage_percent"), 0.5) << describe(run);
  EXPECT_NE(run.output.find("not a finite number"), std::string::npos) << describe(run);
}

TEST(PythonAlgorithms, MissingImportNamesTheModule) {
  const PyRun run = runHeadless("vacuum", kPython + "missing_import/MyAlgorithm.py", kShortVacuum);
  expectPythonFault(run, "MyAlgorithm.py:2: ModuleNotFoundError: no module named 'pandas'");
}

// A file that is not there is refused at once, like a missing plugin (exit 2).
TEST(PythonAlgorithms, MissingFileIsRefusedAtOnce) {
  const std::string missing = aula::testing::privateDir() + "/MyAlgorithm.py";
  const PyRun run = runHeadless("vacuum", missing, kShortVacuum);
  EXPECT_EQ(run.code.value_or(-1), 2) << describe(run);
  EXPECT_NE(run.output.find(missing + ": no such file"), std::string::npos) << describe(run);
}

// The same seed, the same report; another seed, other draws. And the student's environment
// (PYTHONPATH with a numpy that would fail, user site-packages) never reaches the interpreter.
TEST(PythonAlgorithms, SeededAndIsolatedFromTheEnvironment) {
  const std::string file = kPython + "seeded_random/MyAlgorithm.py";
  const PyRun first = runHeadless("vacuum", file, {"--seed=5", "--Vacuum.Referee.Duration=60"});
  const std::string shadow = aula::testing::privateDir();
  fs::create_directories(shadow + "/numpy");
  std::ofstream(shadow + "/numpy/__init__.py") << "raise ImportError('the PYTHONPATH numpy was imported')\n";
  ::setenv("PYTHONPATH", shadow.c_str(), 1);
  ::setenv("PYTHONUSERBASE", shadow.c_str(), 1);
  const PyRun again = runHeadless("vacuum", file, {"--seed=5", "--Vacuum.Referee.Duration=60"});
  ::unsetenv("PYTHONPATH");
  ::unsetenv("PYTHONUSERBASE");
  const PyRun other = runHeadless("vacuum", file, {"--seed=6", "--Vacuum.Referee.Duration=60"});
  ASSERT_EQ(first.code.value_or(-1), 0) << describe(first);
  ASSERT_EQ(again.code.value_or(-1), 0) << describe(again);
  ASSERT_EQ(other.code.value_or(-1), 0) << describe(other);
  EXPECT_EQ(again.report, first.report);
  EXPECT_NE(jsonNumber(other.report, "coverage_percent"), jsonNumber(first.report, "coverage_percent"))
      << first.report << other.report;
}

// The shipped .pyi stubs name exactly what each exercise's module binds (checked inside Aula's
// Python: tests/data/python/stubs_match), every exercise makes MyAlgorithm with the run's seed
// (TeleTaxi's generatePath() first too), and the templates run as shipped.
TEST(PythonAlgorithms, StubsNameExactlyWhatEachExerciseBindsAndTemplatesRun) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> exercises = {
      {"vacuum", {"--seed=7", "--Vacuum.Referee.Duration=5"}},
      {"teletaxi", {"--seed=7", "--TeleTaxi.Destination=220,240", "--TeleTaxi.Referee.Timeout=5"}},
      {"autopark", {"--seed=7", "--Autopark.Referee.Timeout=5"}}};
  for (const auto& [exercise, options] : exercises) {
    const PyRun stubs = runHeadless(exercise, kPython + "stubs_match/MyAlgorithm.py", options);
    EXPECT_NE(stubs.output.find("stubs match: aula_" + exercise), std::string::npos) << describe(stubs);
    EXPECT_NE(stubs.output.find("MyAlgorithm(seed=7)"), std::string::npos) << describe(stubs);
    EXPECT_FALSE(jsonString(stubs.report, "algorithm_error").has_value()) << describe(stubs);
    const PyRun shipped =
        runHeadless(exercise, std::string(AULA_SOURCE_DIR) + "/components/" + exercise + "/student/MyAlgorithm.py", options);
    EXPECT_FALSE(shipped.report.empty()) << describe(shipped);
    EXPECT_FALSE(jsonString(shipped.report, "algorithm_error").has_value()) << describe(shipped);
  }
}

// Programs written to today's RoboticsAcademy pages (`import HAL`, `import GUI`, top-level code,
// `while True:`, `time.time()` timers, `time.sleep()`), unchanged (issue 41): each exercise's does
// its job, with the marks it reaches; the same seed, the same report; the clock and the pacing in
// both shapes of program; what Aula's world lacks is said in the student's line; `aula grade`.
namespace {
void expectCleanRun(const PyRun& run) {
  ASSERT_EQ(run.code.value_or(-1), 0) << describe(run);
  EXPECT_EQ(run.report.find("algorithm_error"), std::string::npos) << describe(run);
  EXPECT_NE(run.report.find("\"algorithm\": \"MyAlgorithm.py\""), std::string::npos) << run.report;
}
}  // namespace

// The vacuum with time.time() timers (spiral 40 s, back 0.6 s, turn 0.8-2.4 s from `random`):
// its 900 s without an error, the same report twice for one seed. Measured: 33.33 %, mark 4.17.
TEST(RoboticsAcademyPrograms, VacuumWithTimersRunsIts900SecondsTheSameTwice) {
  const PyRun first = runHeadless("vacuum", kPython + "ra_vacuum/MyAlgorithm.py", {"--seed=1"});
  const PyRun second = runHeadless("vacuum", kPython + "ra_vacuum/MyAlgorithm.py", {"--seed=1"});
  expectCleanRun(first);
  expectCleanRun(second);
  EXPECT_NE(first.report.find("\"finished\": true"), std::string::npos) << first.report;
  EXPECT_GT(jsonNumber(first.report, "coverage_percent"), 15.0) << first.report;
  EXPECT_GT(jsonNumber(first.report, "bumps"), 0.0) << first.report;  // its timers ran: it backed off and turned
  EXPECT_EQ(first.report, second.report);
  // What it printed, with its sim-time stamps, on the component's output.
  EXPECT_NE(first.output.find("started at 00:00:"), std::string::npos) << first.output;
  EXPECT_NE(first.output.find(", backing off, then turning "), std::string::npos) << first.output;
}

// TeleTaxi: a wavefront planner on GUI.getMap / getTargetPose / worldToGrid, its path shown with
// GUI.showPath and followed with HAL.getPose3d: it reaches the destination.
TEST(RoboticsAcademyPrograms, TeletaxiWavefrontReachesTheDestination) {
  const PyRun run = runHeadless("teletaxi", kPython + "ra_teletaxi/MyAlgorithm.py", {"--seed=1"});
  expectCleanRun(run);
  EXPECT_NE(run.report.find("\"reached\": true"), std::string::npos) << describe(run);
  EXPECT_GE(jsonNumber(run.report, "mark"), 8.0) << run.report;
  EXPECT_NE(run.output.find("wave reached the taxi: True"), std::string::npos) << run.output;
}

// Autopark: a state machine on HAL.getRightLaserData / getFrontLaserData / getBackLaserData and
// getPose3d, with a time.time() pause: it parks.
TEST(RoboticsAcademyPrograms, AutoparkStateMachineParks) {
  const PyRun run = runHeadless("autopark", kPython + "ra_autopark/MyAlgorithm.py", {"--seed=1"});
  expectCleanRun(run);
  EXPECT_NE(run.report.find("\"parked\": true"), std::string::npos) << describe(run);
  EXPECT_GE(jsonNumber(run.report, "mark"), 7.0) << run.report;
  EXPECT_NE(run.output.find("slot found: "), std::string::npos) << run.output;
}

// Issue 54: RA's street as RA's programs see it. A gap finder that knows RA's numbers only (the
// right laser's beams read inf beyond the parked cars, since no beam sees the curb), then a fixed
// manoeuvre timed on the clock: it parks, and the same run twice gives the same report.
TEST(RoboticsAcademyPrograms, AutoparkGapFinderOnInfParksOnRasStreet) {
  const PyRun first = runHeadless("autopark", kPython + "ra_gap_finder/MyAlgorithm.py", {"--seed=1"});
  expectCleanRun(first);
  EXPECT_NE(first.report.find("\"parked\": true"), std::string::npos) << describe(first);
  EXPECT_GE(jsonNumber(first.report, "mark"), 5.0) << first.report;
  EXPECT_NE(first.output.find("gap: inf from x = "), std::string::npos) << first.output;
  const PyRun second = runHeadless("autopark", kPython + "ra_gap_finder/MyAlgorithm.py", {"--seed=1"});
  EXPECT_EQ(first.report, second.report);
}

// A planner that hard-codes RA's map constants (cell = (y + 250) * 400 / 500 for the column, the
// row from x) on GUI.getMap's picture, not GUI.worldToGrid: its path lies on the streets, it arrives.
TEST(RoboticsAcademyPrograms, TeletaxiPlannerOnRasMapConstantsArrives) {
  const PyRun run = runHeadless("teletaxi", kPython + "ra_constants_teletaxi/MyAlgorithm.py", {"--seed=1"});
  expectCleanRun(run);
  EXPECT_NE(run.report.find("\"reached\": true"), std::string::npos) << describe(run);
  EXPECT_EQ(jsonNumber(run.report, "bumps"), 0.0) << run.report;  // its path kept to the streets
  EXPECT_NE(run.output.find("(by RA's constants)"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("arrived, "), std::string::npos) << run.output;
}

// The clock is the simulator's and the pacing as documented, in RoboticsAcademy's shape (sleep,
// a second HAL read, a busy wait on time.time(), datetime) and in Aula's (time.time() is
// api.time_s(), a sleep inside execute() waits in sim time). Each program raises if not.
TEST(RoboticsAcademyPrograms, TheClockIsTheSimulatorsInBothShapes) {
  const PyRun program = runHeadless("vacuum", kPython + "ra_clock/MyAlgorithm.py", kShortVacuum, 120s);
  expectCleanRun(program);
  EXPECT_NE(program.output.find("CLOCK OK at "), std::string::npos) << describe(program);
  const PyRun classic = runHeadless("vacuum", kPython + "clock_in_execute/MyAlgorithm.py", kShortVacuum, 120s);
  expectCleanRun(classic);
  EXPECT_NE(classic.output.find("EXECUTE CLOCK OK"), std::string::npos) << describe(classic);
}

// HAL.getPose3d().x in the vacuum: the run stops at the student's line, saying what exists.
TEST(RoboticsAcademyPrograms, WhatTheVacuumLacksIsSaidAtTheStudentsLine) {
  const PyRun run = runHeadless("vacuum", kPython + "ra_no_position/MyAlgorithm.py", kShortVacuum, 120s);
  ASSERT_TRUE(run.code.has_value()) << describe(run);
  EXPECT_NE(*run.code, 0) << describe(run);
  EXPECT_NE(run.report.find("MyAlgorithm.py:7: AttributeError: HAL.getPose3d().x: the vacuum cleaner has no "
                            "localization in Aula: getPose3d() gives .yaw (rad) and .timeStamp (s) only"),
            std::string::npos)
      << describe(run);
}

// Under `aula grade`: the Autopark program as a student's submission, graded.
TEST(RoboticsAcademyPrograms, AutoparkProgramIsGradedByAulaGrade) {
  const fs::path dir = aula::testing::privateDir();
  fs::create_directories(dir / "class");
  fs::copy(kPython + "ra_autopark", dir / "class" / "ra_student", fs::copy_options::recursive);
  const aula::testing::Outcome graded =
      aula::testing::runToEnd({std::string(AULA_BIN_DIR) + "/aula", "grade", "autopark", (dir / "class" / "ra_student").string(),
                               "--seeds=1", "--out=" + (dir / "out").string()},
                              600s);
  ASSERT_EQ(graded.code.value_or(-1), 0) << graded.output;
  const std::string csv = readFile((dir / "out" / "grades.csv").string());
  ASSERT_NE(csv.find("ra_student,"), std::string::npos) << csv;
  const std::string result = readFile((dir / "out" / "runs" / "ra_student" / "autopark-seed1.json").string());
  EXPECT_NE(result.find("\"parked\": true"), std::string::npos) << result << "\n" << csv;
  EXPECT_NE(result.find("\"sandboxed\": true"), std::string::npos) << result;
  // What the program printed is kept beside its report, in the run's log. Measured: mark 10.00.
  const std::string log = readFile((dir / "out" / "runs" / "ra_student" / "autopark-seed1.log").string());
  EXPECT_NE(log.find("parked at ("), std::string::npos) << log;
  fs::remove_all(dir);
}

// Every generation of the course's program, in each exercise (issue 54): our own small programs in
// each shape (tests/data/python/README.md), each run twice. Each runs to the end of its episode
// without an error, drives (it is not a robot standing still), says what it printed, and the same
// seed gives the same report.
namespace {
struct ShapeRun {
  std::string folder;
  std::string printed;  // a line it prints, on the component's output
};

// `moved`: the report says the robot went somewhere (a program standing still would pass the rest).
void expectEachRunsToTheEndTheSameTwice(const std::string& exercise, const std::vector<ShapeRun>& programs,
                                        const std::vector<std::string>& options,
                                        const std::function<bool(const std::string&)>& moved) {
  for (const ShapeRun& program : programs) {
    SCOPED_TRACE(exercise + " " + program.folder);
    const PyRun first = runHeadless(exercise, kPython + program.folder + "/MyAlgorithm.py", options, 300s);
    const PyRun second = runHeadless(exercise, kPython + program.folder + "/MyAlgorithm.py", options, 300s);
    expectCleanRun(first);
    EXPECT_NE(first.output.find(program.printed), std::string::npos) << describe(first);
    EXPECT_TRUE(moved(first.report)) << first.report;
    EXPECT_EQ(first.report, second.report);
  }
}
}  // namespace

TEST(PythonShapes, VacuumProgramsOfEveryGenerationRunToTheEndTheSameTwice) {
  expectEachRunsToTheEndTheSameTwice("vacuum",
                                     {{"ra2021_vacuum", "ahead again at "},
                                      {"ra2025_vacuum", "following walls"},
                                      {"academy_vacuum", "call 100 at 8.00 s, yaw "}},
                                     {"--seed=2", "--Vacuum.Referee.Duration=60"}, [](const std::string& report) {
                                       return report.find("\"finished\": true") != std::string::npos &&
                                              jsonNumber(report, "coverage_percent") > 1.0;
                                     });
}

TEST(PythonShapes, AutoparkProgramsOfEveryGenerationRunToTheEndTheSameTwice) {
  expectEachRunsToTheEndTheSameTwice("autopark",
                                     {{"ra2021_autopark", "front beams"},
                                      {"ra2025_autopark", "closest on the right: "},
                                      {"academy_autopark", "stopped at x "}},
                                     {"--seed=1", "--Autopark.Referee.Timeout=30"}, [](const std::string& report) {
                                       return report.find("\"finished\": true") != std::string::npos &&
                                              report.find("\"case\": \"stayed_still\"") == std::string::npos;
                                     });
}

TEST(PythonShapes, TeletaxiProgramsOfEveryGenerationRunToTheEndTheSameTwice) {
  expectEachRunsToTheEndTheSameTwice("teletaxi",
                                     {{"ra2021_teletaxi", "a path of "},
                                      {"ra2025_teletaxi", " of a "},
                                      {"academy_teletaxi", "LOOKING FOR SHORTER PATH"}},
                                     {"--seed=1", "--TeleTaxi.Referee.Timeout=60"}, [](const std::string& report) {
                                       return jsonNumber(report, "path_length_m") > 10.0;
                                     });
}

// Dead at its import (line 4), in every exercise: mark 0, the reason in the report, whatever the
// exercise's rubric gives a robot that stays still (Autopark's NotParkedMark gave 1.00); its
// recorded run regrades to the same report.
TEST(PythonShapes, AProgramThatDiesAtImportGetsZeroInEveryExercise) {
  const std::vector<std::pair<std::string, std::string>> exercises = {
      {"vacuum", "--Vacuum.Referee.Duration=20"},
      {"teletaxi", "--TeleTaxi.Referee.Timeout=20"},
      {"autopark", "--Autopark.Referee.Timeout=20"}};
  for (const auto& [exercise, option] : exercises) {
    const std::string recorded = aula::testing::privateDir() + "/" + exercise + ".lcmlog";
    const PyRun run = runHeadless(exercise, kPython + "dies_at_import/MyAlgorithm.py", {option, "--record=" + recorded});
    ASSERT_FALSE(run.report.empty()) << exercise << "\n" << describe(run);
    EXPECT_EQ(jsonNumber(run.report, "mark"), 0.0) << exercise << "\n" << describe(run);
    const auto error = jsonString(run.report, "algorithm_error");
    ASSERT_TRUE(error.has_value()) << exercise << "\n" << describe(run);
    EXPECT_EQ(error->rfind("MyAlgorithm.py:4: ZeroDivisionError: float division by zero", 0), 0u) << *error;
    EXPECT_NE(run.report.find("\"mark_note\": \"0: the student's algorithm failed before the robot moved"),
              std::string::npos)
        << exercise << "\n" << run.report;
    // Graded again from its log alone: the same 0, for the same reason.
    const aula::testing::Outcome again = aula::testing::runToEnd(
        {std::string(AULA_BIN_DIR) + "/aula", "regrade", recorded, "--report=" + recorded + ".json"});
    EXPECT_EQ(again.code, run.code) << again.output;  // a run that ended early, both times
    EXPECT_EQ(readFile(recorded + ".json"), run.report) << exercise;
  }
}

// A hand-in of several files (issue 57): MyAlgorithm imported from a module beside it, or a class
// MyAlgorithm subclassing one from a module beside it, is graded as a class: it drives.
TEST(PythonShapes, AHandInOfSeveralFilesIsGradedAsAClass) {
  const PyRun imported = runHeadless("vacuum", kPython + "multi_file_import/MyAlgorithm.py", {"--Vacuum.Referee.Duration=60"});
  expectCleanRun(imported);
  EXPECT_NE(imported.output.find("Cleaner made with seed "), std::string::npos) << describe(imported);
  EXPECT_GT(jsonNumber(imported.report, "coverage_percent"), 1.0) << imported.report;
  const PyRun subclass = runHeadless("vacuum", kPython + "multi_file_subclass/MyAlgorithm.py", {"--Vacuum.Referee.Duration=60"});
  expectCleanRun(subclass);
  EXPECT_NE(subclass.output.find("MyAlgorithm(Cleaner): 100 calls"), std::string::npos) << describe(subclass);
  EXPECT_GT(jsonNumber(subclass.report, "coverage_percent"), 1.0) << subclass.report;
}

// Under `aula grade` (sandboxed, the submission's .py files copied): the two-file hand-in is a class.
TEST(PythonShapes, AHandInOfSeveralFilesIsGradedAsAClassByAulaGrade) {
  const fs::path dir = aula::testing::privateDir();
  fs::create_directories(dir / "class");
  fs::copy(kPython + "multi_file_import", dir / "class" / "two_files", fs::copy_options::recursive);
  const aula::testing::Outcome graded = aula::testing::runToEnd(
      {std::string(AULA_BIN_DIR) + "/aula", "grade", "vacuum", (dir / "class" / "two_files").string(), "--seeds=1",
       "--calibration-seeds=off", "--similarity=off", "--Vacuum.Referee.Duration=60", "--out=" + (dir / "out").string()},
      600s);
  ASSERT_EQ(graded.code.value_or(-1), 0) << graded.output;
  const std::string result = readFile((dir / "out" / "runs" / "two_files" / "vacuum-seed1.json").string());
  EXPECT_EQ(result.find("algorithm_error"), std::string::npos) << result;
  EXPECT_NE(result.find("\"sandboxed\": true"), std::string::npos) << result;
  EXPECT_GT(jsonNumber(result, "coverage_percent"), 1.0) << result;
  fs::remove_all(dir);
}

// A file with neither a class nor a loop is told why it got 0.
TEST(PythonShapes, AFileWithNeitherAClassNorALoopIsToldWhyItGotZero) {
  const PyRun run = runHeadless("vacuum", kPython + "nothing_to_run/MyAlgorithm.py", kShortVacuum);
  expectPythonFault(run, "MyAlgorithm.py: the file ran to its end in its first call and never waited for the simulator: "
                         "it has neither a class MyAlgorithm");
  EXPECT_NE(run.report.find("It defines execute(): put it in class MyAlgorithm"), std::string::npos) << run.report;
  EXPECT_EQ(jsonNumber(run.report, "mark"), 0.0) << run.report;
}

// Waiting on time.perf_counter() is a time.sleep on Aula: the same run, byte for byte.
TEST(PythonShapes, APerfCounterTimedProgramBehavesAsItsSleepTwin) {
  const std::vector<std::string> options = {"--seed=4", "--Vacuum.Referee.Duration=120"};
  const PyRun busy = runHeadless("vacuum", kPython + "busy_wait_twin/MyAlgorithm.py", options);
  const PyRun sleeping = runHeadless("vacuum", kPython + "sleep_twin/MyAlgorithm.py", options);
  expectCleanRun(busy);
  expectCleanRun(sleeping);
  EXPECT_GT(jsonNumber(sleeping.report, "coverage_percent"), 1.0) << sleeping.report;
  EXPECT_EQ(busy.report, sleeping.report);
}

// Errors that teach: a name RoboticsAcademy's HAL has and this exercise's lacks, imported; a module
// in other letters; Python 2's print; a module Debian packages.
TEST(PythonShapes, ImportMistakesSayWhatAulaOffers) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"teach_import_name", "MyAlgorithm.py:3: ImportError: HAL.getFrontLaserData: not in Aula's HAL for this exercise; "
                            "it has getLaserData()"},
      {"teach_module_case", "MyAlgorithm.py:2: ModuleNotFoundError: no module named 'hal' (Aula's is `HAL`, in these "
                            "letters"},
      {"teach_python2", "MyAlgorithm.py:5: SyntaxError: Missing parentheses in call to 'print'."},
      {"missing_import", "MyAlgorithm.py:2: ModuleNotFoundError: no module named 'pandas' (it is Debian's python3-pandas)"}};
  for (const auto& [folder, message] : cases) {
    const PyRun run = runHeadless("vacuum", kPython + folder + "/MyAlgorithm.py", kShortVacuum);
    expectPythonFault(run, message);
  }
}

// The algorithm's own process has the sandbox's memory limit in every run, a plain `aula run`
// too (issue 57: a runaway Python program took 9.7 GB before the machine killed it): 3 GB in one
// bytearray is refused under a 512 MB limit, and the fault says so in the sandbox's words.
TEST(PythonAlgorithms, APlainRunHasTheSandboxsMemoryLimit) {
  const fs::path dir = aula::testing::privateDir();
  std::ofstream(dir / "MyAlgorithm.py") << "class MyAlgorithm:\n"
                                           "    def __init__(self, seed):\n"
                                           "        self.block = None\n\n"
                                           "    def execute(self, api):\n"
                                           "        self.block = bytearray(3 * 1024 ** 3)\n";
  const PyRun run = runHeadless("vacuum", (dir / "MyAlgorithm.py").string(),
                                {"--Vacuum.Referee.Duration=20", "--Component.Sandbox.Memory=512"});
  EXPECT_NE(run.report.find("the algorithm used more than 512 MB of memory"), std::string::npos) << describe(run);
  EXPECT_NE(run.report.find("\"finished\": false"), std::string::npos) << describe(run);
}
