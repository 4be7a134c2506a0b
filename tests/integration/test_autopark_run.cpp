// The Autopark exercise, headless in lockstep: `aula run autopark` with the reference solutions
// (about 1 s wall per run). The referee grades from the true geometry and DART contacts.
#include "test_support.hpp"
#include "../unit/support/mesh_files.hpp"

#include <aula/process/child_process.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace std::chrono_literals;
using aula::testing::jsonNumber;
using aula::testing::readFile;

namespace {

std::string runAutopark(const std::string& tag, const std::vector<std::string>& extra) {
  const std::string report = ::testing::TempDir() + "autopark_" + tag + ".json";
  const std::string log = ::testing::TempDir() + "autopark_" + tag + ".log";
  std::remove(report.c_str());
  std::vector<std::string> args{std::string(AULA_BIN_DIR) + "/aula", "run", "autopark", "--headless",
                                "--report=" + report, "--lcm-url=" + aula::testing::privateLcmUrl()};
  args.insert(args.end(), extra.begin(), extra.end());
  aula::process::ChildProcess run(args, log, log);
  const auto code = run.wait(120s);
  EXPECT_TRUE(code.has_value()) << readFile(log);
  EXPECT_EQ(code.value_or(-1), 0) << readFile(log);
  return readFile(report) + "\n--- log ---\n" + readFile(log);
}

std::string reportOnly(const std::string& run) { return run.substr(0, run.find("\n--- log ---\n")); }

void expectParkedWell(const std::string& run) {
  EXPECT_NE(run.find("\"parked\": true"), std::string::npos) << run;
  EXPECT_NE(run.find("\"case\": \"parked\""), std::string::npos) << run;
  EXPECT_NE(run.find("\"left_street\": false"), std::string::npos) << run;
  EXPECT_GE(jsonNumber(run, "mark"), 9.0) << run;
  EXPECT_EQ(jsonNumber(run, "collisions"), 0.0) << run;
}

// A run from (-7, 2.5) facing -x, the parked cars on the car's left: it must turn round first,
// then park well.
std::string parksFromAReversedStart(const std::string& algorithm, int seed, const std::string& world) {
  const std::string run = runAutopark(algorithm + "_reversed", {"--algorithm=" + algorithm, "--seed=" + std::to_string(seed),
                                                                "--world=" + world, "--Simulator.StartPose.car=-7,2.5,3.14159"});
  EXPECT_NE(run.find("TURN at x -7.00 y 2.50 yaw 180.0 deg"), std::string::npos) << run;
  expectParkedWell(run);
  return run;
}

}  // namespace

TEST(AutoparkRun, ReactiveParksFromTheDefaultStartAndTheSameSeedGivesTheSameReport) {
  const std::string a = runAutopark("default_a", {"--algorithm=reactive", "--seed=5"});
  const std::string b = runAutopark("default_b", {"--algorithm=reactive", "--seed=5"});
  expectParkedWell(a);
  EXPECT_EQ(reportOnly(a), reportOnly(b)) << "the same seed must give a byte-identical report";
  EXPECT_NE(a.find("\"exercise\": \"autopark\""), std::string::npos) << a;
}

TEST(AutoparkRun, ReactiveParksFromEightMetresFurtherBack) {
  expectParkedWell(runAutopark("back", {"--algorithm=reactive", "--seed=6", "--Simulator.StartPose.car=-15,2.5,0"}));
}

TEST(AutoparkRun, ReactiveParksFromAlongsideTheCarAheadOfTheSlot) {
  // The car ahead of the slot is centred at x = 14: the slot is behind the car at the start.
  expectParkedWell(runAutopark("alongside", {"--algorithm=reactive", "--seed=7", "--Simulator.StartPose.car=14,2.5,0"}));
}

TEST(AutoparkRun, ReactiveParksTheCarLikeCar) {
  expectParkedWell(runAutopark("ackermann", {"--algorithm=reactive", "--seed=8", "--world=worlds/autopark_ackermann.world"}));
}

TEST(AutoparkRun, PlannerParksTheCarLikeCarInTheOnePointThreeLengthSlot) {
  // A 5.2 m slot for a 4 m car that cannot turn tighter than 5 m: many short moves (OMPL + escape).
  const std::string run = runAutopark("planner_13", {"--algorithm=planner", "--seed=9", "--world=worlds/autopark_ackermann_1.3L.world"});
  EXPECT_NE(run.find("\"parked\": true"), std::string::npos) << run;
  EXPECT_EQ(jsonNumber(run, "collisions"), 0.0) << run;
  EXPECT_LE(jsonNumber(run, "position_error_m"), 0.3) << run;
  EXPECT_LE(std::abs(jsonNumber(run, "yaw_error_deg")), 5.0) << run;
  EXPECT_NE(run.find("\"algorithm\": \"planner\""), std::string::npos) << run;
}

