// The whole TeleTaxi exercise, headless in lockstep: `aula run teletaxi` starts the simulator,
// the component with the reference solution and the referee as real processes.
#include "test_support.hpp"
#include "../unit/support/mesh_files.hpp"

#include <aula/process/child_process.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using namespace std::chrono_literals;
using aula::testing::readFile;

namespace {



// Runs one episode; returns the report text.
std::string runTaxi(const std::string& destination, const std::string& tag, const std::string& algorithm = "reference",
                    const std::vector<std::string>& more = {}) {
  const std::string report = ::testing::TempDir() + "teletaxi_" + tag + ".json";
  const std::string log = ::testing::TempDir() + "teletaxi_" + tag + ".log";
  std::remove(report.c_str());
  std::vector<std::string> args = {std::string(AULA_BIN_DIR) + "/aula", "run", "teletaxi", "--headless",
                                   "--algorithm=" + algorithm, "--TeleTaxi.Destination=" + destination,
                                   "--report=" + report, "--lcm-url=" + aula::testing::privateLcmUrl()};
  args.insert(args.end(), more.begin(), more.end());
  aula::process::ChildProcess run(args, log, log);
  const auto code = run.wait(90s);
  EXPECT_TRUE(code.has_value()) << "the run did not end\n" << readFile(log);
  EXPECT_EQ(code.value_or(-1), 0) << readFile(log);
  const std::string json = readFile(report);
  EXPECT_FALSE(json.empty()) << readFile(log);
  return json;
}

}  // namespace

class TeleTaxiReference : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(TeleTaxiReference, ReachesTheDestinationWithAMarkOfAtLeastNine) {
  const std::string json = runTaxi(GetParam().second, GetParam().first);
  EXPECT_NE(json.find("\"reached\": true"), std::string::npos) << json;
  EXPECT_GE(aula::testing::jsonNumber(json, "mark"), 9.0) << json;
  EXPECT_LE(aula::testing::jsonNumber(json, "final_distance_m"), 2.0) << json;
  EXPECT_EQ(aula::testing::jsonNumber(json, "bumps"), 0.0) << "the taxi touched a wall\n" << json;
  EXPECT_NE(json.find("\"exercise\": \"teletaxi\""), std::string::npos);
  EXPECT_NE(json.find("\"algorithm\": \"reference\""), std::string::npos);
  EXPECT_NE(json.find("\"world\": \"cityLarge.world\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"world_sha256\": \""), std::string::npos) << json;
}

INSTANTIATE_TEST_SUITE_P(Destinations, TeleTaxiReference,
                         ::testing::Values(std::make_pair("far", "220,240"),
                                           std::make_pair("plaza", "-40,40"),
                                           std::make_pair("medium", "120,-40")),
                         [](const auto& info) { return std::string(info.param.first); });

TEST(TeleTaxiRun, TheSameRunTwiceGivesByteIdenticalReports) {
  const std::string first = runTaxi("120,-40", "repeat_a");
  const std::string second = runTaxi("120,-40", "repeat_b");
  EXPECT_FALSE(first.empty());
  EXPECT_EQ(first, second);
}

// The component on its own (no simulator, no launcher): a destination the taxi cannot drive to
// is refused as soon as it has loaded the world, with the reason, and nothing runs.
TEST(TeleTaxiComponent, RefusesADestinationInsideABuildingOrAtTheStartWithItsReason) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"60,60", "(60.0, 60.0) is inside a building or obstacle"},
      {"0,0", "(0.0, 0.0) is closer than 2 m to the taxi's start: choose a destination to drive to"},
      {"1.2,-0.8", "(1.2, -0.8) is closer than 2 m to the taxi's start"},
  };
  for (const auto& [destination, reason] : cases) {
    const auto out = aula::testing::runToEnd({std::string(AULA_BIN_DIR) + "/teletaxi", "--headless", "--TeleTaxi.Algorithm=reference",
                                              "--TeleTaxi.Destination=" + destination,
                                              "--lcm-url=" + aula::testing::privateLcmUrl()},
                                             30s);
    ASSERT_TRUE(out.code.has_value()) << destination << ": the component did not end\n" << out.output;
    EXPECT_EQ(*out.code, 2) << out.output;
    EXPECT_NE(out.output.find("TeleTaxi.Destination = " + destination + ": " + reason), std::string::npos) << out.output;
  }
}

// Headless, the taxi standing where the destination cannot be reached from (here: started
// inside a building): the component's Generate Path refuses with the reason, the run ends with
// exit code 2 at once and there is no mark, rather than a 600 s wait for a 0.
TEST(TeleTaxiRun, ADestinationTheTaxiCannotReachFromWhereItStandsEndsTheRunWithTheReason) {
  const std::string dir = aula::testing::privateDir();
  const auto out = aula::testing::runToEnd({std::string(AULA_BIN_DIR) + "/aula", "run", "teletaxi", "--headless",
                                            "--algorithm=reference", "--Simulator.StartPose.taxi_holo=60,60,0",
                                            "--report=" + dir + "/report.json", "--lcm-url=" + aula::testing::privateLcmUrl()},
                                           60s);
  ASSERT_TRUE(out.code.has_value()) << out.output;
  EXPECT_EQ(*out.code, 2) << out.output;
  EXPECT_NE(out.output.find("teletaxi: cannot generate a path: (120.0, -40.0) cannot be reached from where the taxi stands (60."),
            std::string::npos) << out.output;
  EXPECT_NE(out.output.find("no mark: the run never started"), std::string::npos) << out.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/report.json")) << out.output;
  EXPECT_LT(out.wall_s, 20.0) << "refused at once, not after waiting out the referee's timeout";
}

