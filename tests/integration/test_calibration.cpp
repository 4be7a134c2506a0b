// aula calibrate (issue 27): on a generated house, the rubric it writes beside the world puts the
// random-bounce baseline's median at a 5 and the reference's at a 10, and aula run applies it
// (unless told the fixed rubric); a calibration for another version of the world is refused.
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

using namespace std::chrono_literals;
using aula::testing::jsonNumber;
using aula::testing::readFile;
using aula::testing::runToEnd;

namespace {

const std::string kAula = std::string(AULA_BIN_DIR) + "/aula";
// A calibration is tens of whole runs: on a loaded machine (issue 38: a class graded beside other
// work) it takes what it takes. This is only the machine's backstop against a hang, well past
// what any load here has needed (120 s alone, under 400 s beside four busy loops).
constexpr auto kBackstop = std::chrono::seconds(1200);

std::string makeHouse(const std::string& dir, std::vector<std::string> args) {
  std::vector<std::string> command = {AULA_PYTHON, std::string(AULA_SOURCE_DIR) + "/worlds/tools/make_house.py", "--out",
                                      dir + "/house.world"};
  command.insert(command.end(), args.begin(), args.end());
  const auto made = runToEnd(command, 30s);
  EXPECT_EQ(made.code.value_or(-1), 0) << made.output;
  return dir + "/house.world";
}

double medianMark(const std::string& dir, const std::string& world, const std::string& algorithm) {
  std::vector<double> marks;
  for (int seed = 1; seed <= 5; ++seed) {
    const std::string report = dir + "/" + algorithm + "-" + std::to_string(seed) + ".json";
    const auto run = runToEnd({kAula, "run", "vacuum", "--headless", "--world=" + world, "--algorithm=" + algorithm,
                               "--seed=" + std::to_string(seed), "--report=" + report,
                               "--lcm-url=" + aula::testing::privateLcmUrl()},
                              120s);
    EXPECT_EQ(run.code.value_or(-1), 0) << run.output;
    const std::string json = readFile(report);
    EXPECT_NE(json.find("\"calibration\": \"house.rubric.cfg\""), std::string::npos) << json;
    marks.push_back(jsonNumber(json, "mark"));
  }
  std::sort(marks.begin(), marks.end());
  return marks[2];
}

struct House {
  const char* name;
  std::vector<std::string> args;
};

void PrintTo(const House& house, std::ostream* out) { *out << house.name; }  // ctest's name, not its bytes

class CalibratedHouse : public ::testing::TestWithParam<House> {};

}  // namespace

TEST_P(CalibratedHouse, TheBaselineIsWorthAFiveAndTheReferenceATen) {
  const std::string dir = aula::testing::privateDir();
  const std::string world = makeHouse(dir, GetParam().args);
  const auto calibrated = runToEnd({kAula, "calibrate", "vacuum", "--world=" + world, "--seeds=1-5", "--jobs=1",
                                    "--out=" + dir + "/calibration"},
                                   kBackstop);
  ASSERT_EQ(calibrated.code.value_or(-1), 0) << calibrated.output;
  const std::string file = readFile(dir + "/house.rubric.cfg");
  EXPECT_NE(file.find("Calibration.Baseline = bounce"), std::string::npos) << file;
  EXPECT_NE(file.find("Calibration.Anchor = reference"), std::string::npos) << file;
  EXPECT_NE(file.find("Vacuum.Referee.HalfMarkCoverage = "), std::string::npos) << file;
  const double baseline = medianMark(dir, world, "bounce"), reference = medianMark(dir, world, "reference");
  EXPECT_NEAR(baseline, 5.0, 0.5) << file;
  EXPECT_GE(reference, 9.5) << file;
}

INSTANTIATE_TEST_SUITE_P(
    GeneratedHouses, CalibratedHouse,
    ::testing::Values(House{"ThreeByTwo", {"--seed", "7"}},
                      House{"FourRoomsOtherStart", {"--seed", "11", "--rooms-x", "2", "--rooms-y", "2", "--room-size", "3.6",
                                                    "--start=1.5,1.5,1.0"}},
                      House{"FourInARowFurnished", {"--seed", "3", "--rooms-x", "4", "--rooms-y", "1", "--furniture", "3"}},
                      House{"TwoByThreeNarrowDoors", {"--seed", "21", "--rooms-x", "2", "--rooms-y", "3", "--door-width", "0.8"}}),
    [](const ::testing::TestParamInfo<House>& info) { return std::string(info.param.name); });