// A slot too short for two arcs of the car-like car's 5 m radius (the shipped 1.2 L street): the
// reactive reference says so, with the length it would need, and does not try. No contact, and
// never "parked". The report says why (issue 44: `algorithm_status`, what the algorithm said last).
TEST(AutoparkRun, ReactiveDeclinesASlotTooShortForItsArcsAndSaysWhy) {
  const std::string run = runAutopark("declines", {"--algorithm=reactive", "--seed=10", "--world=worlds/autopark_ackermann_1.2L.world"});
  EXPECT_NE(reportOnly(run).find("\"algorithm_status\": \"slot too short for a reactive park: 4."), std::string::npos) << run;
  EXPECT_NE(run.find("DECLINED"), std::string::npos) << run;
  EXPECT_NE(run.find("slot too short for a reactive park: 4."), std::string::npos) << run;
  EXPECT_NE(run.find(" m, need 6."), std::string::npos) << run;
  EXPECT_EQ(jsonNumber(run, "collisions"), 0.0) << run;
  EXPECT_NE(run.find("\"parked\": false"), std::string::npos) << run;
  EXPECT_EQ(run.find("PARKED"), std::string::npos) << run;
}

// Facing the wrong way at the start: the car turns round (on the spot, or a three-point turn for
// the car-like car) without touching anything, then searches and parks.
TEST(AutoparkRun, ReactiveTurnsRoundFromAReversedStartAndParks) {
  for (const char* world : {"worlds/autopark.world", "worlds/autopark_ackermann.world"}) {
    SCOPED_TRACE(world);
    parksFromAReversedStart("reactive", 11, world);
  }
}

// The planner from a reversed start: it turns round before searching (on the spot, or a
// three-point turn), parks without a contact, and every plan keeps the car's body on the street
// (the shipped streets: x -25 to 35 between the curb faces y -4.25 and 5), as its log says.
TEST(AutoparkRun, PlannerTurnsRoundFromAReversedStartParksAndItsPlanNeverLeavesTheStreet) {
  for (const char* world : {"worlds/autopark.world", "worlds/autopark_ackermann_1.3L.world"}) {
    SCOPED_TRACE(world);
    const std::string run = parksFromAReversedStart("planner", 12, world);
    int plans = 0;
    for (size_t at = run.find("body within x "); at != std::string::npos; at = run.find("body within x ", at + 1)) {
      double x0, x1, y0, y1;
      ASSERT_EQ(std::sscanf(run.c_str() + at, "body within x %lf to %lf, y %lf to %lf", &x0, &x1, &y0, &y1), 4) << run;
      EXPECT_GE(x0, -25.0);
      EXPECT_LE(x1, 35.0);
      EXPECT_GE(y0, -4.25);
      EXPECT_LE(y1, 5.0);
      ++plans;
    }
    EXPECT_GE(plans, 1) << run;
  }
}


// A teacher's street whose curbs and parked cars have other names: the referee finds them from
// the geometry, the run parks as on the shipped street; and a street whose curb a setting names.
TEST(AutoparkRun, AStreetWhoseCurbAndCarsHaveOtherNamesRuns) {
  std::string street = readFile(std::string(AULA_SOURCE_DIR) + "/worlds/autopark.world");
  auto replaceAll = [&street](const std::string& from, const std::string& to) {
    for (size_t at = street.find(from); at != std::string::npos; at = street.find(from, at + to.size())) {
      street.replace(at, from.size(), to);
    }
  };
  replaceAll("curb_parking_side", "kerb_south");
  replaceAll("curb_far_side", "kerb_north");
  replaceAll("parked_car_", "van_");
  const std::string world = ::testing::TempDir() + "autopark_renamed.world";
  std::ofstream(world) << street;
  const std::string run = runAutopark("renamed", {"--algorithm=reactive", "--seed=1", "--world=" + world});
  expectParkedWell(run);
  EXPECT_NEAR(jsonNumber(run, "slot_length_m"), 8.6, 1e-6) << run;
  // Named by settings instead: the same slot.
  const std::string named = runAutopark("renamed_named", {"--algorithm=reactive", "--seed=1", "--world=" + world,
                                                          "--Autopark.Referee.Curb=kerb_south",
                                                          "--Autopark.Referee.CarPrefix=van_"});
  expectParkedWell(named);
  EXPECT_NEAR(jsonNumber(named, "slot_length_m"), 8.6, 1e-6) << named;
}

