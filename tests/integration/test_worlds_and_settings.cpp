// Worlds and settings with one source of truth, tried as a user would: misspelt keys fail at
// once, a world carries its own channel names and models, a destination the taxi cannot reach
// is refused before anything drives.
#include "test_support.hpp"

#include <aula/process/child_process.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>

using namespace std::chrono_literals;
using aula::process::ChildProcess;
using aula::testing::Outcome;
using aula::testing::readFile;
using aula::testing::runToEnd;
namespace fs = std::filesystem;

namespace {

const std::string kBin = AULA_BIN_DIR;
const std::string kWorlds = std::string(AULA_SOURCE_DIR) + "/worlds/";


void writeFile(const std::string& path, const std::string& text) {
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream(path) << text;
}

// The roomba model as an inline <model>, channels renamed, at (x, y).
std::string inlineRoomba(const std::string& name, const std::string& channel_prefix, double x, double y) {
  std::string sdf = readFile(kWorlds + "models/roomba/model.sdf");
  const auto begin = sdf.find("<model name=\"roomba\">");
  const auto end = sdf.rfind("</model>") + 8;
  std::string model = sdf.substr(begin, end - begin);
  model = std::regex_replace(model, std::regex("ROOMBA_"), channel_prefix);
  model = std::regex_replace(model, std::regex("<model name=\"roomba\">"),
                             "<model name=\"" + name + "\"><pose>" + std::to_string(x) + " " + std::to_string(y) +
                                 " 0 0 0 0</pose>");
  return model;
}

// The shipped house with its <include> of the roomba replaced by `robot`.
std::string houseWith(const std::string& robot) {
  const std::string house = readFile(kWorlds + "vacuum.world");
  const auto begin = house.find("<include>");
  const auto end = house.find("</include>") + 10;
  return house.substr(0, begin) + robot + house.substr(end);
}

}  // namespace

TEST(Settings, AMisspeltSimulatorKeyExitsTwoAtOnce) {
  const Outcome out = runToEnd({kBin + "/aula-sim", kWorlds + "vacuum.world", "--Simulator.Duratoin=0.5"}, 10s);
  ASSERT_TRUE(out.code.has_value()) << "aula-sim did not stop";
  EXPECT_EQ(*out.code, 2) << out.output;
  EXPECT_LT(out.wall_s, 1.0);
  EXPECT_NE(out.output.find("command line --Simulator.Duratoin: unknown key 'Simulator.Duratoin' (did you mean "
                            "'Simulator.Duration'?)"),
            std::string::npos)
      << out.output;
}

TEST(Settings, TheLauncherChecksEveryKeyBeforeStartingAnything) {
  const std::string url = "--lcm-url=" + aula::testing::privateLcmUrl();
  Outcome out = runToEnd({kBin + "/aula", "run", "vacuum", "--headless", "--Vacuum.MaxVV=9", url}, 10s);
  ASSERT_TRUE(out.code.has_value());
  EXPECT_EQ(*out.code, 2) << out.output;
  EXPECT_NE(out.output.find("unknown key 'Vacuum.MaxVV' (did you mean 'Vacuum.MaxV'?)"), std::string::npos) << out.output;
  EXPECT_EQ(out.output.find("aula-sim"), std::string::npos) << "a process was started\n" << out.output;

  out = runToEnd({kBin + "/aula", "run", "vacuum", "--headless", "--Vacuum.MaxV=9", url}, 10s);
  EXPECT_EQ(out.code.value_or(-1), 2) << out.output;
  EXPECT_NE(out.output.find("command line --Vacuum.MaxV: Vacuum.MaxV = '9': out of range (0, 2] m/s"),
            std::string::npos)
      << out.output;
}