// The calibration file is the world's: aula config names it as the rubric's origin; the fixed
// preset ignores it; a changed world (its hash) or a key that is not the calibrated rubric is
// refused with exit 2, naming the file.
TEST(Calibration, IsAppliedNamedAndRefusedForAnotherVersionOfTheWorld) {
  const std::string dir = aula::testing::privateDir();
  const std::string world = makeHouse(dir, {"--seed", "5", "--rooms-x", "2", "--rooms-y", "1"});
  const auto calibrated = runToEnd({kAula, "calibrate", "vacuum", "--world=" + world, "--seeds=1", "--jobs=1",
                                    "--out=" + dir + "/calibration"}, kBackstop);
  ASSERT_EQ(calibrated.code.value_or(-1), 0) << calibrated.output;
  const std::string rubric_file = dir + "/house.rubric.cfg";
  const auto config = runToEnd({kAula, "config", "vacuum", "--world=" + world});
  ASSERT_EQ(config.code.value_or(-1), 0) << config.output;
  EXPECT_NE(config.output.find("[calibration " + rubric_file + ":"), std::string::npos) << config.output;
  EXPECT_EQ(config.output.find("HalfMarkCoverage = 40 %"), std::string::npos) << config.output;
  const auto fixed = runToEnd({kAula, "config", "vacuum", "--world=" + world, "--Vacuum.Referee.Rubric=fixed"});
  EXPECT_NE(fixed.output.find("HalfMarkCoverage = 40 %"), std::string::npos) << fixed.output;

  const std::string text = readFile(rubric_file);
  std::ofstream(rubric_file, std::ios::app) << "Vacuum.MaxV = 0.7\n";
  const auto foreign_key = runToEnd({kAula, "config", "vacuum", "--world=" + world});
  EXPECT_EQ(foreign_key.code.value_or(-1), 2) << foreign_key.output;
  EXPECT_NE(foreign_key.output.find(rubric_file + ":"), std::string::npos) << foreign_key.output;
  EXPECT_NE(foreign_key.output.find("'Vacuum.MaxV' is not a calibrated rubric setting"), std::string::npos)
      << foreign_key.output;

  // The calibration records what a run can reach besides the world (issue 38): a run with
  // other noise, another episode length or other speed limits is refused before it starts.
  std::ofstream(rubric_file, std::ios::trunc) << text;
  EXPECT_NE(text.find("Calibration.Setting.Vacuum.Referee.Duration = 900\n"), std::string::npos) << text;
  EXPECT_NE(text.find("Calibration.Setting.Simulator.Noise.WheelSlip = 0\n"), std::string::npos) << text;
  const std::vector<std::pair<std::string, std::string>> unfit = {
      {"--Simulator.Noise=realistic", "calibrated for Simulator.Noise.LaserStddev = 0, and this run's is 0.01 (preset realistic"},
      {"--Vacuum.Referee.Duration=120", "calibrated for Vacuum.Referee.Duration = 900, and this run's is 120 (command line"},
      {"--Vacuum.MaxW=2", "calibrated for Vacuum.MaxW = 3.0, and this run's is 2 (command line"}};
  for (const auto& [setting, said] : unfit) {
    const auto refused = runToEnd({kAula, "run", "vacuum", "--headless", "--world=" + world, setting});
    EXPECT_EQ(refused.code.value_or(-1), 2) << setting << ": " << refused.output;
    EXPECT_NE(refused.output.find(rubric_file + ":"), std::string::npos) << refused.output;
    EXPECT_NE(refused.output.find(said), std::string::npos) << refused.output;
  }
  // A file made before Aula recorded a setting counts as made with the shipped value.
  std::string unrecorded;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("Calibration.Setting.", 0) != 0) unrecorded += line + "\n";
  }
  std::ofstream(rubric_file, std::ios::trunc) << unrecorded;
  EXPECT_EQ(runToEnd({kAula, "config", "vacuum", "--world=" + world}).code.value_or(-1), 0);
  const auto old_file = runToEnd({kAula, "config", "vacuum", "--world=" + world, "--Vacuum.MaxV=0.3"});
  EXPECT_EQ(old_file.code.value_or(-1), 2) << old_file.output;
  EXPECT_NE(old_file.output.find("made before Aula recorded Vacuum.MaxV: the shipped value): calibrated for Vacuum.MaxV = 0.5"),
            std::string::npos)
      << old_file.output;

  std::ofstream(rubric_file, std::ios::trunc) << text;
  std::ofstream(world, std::ios::app) << "<!-- a wall moved -->\n";
  const auto stale = runToEnd({kAula, "run", "vacuum", "--headless", "--world=" + world, "--algorithm=bounce"});
  EXPECT_EQ(stale.code.value_or(-1), 2) << stale.output;
  EXPECT_NE(stale.output.find("calibrated for another version of " + world), std::string::npos) << stale.output;
}

