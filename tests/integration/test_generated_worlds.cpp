// Each exercise's reference, end to end, on a world the test generates with worlds/tools:
// a layout, slot and start that no shipped world has. A teacher's world must just work.
#include "test_support.hpp"

#include <aula/process/child_process.hpp>

#include <gtest/gtest.h>

using namespace std::chrono_literals;
using aula::process::ChildProcess;
using aula::testing::jsonNumber;
using aula::testing::readFile;

namespace {

// Writes a world with a generator of worlds/tools; returns its path.
std::string generate(const std::string& dir, const std::string& tool, std::vector<std::string> args) {
  const std::string world = dir + "/" + tool + ".world";
  std::vector<std::string> command = {AULA_PYTHON, std::string(AULA_SOURCE_DIR) + "/worlds/tools/" + tool + ".py",
                                      "--out", world};
  command.insert(command.end(), args.begin(), args.end());
  ChildProcess gen(command, dir + "/gen.log", dir + "/gen.log");
  EXPECT_EQ(gen.wait(30s).value_or(-1), 0) << readFile(dir + "/gen.log");
  return world;
}

// Runs an exercise headless on `world`; returns the report.
std::string runOn(const std::string& dir, const std::string& exercise, const std::string& world,
                  std::vector<std::string> extra) {
  const std::string report = dir + "/report.json", log = dir + "/run.log";
  std::vector<std::string> args = {std::string(AULA_BIN_DIR) + "/aula", "run", exercise, "--headless", "--world=" + world,
                                   "--report=" + report, "--lcm-url=" + aula::testing::privateLcmUrl()};
  args.insert(args.end(), extra.begin(), extra.end());
  ChildProcess run(args, log, log);
  const auto code = run.wait(120s);
  EXPECT_EQ(code.value_or(-1), 0) << readFile(log);
  const std::string json = readFile(report);
  EXPECT_NE(json.find("\"world_sha256\": \"" ), std::string::npos) << json << readFile(log);
  return json;
}

}  // namespace

TEST(GeneratedWorlds, TheVacuumReferenceCleansAHouseOfFourRoomsFromAnotherStart) {
  const std::string dir = aula::testing::privateDir();
  const std::string world = generate(dir, "make_house", {"--seed", "11", "--rooms-x", "2", "--rooms-y", "2",
                                                         "--room-size", "3.6", "--start=1.5,1.5,1.0"});
  const std::string json = runOn(dir, "vacuum", world, {"--algorithm=reference"});
  // The reference (the mapping cleaner) covers about 86 % of the shipped house in 900 s.
  EXPECT_GE(jsonNumber(json, "coverage_percent"), 55.0) << json;
  EXPECT_LT(jsonNumber(json, "floor_area_m2"), 50.0) << json;  // this house's floor, not the shipped one's
  EXPECT_EQ(jsonNumber(json, "pose_messages"), 45001) << json;
}

// In this house a lane along a wall leads, on seed 4, into the 0.35 m gap between a box and a
// wall that the map draws a centimetre wider: the reference was wedged there from 290 s to the
// end (46.4 %, 1026 bumps). Bumped again and again in one spot, it backs out the way it came.
TEST(GeneratedWorlds, TheVacuumReferenceBacksOutOfAGapItIsWedgedIn) {
  const std::string dir = aula::testing::privateDir();
  const std::string world = generate(dir, "make_house", {"--seed", "21", "--rooms-x", "3", "--rooms-y", "2",
                                                         "--room-size", "3.2", "--furniture", "2"});
  const std::string json = runOn(dir, "vacuum", world, {"--algorithm=reference", "--seed=4"});
  EXPECT_GE(jsonNumber(json, "coverage_percent"), 80.0) << json;
  EXPECT_LT(jsonNumber(json, "bumps"), 100) << json;
}

// Issue 44's house (4 x 3 rooms, 0.6 m doors) under realistic noise, seed 3: entering the
// top-left room, the scans fitted the map along one axis only and none was drawn; the room stayed
// blank, nothing drew the cleaner back, and it never reached the six rooms beyond it (32.1 %,
// six rooms of twelve). A scan is drawn where the axis it does not fix is known from the last fix.
TEST(GeneratedWorlds, TheVacuumReferenceDrawsTheRoomsItEntersUnderNoise) {
  const std::string dir = aula::testing::privateDir();
  const std::string world = generate(dir, "make_house", {"--seed", "101", "--rooms-x", "4", "--rooms-y", "3",
                                                         "--door-width", "0.6", "--furniture", "2"});
  const std::string json = runOn(dir, "vacuum", world, {"--algorithm=reference", "--seed=3", "--Simulator.Noise=realistic"});
  EXPECT_GE(jsonNumber(json, "coverage_percent"), 55.0) << json;
  EXPECT_NE(json.find("\"wedged\": false"), std::string::npos) << json;
}

TEST(GeneratedWorlds, TheTeleTaxiReferenceCrossesAGeneratedCity) {
  const std::string dir = aula::testing::privateDir();
  const std::string world = generate(dir, "make_city", {"--seed", "5", "--blocks", "3"});
  // Roads' centre lines are at -141, -47, 47 and 141; the taxi starts at (-47, -47).
  const std::string json = runOn(dir, "teletaxi", world, {"--algorithm=reference", "--TeleTaxi.Destination=141,47"});
  EXPECT_NE(json.find("\"reached\": true"), std::string::npos) << json;
  EXPECT_GE(jsonNumber(json, "mark"), 9.0) << json;
  EXPECT_EQ(jsonNumber(json, "bumps"), 0.0) << json;
}