TEST(Settings, ABadKeyInACfgFileNamesFileAndLine) {
  const std::string dir = aula::testing::privateDir();
  std::string cfg = readFile(std::string(AULA_SOURCE_DIR) + "/config/vacuumCleaner.cfg");
  cfg += "Vacuum.Referee.Duraton = 60\n";
  const int line = static_cast<int>(std::count(cfg.begin(), cfg.end(), '\n'));
  writeFile(dir + "/my.cfg", cfg);
  const Outcome out = runToEnd({kBin + "/aula", "run", "vacuum", "--headless", "--config=" + dir + "/my.cfg",
                                "--lcm-url=" + aula::testing::privateLcmUrl()},
                               10s);
  EXPECT_EQ(out.code.value_or(-1), 2) << out.output;
  EXPECT_NE(out.output.find(dir + "/my.cfg:" + std::to_string(line) +
                            ": unknown key 'Vacuum.Referee.Duraton' (did you mean 'Vacuum.Referee.Duration'?)"),
            std::string::npos)
      << out.output;
}

TEST(Settings, AulaConfigPrintsEachProcessWithWhereEachValueCameFrom) {
  const Outcome out = runToEnd({kBin + "/aula", "config", "vacuum", "--Vacuum.Referee.Duration=60"}, 10s);
  EXPECT_EQ(out.code.value_or(-1), 0) << out.output;
  EXPECT_NE(out.output.find("vacuum-cleaner-referee:\n"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("Vacuum.Referee.Duration = 60 s    [command line --Vacuum.Referee.Duration]"), std::string::npos)
      << out.output;
  EXPECT_NE(out.output.find("Vacuum.Robot = roomba    [default]"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("Simulator.PhysicsStep = 0.01 s    [the vacuum exercise's step]"), std::string::npos)
      << out.output;
}

TEST(Worlds, AllThreeProcessesFollowTheRobotChannelsOfTheWorldGiven) {
  const std::string dir = aula::testing::privateDir();
  const std::string world = dir + "/house_other_channels.world";
  writeFile(world, houseWith(inlineRoomba("roomba", "CLEANER_", -1, 1.5)));
  const std::string report = dir + "/report.json";
  const Outcome out = runToEnd({kBin + "/aula", "run", "vacuum", "--headless", "--world=" + world,
                                "--algorithm=reference", "--Vacuum.Referee.Duration=60", "--report=" + report,
                                "--lcm-url=" + aula::testing::privateLcmUrl()},
                               120s);
  ASSERT_EQ(out.code.value_or(-1), 0) << out.output;
  const std::string json = readFile(report);
  EXPECT_EQ(aula::testing::jsonNumber(json, "pose_messages"), 3001) << json;  // the referee heard CLEANER_POSE
  EXPECT_GT(aula::testing::jsonNumber(json, "coverage_percent"), 5.0) << json;  // the component drove CLEANER_MOTORS
  EXPECT_NE(json.find("\"world\": \"house_other_channels.world\""), std::string::npos) << json;
  EXPECT_EQ(out.output.find("ROOMBA_"), std::string::npos) << out.output;
}

TEST(Worlds, TeleTaxiDestinationsTheTaxiCannotReachAreRefusedAtOnce) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"60,60", "(60.0, 60.0) is inside a building or obstacle"},
      {"5000,0", "(5000.0, 0.0) is off the map (x in [-250.0, 250.0], y in [-250.0, 250.0] m)"},
      {"0.5,0.5", "is closer than 2 m to the taxi's start"},
  };
  for (const auto& [destination, reason] : cases) {
    const Outcome out = runToEnd({kBin + "/aula", "run", "teletaxi", "--headless", "--algorithm=reference",
                                  "--TeleTaxi.Destination=" + destination, "--lcm-url=" + aula::testing::privateLcmUrl()},
                                 30s);
    ASSERT_TRUE(out.code.has_value()) << destination;
    EXPECT_EQ(*out.code, 2) << out.output;
    // The launcher refuses what the map alone says before starting anything; the component
    // refuses what needs its planner (too close, walled off) as soon as it has loaded the world.
    // Generous bounds: this tells "refused at once" from "waited out a run" (600 s of sim), on
    // a loaded machine under parallel ctest; the typical figures (0.3 s, 1.5 s) are measured.
    EXPECT_LT(out.wall_s, reason.find("off the map") != std::string::npos || reason.find("inside") != std::string::npos
                              ? 3.0
                              : 8.0)
        << destination;
    EXPECT_NE(out.output.find("TeleTaxi.Destination = " + destination + ": "), std::string::npos)
        << out.output;
    EXPECT_NE(out.output.find(reason), std::string::npos) << out.output;
  }
}

