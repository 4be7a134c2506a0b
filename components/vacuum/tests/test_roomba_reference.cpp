// The vacuum's reference and baseline algorithms on plain data (no LCM, no DART, no process):
// the shipped house's walls and furniture at the laser's height, the roomba's laser ray-cast and
// its bumper pressed when its disc meets an obstacle (tests/unit/support/plain_robot.hpp).
#include "support/plain_robot.hpp"
#include <aula/vacuum/references.hpp>

#include <aula/vacuum/vacuum_algorithm.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

using namespace aula::vacuum;

namespace {

constexpr double kPeriodS = 0.08;  // Vacuum.Period

struct Coverage {
  int cells_visited = 0;  // 0.25 m cells the robot's centre passed over
  int contacts = 0;
  double max_abs_v_mps = 0;
};

Coverage drive(std::unique_ptr<VacuumAlgorithm> algorithm, double seconds) {
  aula::test::PlainRobot robot("vacuum.world", "roomba", 0.5, 3.0);
  YawSensor yaw(robot.pose);
  aula::component::Belief belief;
  VacuumApi api{yaw, robot.laser(), robot.bumper, robot.motors, belief, kPeriodS};
  std::set<std::pair<int, int>> cells;
  Coverage run;
  const int periods = static_cast<int>(seconds / kPeriodS);
  for (int i = 1; i <= periods; ++i) {
    algorithm->execute(api);
    run.max_abs_v_mps = std::max(run.max_abs_v_mps, std::abs(robot.motors.getV()));
    robot.step(kPeriodS, static_cast<int64_t>(i * kPeriodS * 1e6));
    cells.insert({static_cast<int>(std::floor(robot.x() / 0.25)), static_cast<int>(std::floor(robot.y() / 0.25))});
  }
  run.cells_visited = static_cast<int>(cells.size());
  run.contacts = robot.contacts();
  return run;
}

}  // namespace

TEST(RoombaReference, ABumpWhileDrivingForwardBacksOff) {
  aula::test::PlainRobot robot("vacuum.world", "roomba", 0.5, 3.0);
  YawSensor yaw(robot.pose);
  aula::component::Belief belief;
  VacuumApi api{yaw, robot.laser(), robot.bumper, robot.motors, belief, kPeriodS};
  auto reference = makeReferenceAlgorithm(1);
  reference->execute(api);
  EXPECT_GT(robot.motors.getV(), 0) << "it starts driving (its spiral)";
  robot.bumper.set({1, 1, 80000});
  reference->execute(api);
  EXPECT_LT(robot.motors.getV(), 0) << "a bump ends the forward move: it backs off";
}

TEST(RoombaReference, WaitsForItsFirstScan) {
  aula::component::Pose3d pose;
  aula::component::Laser laser;  // nothing received yet
  aula::component::Bumper bumper;
  aula::component::Motors motors(0.5, 3.0);
  YawSensor yaw(pose);
  aula::component::Belief belief;
  VacuumApi api{yaw, laser, bumper, motors, belief, kPeriodS};
  makeReferenceAlgorithm(1)->execute(api);
  EXPECT_EQ(motors.getV(), 0);
  EXPECT_EQ(motors.getW(), 0);
}

TEST(RoombaReference, CoversMoreOfTheHouseThanTheRandomBounceAndRarelyTouchesAnything) {
  // 300 s of the house on plain data, three seeds each.
  for (uint64_t seed : {1u, 2u, 3u}) {
    const Coverage reference = drive(makeReferenceAlgorithm(seed), 300);
    const Coverage bounce = drive(makeRandomBounceAlgorithm(seed), 300);
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::printf("seed %llu: reference %d cells, %d contacts; bounce %d cells, %d contacts\n",
                static_cast<unsigned long long>(seed), reference.cells_visited, reference.contacts, bounce.cells_visited,
                bounce.contacts);
    EXPECT_GT(reference.cells_visited, 1.3 * bounce.cells_visited);
    EXPECT_LT(2 * reference.contacts, bounce.contacts);
    EXPECT_LE(reference.max_abs_v_mps, 0.5);
  }
}