namespace {

struct TaxiRun {
  double mark = 0, driving_time_s = 0;
};

// One headless TeleTaxi run on `world` to `destination`; `extra`: more options.
TaxiRun taxiRun(const std::string& dir, const std::string& world, const std::string& algorithm, const std::string& destination,
                const std::vector<std::string>& extra) {
  const std::string report = dir + "/taxi-" + std::to_string(std::hash<std::string>{}(algorithm + destination)) + ".json";
  std::vector<std::string> command = {kAula, "run", "teletaxi", "--headless", "--world=" + world, "--algorithm=" + algorithm,
                                      "--TeleTaxi.Destination=" + destination, "--report=" + report,
                                      "--lcm-url=" + aula::testing::privateLcmUrl()};
  command.insert(command.end(), extra.begin(), extra.end());
  const auto run = runToEnd(command, 120s);
  EXPECT_EQ(run.code.value_or(-1), 0) << run.output;
  const std::string json = readFile(report);
  return {jsonNumber(json, "mark"), jsonNumber(json, "driving_time_s")};
}

}  // namespace

// TeleTaxi's speed scale, calibrated per world and destination (issue 27): the fixed scale gives
// the reference and a plain BFS student that drives slower both 10.00 (their average speeds are
// far above its 2.6 m/s); calibrated on the reference's driving time to each destination, the
// slower student gets a lower mark than the reference on every destination. A calibration for
// another destination is refused.
TEST(CalibratedCity, AStudentSlowerThanTheReferenceGetsALowerMarkOnEveryDestination) {
  const std::string dir = aula::testing::privateDir();
  const std::string world = dir + "/city.world";
  std::filesystem::copy_file(std::string(AULA_SOURCE_DIR) + "/worlds/cityLarge.world", world);
  // The student: a breadth-first wave on the grid, followed at up to 6 m/s (tests/data/plugins/teletaxi_follow.cpp).
  const std::vector<std::string> slower = {};
  for (const std::string destination : {"220,240", "-40,40"}) {
    const std::string calibration = dir + "/city-" + destination + ".rubric.cfg";
    const auto calibrated = runToEnd({kAula, "calibrate", "teletaxi", "--world=" + world, "--seeds=1", "--jobs=1",
                                      "--TeleTaxi.Destination=" + destination, "--out=" + dir + "/runs", "--output=" + calibration},
                                     kBackstop);
    ASSERT_EQ(calibrated.code.value_or(-1), 0) << calibrated.output;
    const std::string text = readFile(calibration);
    EXPECT_NE(text.find("Calibration.Setting.TeleTaxi.Destination = " + destination), std::string::npos) << text;
    EXPECT_NE(text.find("TeleTaxi.Referee.FullMarkTime = "), std::string::npos) << text;

    const TaxiRun fixed_reference = taxiRun(dir, world, "reference", destination, {"--TeleTaxi.Referee.Rubric=fixed"});
    std::vector<std::string> fixed_student = slower;
    fixed_student.push_back("--TeleTaxi.Referee.Rubric=fixed");
    const TaxiRun fixed_bfs = taxiRun(dir, world, AULA_PLUGIN_TELETAXI_FOLLOW, destination, fixed_student);
    EXPECT_DOUBLE_EQ(fixed_reference.mark, fixed_bfs.mark) << "the fixed scale tells them apart: the test shows nothing";

    const TaxiRun reference = taxiRun(dir, world, "reference", destination, {"--calibration=" + calibration});
    std::vector<std::string> calibrated_student = slower;
    calibrated_student.push_back("--calibration=" + calibration);
    const TaxiRun bfs = taxiRun(dir, world, AULA_PLUGIN_TELETAXI_FOLLOW, destination, calibrated_student);
    EXPECT_GT(bfs.driving_time_s, 1.2 * reference.driving_time_s) << destination;
    EXPECT_GE(reference.mark, 9.9) << destination;
    EXPECT_LT(bfs.mark, reference.mark - 0.2) << destination << ": " << bfs.driving_time_s << " s against "
                                              << reference.driving_time_s << " s";
  }
  // A calibration made for one destination is refused for another, before the run.
  const auto other = runToEnd({kAula, "run", "teletaxi", "--headless", "--world=" + world, "--TeleTaxi.Destination=-40,40",
                               "--calibration=" + dir + "/city-220,240.rubric.cfg", "--lcm-url=" + aula::testing::privateLcmUrl()},
                              60s);
  EXPECT_EQ(other.code.value_or(-1), 2) << other.output;
  EXPECT_NE(other.output.find("calibrated for TeleTaxi.Destination = 220,240, and this run's is -40,40"), std::string::npos)
      << other.output;
  std::filesystem::remove_all(dir);
}