TEST(Worlds, ModelsResolveThroughAulaModelPathAndAWorldWithoutPhysicsStepsAtTheSetting) {
  const std::string dir = aula::testing::privateDir();
  // A model only this test has, in a folder of its own; the world in another, with no models/.
  std::string model = inlineRoomba("tinybot", "TINY_", 0, 0);
  model = std::regex_replace(model, std::regex("<pose>0\\.0+ 0\\.0+ 0 0 0 0</pose>"), "");
  writeFile(dir + "/my_models/tinybot/model.config",
            "<?xml version=\"1.0\"?><model><name>tinybot</name><sdf version=\"1.9\">model.sdf</sdf></model>\n");
  writeFile(dir + "/my_models/tinybot/model.sdf", "<?xml version=\"1.0\"?>\n<sdf version=\"1.9\">\n" + model + "\n</sdf>\n");
  std::string world = houseWith("<include><uri>model://tinybot</uri><name>tinybot</name><pose>-1 1.5 0 0 0 0</pose></include>");
  world = std::regex_replace(world, std::regex("<physics[^>]*>.*</physics>"), "");
  ASSERT_EQ(world.find("<physics"), std::string::npos);
  writeFile(dir + "/worlds/house.world", world);
  const std::vector<std::string> sim = {kBin + "/aula-sim", dir + "/worlds/house.world", "--duration=0.2", "--rtf=0",
                                        "--lcm-url=" + aula::testing::privateLcmUrl()};

  unsetenv("AULA_MODEL_PATH");
  Outcome out = runToEnd(sim, 20s);
  EXPECT_EQ(out.code.value_or(-1), 2) << out.output;
  EXPECT_NE(out.output.find("model 'tinybot' not found"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("AULA_MODEL_PATH"), std::string::npos) << out.output;

  setenv("AULA_MODEL_PATH", ("/nonexistent:" + dir + "/my_models").c_str(), 1);
  out = runToEnd(sim, 20s);
  EXPECT_EQ(out.code.value_or(-1), 0) << out.output;
  EXPECT_NE(out.output.find("with 1 robot(s), step 5 ms"), std::string::npos) << "Simulator.PhysicsStep's 5 ms\n" << out.output;

  std::vector<std::string> faster = sim;
  faster.push_back("--Simulator.PhysicsStep=0.004");
  out = runToEnd(faster, 20s);
  EXPECT_EQ(out.code.value_or(-1), 0) << out.output;
  EXPECT_NE(out.output.find("step 4 ms"), std::string::npos) << out.output;
  unsetenv("AULA_MODEL_PATH");

  // The shipped house states a 10 ms step: the setting wins, and the simulator says so.
  out = runToEnd({kBin + "/aula-sim", kWorlds + "vacuum.world", "--duration=0.2", "--rtf=0",
                  "--lcm-url=" + aula::testing::privateLcmUrl()},
                 20s);
  EXPECT_NE(out.output.find("step 5 ms"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("vacuum.world states <max_step_size>0.01</max_step_size>; the step is "
                            "Simulator.PhysicsStep, 5 ms"),
            std::string::npos)
      << out.output;
}

TEST(Worlds, AWorldsPhysicsDoesNotChangeTheExercisesStep) {
  // The same house with and without <physics>: `aula run` steps both at the vacuum's 10 ms, and
  // the two runs measure the same.
  const std::string dir = aula::testing::privateDir();
  std::string house = readFile(kWorlds + "vacuum.world");
  house = std::regex_replace(house, std::regex("<physics[^>]*>.*</physics>"), "");
  writeFile(dir + "/stated/house.world", readFile(kWorlds + "vacuum.world"));
  writeFile(dir + "/unstated/house.world", house);
  std::vector<std::string> reports;
  for (const std::string which : {"stated", "unstated"}) {
    const Outcome out = runToEnd({kBin + "/aula", "run", "vacuum", "--headless", "--world=" + dir + "/" + which + "/house.world",
                                  "--algorithm=reference", "--seed=1", "--Vacuum.Referee.Duration=30",
                                  "--report=" + dir + "/" + which + ".json", "--lcm-url=" + aula::testing::privateLcmUrl()},
                                 90s);
    ASSERT_EQ(out.code.value_or(-1), 0) << out.output;
    EXPECT_NE(out.output.find("step 10 ms"), std::string::npos) << out.output;
    std::string json = readFile(dir + "/" + which + ".json");
    json = std::regex_replace(json, std::regex("\"world_sha256\": \"[0-9a-f]+\""), "");
    json = std::regex_replace(json, std::regex("\"wall_[a-z_]+\": [0-9.e+-]+"), "");
    reports.push_back(json);
  }
  EXPECT_EQ(aula::testing::jsonNumber(reports[0], "coverage_percent"), aula::testing::jsonNumber(reports[1], "coverage_percent"));
  EXPECT_EQ(aula::testing::jsonNumber(reports[0], "mark"), aula::testing::jsonNumber(reports[1], "mark"));
}

TEST(Worlds, AStudentsRoombaFolderWhereTheRunStartsDoesNotShadowTheTeachersModel) {
  // The teacher's roomba on AULA_MODEL_PATH; `aula run` started in the student's folder, which
  // holds a roomba/ folder of the student's own (no model.config).
  const std::string dir = aula::testing::privateDir();
  fs::create_directories(dir + "/teacher/models");
  fs::copy(kWorlds + "models/roomba", dir + "/teacher/models/roomba", fs::copy_options::recursive);
  writeFile(dir + "/teacher/worlds/house.world", readFile(kWorlds + "vacuum.world"));
  writeFile(dir + "/student/roomba/CMakeLists.txt", "# the student's own roomba\n");
  const auto previous = fs::current_path();
  fs::current_path(dir + "/student");
  setenv("AULA_MODEL_PATH", (dir + "/teacher/models").c_str(), 1);
  const Outcome out = runToEnd({kBin + "/aula", "run", "vacuum", "--headless", "--world=" + dir + "/teacher/worlds/house.world",
                                "--algorithm=reference", "--Vacuum.Referee.Duration=5", "--report=" + dir + "/report.json",
                                "--lcm-url=" + aula::testing::privateLcmUrl()},
                               60s);
  unsetenv("AULA_MODEL_PATH");
  fs::current_path(previous);
  EXPECT_EQ(out.code.value_or(-1), 0) << out.output;
  EXPECT_EQ(out.output.find("model.config"), std::string::npos) << out.output;
  EXPECT_NE(readFile(dir + "/report.json").find("\"world\": \"house.world\""), std::string::npos);
}

TEST(Worlds, AWorldWhoseOnlyTaxiHasAnotherNameRunsWithIt) {
  const std::string dir = aula::testing::privateDir();
  std::string city = readFile(kWorlds + "cityLarge.world");
  city = std::regex_replace(city, std::regex("<name>taxi_holo</name>"), "<name>taxi</name>");
  writeFile(dir + "/city.world", city);
  const std::string report = dir + "/report.json";
  const Outcome out = runToEnd({kBin + "/aula", "run", "teletaxi", "--headless", "--world=" + dir + "/city.world",
                                "--algorithm=reference", "--TeleTaxi.Referee.Timeout=20", "--report=" + report,
                                "--lcm-url=" + aula::testing::privateLcmUrl()},
                               90s);
  EXPECT_EQ(out.code.value_or(-1), 0) << out.output;
  EXPECT_NE(out.output.find("teletaxi: the world has no robot 'taxi_holo' (TeleTaxi.Robot); using its only robot with "
                            "the exercise's plugins, 'taxi'\n"),
            std::string::npos)
      << out.output;
  EXPECT_GT(aula::testing::jsonNumber(readFile(report), "path_length_m"), 20.0) << readFile(report);  // it drove
  // check-world agrees, and says which robot.
  const Outcome check = runToEnd({kBin + "/aula", "check-world", dir + "/city.world", "--exercise=teletaxi"}, 20s);
  EXPECT_EQ(check.code.value_or(-1), 0) << check.output;
  EXPECT_NE(check.output.find("teletaxi: the robot is 'taxi'"), std::string::npos) << check.output;
  EXPECT_NE(check.output.find("teletaxi: ok"), std::string::npos) << check.output;
}

TEST(Worlds, AMisspeltPluginKeyExitsTwoNamingIt) {
  const std::string dir = aula::testing::privateDir();
  std::string robot = inlineRoomba("roomba", "ROOMBA_", -1, 1.5);
  robot = std::regex_replace(robot, std::regex("<samples>"), "<sampels>");
  robot = std::regex_replace(robot, std::regex("</samples>"), "</sampels>");
  writeFile(dir + "/typo.world", houseWith(robot));
  const std::string said = "typo.world: model 'roomba', plugin 'laser': unknown key <sampels> (did you mean <samples>?)";
  const Outcome run = runToEnd({kBin + "/aula", "run", "vacuum", "--headless", "--world=" + dir + "/typo.world",
                                "--lcm-url=" + aula::testing::privateLcmUrl()},
                               20s);
  EXPECT_EQ(run.code.value_or(-1), 2) << run.output;
  EXPECT_NE(run.output.find(said), std::string::npos) << run.output;
  EXPECT_LT(run.wall_s, 3.0);
  const Outcome check = runToEnd({kBin + "/aula", "check-world", dir + "/typo.world"}, 20s);
  EXPECT_EQ(check.code.value_or(-1), 2) << check.output;
  EXPECT_NE(check.output.find(said), std::string::npos) << check.output;
}

TEST(Worlds, AWorldThatIncludesItselfIsRefusedAtOnce) {
  const std::string dir = aula::testing::privateDir();
  const std::string world = dir + "/loop.world";
  writeFile(world, houseWith("<include><uri>file://" + world + "</uri></include>"));
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{kBin + "/aula", "check-world", world},
        std::vector<std::string>{kBin + "/aula", "run", "vacuum", "--headless", "--world=" + world,
                                 "--lcm-url=" + aula::testing::privateLcmUrl()}}) {
    const Outcome out = runToEnd(args, 20s);
    EXPECT_EQ(out.code.value_or(-1), 2) << out.output;
    EXPECT_NE(out.output.find("loop.world: includes itself ("), std::string::npos) << out.output;
    EXPECT_LT(out.wall_s, 3.0);
  }
}