// RoboticsAcademy's street as a teacher brings it, with RoboticsInfrastructure's kind of car: seven
// COLLADA cars turned 1.57 rad, <static>false</static>, no plugin (kept still); no curb; a car of
// seven links placed with relative_to, built along its own +y, driven by
// libgazebo_ros_ackermann_drive.so, its three lasers <sensor>s; model://ground_plane and
// model://sun with no folder. The planner parks it with no contact. Every file is written here.
TEST(AutoparkRun, PlannerParksAGazeboAckermannCarOnAStreetOfMeshCarsWithNoCurb) {
  const std::string dir = aula::testing::privateDir();
  std::filesystem::create_directories(dir + "/models/car_mesh/meshes");
  std::filesystem::create_directories(dir + "/models/gz_car");
  aula::testing::writeCollada(dir + "/models/car_mesh/meshes/car.dae",
                              {aula::testing::boxTriangles({{{-1.1, -2.45, 0}, {1.1, 2.45, 1.6}}})}, {"car"});
  std::ofstream(dir + "/models/car_mesh/model.config") << "<model><sdf version='1.4'>model.sdf</sdf></model>";
  std::ofstream(dir + "/models/car_mesh/model.sdf") << "<sdf version='1.4'><model name='car_mesh'><static>true</static></model></sdf>";
  auto laser = [](const std::string& name, const std::string& pose) {
    return "<sensor name='" + name + "' type='ray'><pose relative_to='chassis'>" + pose + "</pose><update_rate>20</update_rate>"
           "<ray><scan><horizontal><samples>180</samples><min_angle>-1.570796</min_angle><max_angle>1.570796</max_angle>"
           "</horizontal></scan><range><min>0.12</min><max>30</max></range><noise><type>gaussian</type><stddev>0.01</stddev>"
           "</noise></ray></sensor>";
  };
  auto wheel = [](const std::string& name, const std::string& at) {
    return "<joint name='" + name + "_axle' type='revolute'><pose relative_to='chassis'>" + at + " 0.3 0 0 0</pose>"
           "<parent>chassis</parent><child>" + name + "</child></joint><link name='" + name + "'><pose relative_to='" + name +
           "_axle'/><inertial><mass>20</mass></inertial><collision name='c'><pose relative_to='" + name + "_axle'>0 0 0 0 1.5708 0"
           "</pose><geometry><cylinder><radius>0.3</radius><length>0.2</length></cylinder></geometry></collision></link>";
  };
  std::ofstream(dir + "/models/gz_car/model.config") << "<model><sdf version='1.5'>model.sdf</sdf></model>";
  std::ofstream(dir + "/models/gz_car/model.sdf")
      << "<sdf version='1.5'><model name='gz_car'><link name='base_link'/><link name='chassis'><inertial><mass>1200</mass>"
         "</inertial><collision name='body'><pose>0 0.1 0.75 0 0 0</pose><geometry><box><size>1.8 4.4 1.3</size></box></geometry>"
         "</collision>" + laser("front", "0 2.35 0.5 0 0 1.5708") + laser("back", "0 -2.15 0.5 0 0 -1.5708") +
             laser("side", "0.95 0.1 0.5 0 0 0") + "</link>" + wheel("fl", "-0.75 1.45") + wheel("fr", "0.75 1.45") +
             wheel("rl", "-0.75 -1.15") + wheel("rr", "0.75 -1.15") +
             "<plugin name='drive' filename='libgazebo_ros_ackermann_drive.so'><front_left_joint>fl_axle</front_left_joint>"
             "<front_right_joint>fr_axle</front_right_joint><rear_left_joint>rl_axle</rear_left_joint>"
             "<rear_right_joint>rr_axle</rear_right_joint><max_steer>0.5</max_steer><max_speed>20</max_speed></plugin></model></sdf>";
  std::string cars;
  int n = 0;
  for (const double x : {-20.0, -13.5, -7.0, 0.5, 14.0, 21.5, 29.0}) {
    cars += "<model name='car" + std::to_string(++n) + "'><pose>" + std::to_string(x) +
            " -3 0 0 0 1.57</pose><static>false</static><link name='l'><collision name='c'><geometry><mesh>"
            "<uri>model://car_mesh/meshes/car.dae</uri></mesh></geometry></collision></link></model>\n";
  }
  const std::string world = dir + "/ra_street.world";
  std::ofstream(world) << "<?xml version='1.0'?>\n<sdf version='1.4'><world name='default'>\n"
                          "<include><uri>model://ground_plane</uri></include><include><uri>model://sun</uri></include>\n"
                          "<include><uri>model://gz_car</uri><pose>-7 2.5 0.02 0 0 -1.5708</pose></include>\n" + cars +
                              "</world></sdf>\n";
  setenv("AULA_MODEL_PATH", (dir + "/models").c_str(), 1);
  const std::string run = runAutopark("gazebo_car", {"--algorithm=planner", "--seed=1", "--world=" + world});
  unsetenv("AULA_MODEL_PATH");
  expectParkedWell(run);
  EXPECT_NEAR(jsonNumber(run, "slot_length_m"), 8.6, 0.05) << run;  // between the meshes, 4.9 m long
}