// The default rubric's report states its preset and numbers; the original's too.
TEST(TeleTaxiRun, TheReportStatesTheRubricPresetAndItsNumbers) {
  const std::string json = runTaxi("120,-40", "rubric");
  EXPECT_NE(json.find("\"rubric\": {\n    \"preset\": \"default\",\n    \"TeleTaxi.Referee.ArrivalRadius\": 5.0,\n"
                      "    \"TeleTaxi.Referee.FullMarkSpeed\": 2.6,\n    \"TeleTaxi.Referee.FullMarkTime\": 0.0,\n"
                      "    \"TeleTaxi.Referee.MinTravel\": 2.0\n  }"),
            std::string::npos) << json;
  EXPECT_NE(json.find("\"measures\": [\"driving_time_s\", \"final_distance_m\", \"path_length_m\"]"), std::string::npos) << json;
}

// A taxi that never moves (the student template stays still), its destination 3 m from the start:
// the original's scale gave it 7.5 for "arriving"; the default gives no distance mark.
TEST(TeleTaxiRun, ATaxiThatNeverDrivesGetsNoDistanceMarkUnlessTheOriginalRubric) {
  const std::string still = runTaxi("0,-3", "still", "student");
  EXPECT_NE(still.find("\"reached\": true"), std::string::npos) << still;
  EXPECT_LT(aula::testing::jsonNumber(still, "path_length_m"), 0.5) << still;
  EXPECT_EQ(aula::testing::jsonNumber(still, "mark"), 0.0) << still;
  EXPECT_NE(still.find("at the destination without driving"), std::string::npos) << still;
  const std::string original = runTaxi("0,-3", "still_original", "student", {"--TeleTaxi.Referee.Rubric=original"});
  EXPECT_EQ(aula::testing::jsonNumber(original, "mark"), 7.5) << original;
  EXPECT_NE(original.find("\"preset\": \"original\""), std::string::npos) << original;
}

// RoboticsAcademy's city in small, as its files come: one COLLADA mesh (four blocks in Blender's
// [-1, 1] under a node matrix scaling x and y by 250, 3 m high, a ground; streets 20 m wide along
// both axes and round the blocks) and a taxi known by Gazebo's planar-move plugin, which has no
// speed limit of its own: the taxi drives at the exercise's speed (the motors' default held it to
// 1 m/s, and RoboticsAcademy's city took 200-460 s a trip).
TEST(TeleTaxiRun, TheReferenceDrivesAGazeboTaxiThroughAColladaCityAtTheExercisesSpeed) {
  const std::string dir = aula::testing::privateDir();
  const double k = 1.0 / 250;  // the file's units: world metres / 250 in x and y
  std::vector<aula::testing::MeshBox> blocks;
  for (const double sx : {-1.0, 1.0}) {
    for (const double sy : {-1.0, 1.0}) {
      blocks.push_back({{std::min(10 * sx, 110 * sx) * k, std::min(10 * sy, 110 * sy) * k, 0},
                        {std::max(10 * sx, 110 * sx) * k, std::max(10 * sy, 110 * sy) * k, 3}});
    }
  }
  aula::testing::writeCollada(dir + "/city.dae", {aula::testing::boxTriangles(blocks, 1.0)}, {"city"},
                              "250 0 0 0 0 250 0 0 0 0 1 0 0 0 0 1");
  std::ofstream(dir + "/city.world")
      << "<sdf version='1.6'><world name='city'>"
         "<model name='city'><static>true</static><link name='l'><collision name='c'><geometry><mesh><uri>city.dae</uri>"
         "</mesh></geometry></collision></link></model>"
         "<model name='taxi_holo'><pose>0 0 0 0 0 -1.5529944</pose><link name='chassis'><inertial><mass>750</mass></inertial>"
         "<collision name='body'><pose>0 0 0.75 0 0 0</pose><geometry><box><size>4 2 1.5</size></box></geometry></collision>"
         "</link><plugin name='object_controller' filename='libgazebo_ros_planar_move.so'/></model></world></sdf>\n";
  // North along the street on x = 0 past the blocks, then east: about 180 m.
  const std::string json = runTaxi("60,120", "collada_city", "reference", {"--world=" + dir + "/city.world"});
  EXPECT_NE(json.find("\"reached\": true"), std::string::npos) << json;
  EXPECT_EQ(aula::testing::jsonNumber(json, "bumps"), 0.0) << json;
  EXPECT_GE(aula::testing::jsonNumber(json, "path_length_m"), 170.0) << "round the block, not through it\n" << json;
  EXPECT_GE(aula::testing::jsonNumber(json, "average_speed_mps"), 5.0) << json;
  EXPECT_GE(aula::testing::jsonNumber(json, "mark"), 9.0) << json;
}