TEST(Worlds, ARefereeGivenAnotherWorldThanTheSimulatorsRefusesToGrade) {
  const std::string dir = aula::testing::privateDir();
  const std::string other = dir + "/moved_roomba.world";
  writeFile(other, houseWith(inlineRoomba("roomba", "ROOMBA_", 2.0, 0.5)));
  const std::string url = "--lcm-url=" + aula::testing::privateLcmUrl();
  ChildProcess sim({kBin + "/aula-sim", other, "--lockstep", "--rtf=0", url}, dir + "/sim.log", dir + "/sim.log");
  const Outcome out = runToEnd({kBin + "/vacuum-cleaner-referee", "--headless", url}, 20s);
  ASSERT_TRUE(out.code.has_value()) << "the referee graded on\n" << out.output;
  EXPECT_EQ(*out.code, 2) << out.output;
  EXPECT_NE(out.output.find("the simulator runs world 'vacuum' (sha256 "), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("but this process was given " + std::string(AULA_SOURCE_DIR)), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("give all three processes the same --world"), std::string::npos) << out.output;
}

TEST(Settings, EveryProgramPrintsItsUsageAndDeclaredSettingsWithoutADisplay) {
  const char* display = std::getenv("DISPLAY");
  const std::string saved = display != nullptr ? display : "";
  unsetenv("DISPLAY");
  const std::vector<std::pair<std::string, std::string>> programs = {
      {"aula-sim", "Simulator.PhysicsStep"},        {"teletaxi", "TeleTaxi.Destination"},
      {"teletaxi-referee", "TeleTaxi.Referee.Timeout"}, {"vacuum-cleaner", "Vacuum.Algorithm"},
      {"vacuum-cleaner-referee", "Vacuum.Referee.FullMarkCoverage"}, {"autopark", "Autopark.Algorithm"},
      {"autopark-referee", "Autopark.Referee.GapBands"}, {"aula-demo-client", "Demo.MaxV"}};
  for (const auto& [program, key] : programs) {
    const Outcome out = runToEnd({kBin + "/" + program, "--help"}, 10s);
    EXPECT_EQ(out.code.value_or(-1), 0) << program << "\n" << out.output;
    EXPECT_NE(out.output.find("usage: " + program), std::string::npos) << out.output;
    EXPECT_NE(out.output.find("  " + key + "  ("), std::string::npos) << program << "\n" << out.output;
  }
  // The tools without settings of their own: their usage.
  for (const auto& [program, usage] : std::vector<std::pair<std::string, std::string>>{
           {"aula", "usage: aula run"}, {"aula-mapgen", "usage: aula-mapgen"}, {"aula-replay", "usage: aula replay"}}) {
    const Outcome out = runToEnd({kBin + "/" + program, "--help"}, 10s);
    EXPECT_EQ(out.code.value_or(-1), 0) << program << "\n" << out.output;
    EXPECT_NE(out.output.find(usage), std::string::npos) << out.output;
  }
  // Without --help and without a display, a window process says what to do instead of aborting.
  const Outcome out = runToEnd({kBin + "/vacuum-cleaner"}, 10s);
  EXPECT_EQ(out.code.value_or(-1), 2) << out.output;
  EXPECT_NE(out.output.find("no display (DISPLAY is not set): use --headless"), std::string::npos) << out.output;
  if (!saved.empty()) setenv("DISPLAY", saved.c_str(), 1);
}