TEST(GeneratedWorlds, TheReactiveParkerParksInAnotherSlotFromAnotherStart) {
  const std::string dir = aula::testing::privateDir();
  const std::string world = generate(dir, "make_autopark", {"--slot-length", "8", "--slot-x", "6", "--start=-12,2.5,0"});
  const std::string json = runOn(dir, "autopark", world, {"--algorithm=reactive"});
  EXPECT_NE(json.find("\"parked\": true"), std::string::npos) << json;
  EXPECT_EQ(jsonNumber(json, "collisions"), 0.0) << json;
  EXPECT_GE(jsonNumber(json, "mark"), 9.0) << json;
}

// A street the shipped ones are not: a van behind the slot, a small car ahead of it, the curb
// 0.5 m further out, a free 8 m curb beyond the last car (longer than the slot, and not it) and
// the car facing away from the slot. The planner turns round and parks in the slot, touching
// nothing; the referee takes the slot between the van and the small car.
TEST(GeneratedWorlds, ThePlannerParksBetweenAVanAndASmallCarFromAReversedStartNotAtTheFreeCurb) {
  const std::string dir = aula::testing::privateDir();
  const std::string world = generate(dir, "make_autopark", {"--slot-length", "5.6", "--curb-offset", "0.5", "--kinematics", "ackermann",
                                                            "--reversed", "--rear-neighbour", "van", "--front-neighbour", "small",
                                                            "--free-curb", "8"});
  const std::string json = runOn(dir, "autopark", world, {"--algorithm=planner"});
  EXPECT_NE(json.find("\"case\": \"parked\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"left_street\": false"), std::string::npos) << json;
  EXPECT_EQ(jsonNumber(json, "collisions"), 0.0) << json;
  EXPECT_NEAR(jsonNumber(json, "slot_length_m"), 5.6, 1e-9) << json;
  EXPECT_GE(jsonNumber(json, "mark"), 9.0) << json;
}

// The car that turns in place in a 1.3 L slot, too short for the reactive reference's two arcs:
// it parks with several moves, forward and back within the slot, touching nothing.
TEST(GeneratedWorlds, TheReactiveParkerParksTheCarThatTurnsInPlaceInAOnePointThreeLengthSlotWithSeveralMoves) {
  const std::string dir = aula::testing::privateDir();
  const std::string world = generate(dir, "make_autopark", {"--slot-length", "5.2", "--curb-offset", "0.5", "--kinematics", "diff"});
  const std::string json = runOn(dir, "autopark", world, {"--algorithm=reactive"});
  EXPECT_NE(json.find("\"case\": \"parked\""), std::string::npos) << json;
  EXPECT_EQ(jsonNumber(json, "collisions"), 0.0) << json;
  EXPECT_GE(jsonNumber(json, "mark"), 9.0) << json;
}

namespace {
// Both references from five starts 2 m apart along the lane (facing +x, on the lane line y 2.5):
// each parks in the slot, touching nothing.
void bothParkFromFiveStarts(const std::string& world_name, std::vector<std::string> street, double first_x_m) {
  const std::string dir = aula::testing::privateDir();
  const std::string world = generate(dir, "make_autopark", street);
  for (const char* algorithm : {"reactive", "planner"}) {
    for (int i = 0; i < 5; ++i) {
      const std::string start = std::to_string(first_x_m + 2 * i) + ",2.5,0";
      SCOPED_TRACE(world_name + ", " + algorithm + " from " + start);
      const std::string json =
          runOn(dir, "autopark", world, {std::string("--algorithm=") + algorithm, "--seed=1", "--Simulator.StartPose.car=" + start});
      EXPECT_NE(json.find("\"case\": \"parked\""), std::string::npos) << json << readFile(dir + "/run.log");
      EXPECT_EQ(jsonNumber(json, "collisions"), 0.0) << json;
    }
  }
}
}  // namespace

// A held-out street with free curb at both ends (17 m before the first car, 9 m beyond the last,
// each longer than the slot): a 7.6 m slot between a van and a small car. From beside the slot
// and past it, each reference finds the slot (not the free curb) and parks.
TEST(GeneratedWorlds, BothReferencesParkFromFiveStartsOnAStreetWithFreeCurbAtBothEnds) {
  bothParkFromFiveStarts("free curb at both ends",
                         {"--slot-length", "7.6", "--slot-x", "15", "--free-curb", "9", "--rear-neighbour", "van",
                          "--front-neighbour", "small", "--kinematics", "ackermann"},
                         16);
}

// bench/autopark_streets.sh's street 9 (seed 1): from four of these starts, beside the slot, the
// reactive reference crept back and forth short of its arcs' start, off the lane, for the whole
// 300 s without a word. It backs off along the lane and comes again; the planner parks as before.
TEST(GeneratedWorlds, BothReferencesParkFromFiveStartsWhereTheReactiveStalledBeside) {
  bothParkFromFiveStarts("street 9", {"--slot-length", "7.18", "--slot-x", "16.52", "--curb-offset", "-0.91", "--kinematics",
                                      "ackermann", "--rear-neighbour", "van", "--front-neighbour", "van"},
                         17.89);
}