// A grade whose settings change what a run can reach (issue 38) does not use a calibration made
// for others: beside a world calibrated for 120 s episodes, a grade of 150 s calibrates the world
// itself (saying why) and its runs name that calibration; a grade of 120 s uses the world's own.
// A grade of Aula's own house with noise calibrates it too (its rubric was made without).
TEST(Calibration, AGradeWithOtherSettingsMakesItsOwn) {
  namespace fs = std::filesystem;
  const std::string dir = aula::testing::privateDir();
  const std::string world = makeHouse(dir, {"--seed", "5", "--rooms-x", "2", "--rooms-y", "1"});
  const auto calibrated = runToEnd({kAula, "calibrate", "vacuum", "--world=" + world, "--seeds=1", "--jobs=1",
                                    "--Vacuum.Referee.Duration=120", "--out=" + dir + "/calibration"},
                                   120s);
  ASSERT_EQ(calibrated.code.value_or(-1), 0) << calibrated.output;
  fs::create_directories(dir + "/class/ana");
  fs::copy_file(std::string(AULA_TEST_DATA_DIR) + "/python/vacuum_bounce/MyAlgorithm.py", dir + "/class/ana/MyAlgorithm.py");
  // `on`: the world graded ("" for the exercise's own, vacuum.world).
  auto grade = [&](const std::string& out, const std::string& on, const std::vector<std::string>& settings) {
    std::vector<std::string> command = {kAula, "grade", "vacuum", dir + "/class/ana", "--seeds=1",
                                        "--calibration-seeds=1", "--jobs=1", "--out=" + dir + "/" + out};
    if (!on.empty()) command.push_back("--worlds=" + on);
    command.insert(command.end(), settings.begin(), settings.end());
    const auto graded = runToEnd(command, kBackstop);
    EXPECT_EQ(graded.code.value_or(-1), 0) << graded.output;
    const std::string name = on.empty() ? "vacuum" : "house";
    return graded.output + readFile(dir + "/" + out + "/runs/ana/" + name + "-seed1.json");
  };
  const std::string same = grade("same", world, {"--Vacuum.Referee.Duration=120"});
  EXPECT_EQ(same.find("calibrating"), std::string::npos) << same;
  EXPECT_NE(same.find("\"calibration\": \"house.rubric.cfg\""), std::string::npos) << same;
  const std::string longer = grade("longer", world, {"--Vacuum.Referee.Duration=150"});
  EXPECT_NE(longer.find("house.world: house.rubric.cfg was calibrated for Vacuum.Referee.Duration = 120, and this grade's is "
                        "150: calibrating for this grade"),
            std::string::npos)
      << longer;
  EXPECT_NE(longer.find("\"calibration\": \"house-"), std::string::npos) << longer;
  bool recorded = false;
  for (const auto& entry : fs::directory_iterator(dir + "/longer/calibrations")) {
    if (entry.path().extension() == ".cfg") {
      recorded = readFile(entry.path().string()).find("Calibration.Setting.Vacuum.Referee.Duration = 150\n") != std::string::npos;
    }
  }
  EXPECT_TRUE(recorded);
  const std::string noisy = grade("noisy", "", {"--Simulator.Noise=realistic", "--Vacuum.Referee.Duration=150"});
  EXPECT_NE(noisy.find("vacuum.world: Aula's rubric for it was made for Vacuum.Referee.Duration = 900, and this grade's is 150"),
            std::string::npos)
      << noisy;
  EXPECT_NE(noisy.find("\"calibration\": \"vacuum-"), std::string::npos) << noisy;
  std::filesystem::remove_all(dir);
}
