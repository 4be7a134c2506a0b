// The mapping reference's coverage planner on a map drawn from synthetic scans of a square room
// (4 m a side, centred on the start): where it may drive, bumps it keeps away from for a while,
// and which floor is still worth a trip.
#include "../support/synthetic_scan.hpp"

#include <coverage_planner.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using aula::vacuum::mapping::CoveragePlanner;
using aula::vacuum::mapping::Point2;
using aula::vacuum::mapping::ScanMap;

namespace {

// The roomba's laser (180 beams over -90..90 degrees) at the room's centre facing yaw_rad: each
// beam ends on the square's wall, 2 m from the centre along the axes.
aula::component::LaserData roomScan(double yaw_rad) {
  return aula::test::syntheticScan(180, -M_PI / 2, M_PI / 2, [yaw_rad](double angle_rad) {
    const double a = yaw_rad + angle_rad;
    return 2.0 / std::max(std::abs(std::cos(a)), std::abs(std::sin(a)));
  });
}

}  // namespace

TEST(CoveragePlanner, ABumpKeepsThePlansAwayUntilItExpires) {
  ScanMap map;
  for (double yaw : {0.0, M_PI / 2, M_PI, -M_PI / 2}) map.insert(roomScan(yaw), yaw, {0, 0});
  CoveragePlanner planner(map);
  const Point2 spot{0.5, 0.3};
  ASSERT_TRUE(planner.traversable(spot));
  planner.addBump(spot, 10.0);
  EXPECT_FALSE(planner.traversable(spot));
  EXPECT_FALSE(planner.traversable(Point2{0.5 + 0.15, 0.3})) << "within clearance_m of the bump";
  EXPECT_TRUE(planner.traversable(Point2{0.5 + 0.25, 0.3}));
  planner.expireBumps(9.9);
  EXPECT_FALSE(planner.traversable(spot));
  planner.expireBumps(10.0);
  EXPECT_TRUE(planner.traversable(spot)) << "the bump is forgotten when it expires";
  EXPECT_TRUE(map.knownFree(map.col(spot.x_m), map.row(spot.y_m))) << "the map itself never had it";
}

// A frontier (floor next to what the laser never saw) is worth a trip only until the robot has
// been there: from one scan facing +x, the floor behind the laser is never seen, and a planner
// that kept it as a goal after sweeping it sent the robot back to it for the rest of the run.
TEST(CoveragePlanner, AFrontierAlreadySweptIsNoLongerAGoal) {
  ScanMap map;
  map.insert(roomScan(0), 0, {0, 0});
  map.markFree({-0.139, 0}, 0.15);  // the robot's footprint, its centre behind the laser
  CoveragePlanner planner(map);
  EXPECT_FALSE(planner.pathToUnswept({0.3, 0}).empty()) << "unswept floor all round";
  for (int j = map.minRow(); j <= map.maxRow(); ++j) {
    for (int i = map.minCol(); i <= map.maxCol(); ++i) {
      if (planner.traversable(i, j)) planner.sweep(map.centre(i, j));
    }
  }
  EXPECT_TRUE(planner.pathToUnswept({0.3, 0}).empty()) << "swept everywhere it can go, frontiers included";
}

TEST(CoveragePlanner, TheRelaxedSearchNeverPassesAGapNarrowerThanTheDisc) {
  EXPECT_GT(aula::vacuum::mapping::CoverageSettings{}.relaxed_clearance_m, 0.165) << "the roomba's radius";
}