TEST(Worlds, CheckWorldSaysWhatEachExerciseWouldMiss) {
  const Outcome out = runToEnd({kBin + "/aula", "check-world", kWorlds + "vacuum.world"}, 20s);
  EXPECT_EQ(out.code.value_or(-1), 0) << out.output;
  EXPECT_NE(out.output.find("robot 'roomba' at (-1, 1.5)"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("  laser 'laser' on ROOMBA_LASER"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("vacuum: ok"), std::string::npos) << out.output;
  // The roomba is the house's only robot with a taxi's plugins, but the taxi's destination is off the map.
  EXPECT_NE(out.output.find("teletaxi: cannot run; the world needs its points on free floor: default: "
                            "TeleTaxi.Destination = 120, -40: (120.0, -40.0) is off the map"),
            std::string::npos)
      << out.output;
  EXPECT_NE(out.output.find("autopark: cannot run; the world needs a robot named 'car' (Autopark.Robot)"),
            std::string::npos)
      << out.output;
  // A roomba without its laser: the vacuum exercise says so.
  const std::string dir = aula::testing::privateDir();
  std::string robot = inlineRoomba("roomba", "ROOMBA_", -1, 1.5);
  robot = std::regex_replace(robot, std::regex("<plugin name=\"laser\"[^]*?</plugin>"), "");
  writeFile(dir + "/blind.world", houseWith(robot));
  const Outcome blind = runToEnd({kBin + "/aula", "check-world", dir + "/blind.world"}, 20s);
  EXPECT_NE(blind.output.find("vacuum: cannot run; the world needs a laser plugin"), std::string::npos) << blind.output;
}

TEST(Worlds, CheckWorldOnAStreetWithoutACurbSaysWhatIsMissing) {
  const std::string dir = aula::testing::privateDir();
  std::string street = readFile(kWorlds + "autopark.world");
  street = std::regex_replace(street, std::regex("<(collision|visual) name=\"curb_parking_side\">.*\n"), "");
  ASSERT_EQ(street.find("curb_parking_side"), std::string::npos);
  // With no curb (as RoboticsAcademy's street), the parking line is the parked cars' far side.
  writeFile(dir + "/no_curb.world", street);
  const Outcome no_curb = runToEnd({kBin + "/aula", "check-world", dir + "/no_curb.world", "--exercise=autopark"}, 20s);
  EXPECT_EQ(no_curb.code.value_or(-1), 0) << no_curb.output;
  EXPECT_NE(no_curb.output.find("autopark: ok"), std::string::npos) << no_curb.output;
  // With no curb and one parked car, there is no slot.
  street = std::regex_replace(street, std::regex("<include>\\s*<uri>model://parked_car</uri>\\s*<name>parked_car_[1-6]</name>[^]*?</include>"), "");
  ASSERT_EQ(street.find("parked_car_1"), std::string::npos);
  writeFile(dir + "/one_car.world", street);
  const Outcome out = runToEnd({kBin + "/aula", "check-world", dir + "/one_car.world", "--exercise=autopark"}, 20s);
  EXPECT_EQ(out.code.value_or(-1), 1) << out.output;
  EXPECT_NE(out.output.find("autopark: cannot run; the world needs its street for the referee: " + dir +
                            "/one_car.world: needs at least two parked cars (static boxes or meshes between the parking-side "
                            "curb, if any, and the car's start; or name them with Autopark.Referee.CarPrefix)"),
            std::string::npos)
      << out.output;
  // The shipped street: ok.
  const Outcome ok = runToEnd({kBin + "/aula", "check-world", kWorlds + "autopark.world", "--exercise=autopark"}, 20s);
  EXPECT_EQ(ok.code.value_or(-1), 0) << ok.output;
  EXPECT_NE(ok.output.find("autopark: ok"), std::string::npos) << ok.output;
}

TEST(Settings, TheRealTimeFactorIsHonouredInHeadlessLockstepRuns) {
  // 20 s of sim: at --rtf=4 five seconds or more, whatever the machine; as fast as possible,
  // well under that even beside other tests on a loaded 2-core machine (measured 1-4.4 s).
  auto run = [](const std::string& rtf) {
    std::vector<std::string> args = {kBin + "/aula", "run", "teletaxi", "--headless", "--algorithm=student",
                                     "--TeleTaxi.Referee.Timeout=20", "--lcm-url=" + aula::testing::privateLcmUrl()};
    if (!rtf.empty()) args.push_back("--rtf=" + rtf);
    return runToEnd(args, 60s);
  };
  const Outcome fast = run("");
  const Outcome paced = run("4");
  EXPECT_EQ(fast.code.value_or(-1), 0) << fast.output;
  EXPECT_EQ(paced.code.value_or(-1), 0) << paced.output;
  EXPECT_GE(paced.wall_s, 5.0) << paced.output;
  EXPECT_LT(fast.wall_s, paced.wall_s - 0.5) << fast.output;
}

// The exercise pages' grading numbers are generated from the referees' declared settings
// (scripts/update-exercise-docs.sh): a changed default that the page does not show fails here.
TEST(Docs, ExercisePagesShowTheRefereesSettings) {
  for (const std::string exercise : {"vacuum", "teletaxi", "autopark"}) {
    const Outcome out = runToEnd({kBin + "/aula", "config", exercise, "--markdown"}, 20s);
    ASSERT_EQ(out.code.value_or(-1), 0) << out.output;
    const std::string page = aula::testing::readFile(std::string(AULA_SOURCE_DIR) + "/docs/exercises/" + exercise + ".md");
    const auto begin = page.find("-->\n", page.find("<!-- settings:begin"));
    const auto end = page.find("<!-- settings:end -->");
    ASSERT_NE(begin, std::string::npos) << exercise;
    ASSERT_NE(end, std::string::npos) << exercise;
    EXPECT_EQ(page.substr(begin + 4, end - begin - 4), out.output)
        << "docs/exercises/" << exercise << ".md is out of date: run scripts/update-exercise-docs.sh";
    EXPECT_NE(out.output.find("| `" + std::string(exercise == "teletaxi" ? "TeleTaxi" : exercise == "vacuum" ? "Vacuum" : "Autopark") + ".Referee."),
              std::string::npos) << out.output;
  }
}
