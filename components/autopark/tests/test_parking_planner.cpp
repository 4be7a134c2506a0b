// Parking planner (OMPL Reeds-Shepp + escape manoeuvre) and path tracker on the ground-truth street.
#include <aula/autopark/footprint_checker.hpp>
#include <aula/autopark/parking_planner.hpp>
#include <aula/autopark/path_tracker.hpp>
#include <aula/autopark/street_scenario.hpp>
#include <aula/geometry/angles.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace aula::autopark;

namespace {

constexpr double kDeg = M_PI / 180.0;

ParkingPlanner::Options options(unsigned seed = 1) {
  ParkingPlanner::Options o;
  o.seed = seed;
  o.time_limit_s = 1.0;
  return o;
}

// Rear-axle bicycle: the rear axle moves along the heading at v, the body turns at w (exact arc over dt).
Pose2D stepAckermann(const Pose2D& centre, double v, double w, double dt, const CarGeometry& car) {
  const Pose2D r = centreToRearAxle(centre, car);
  const double ds = v * dt;
  Pose2D n;
  if (std::abs(w) < 1e-12) {
    n = {r.x_m + ds * std::cos(r.yaw_rad), r.y_m + ds * std::sin(r.yaw_rad), r.yaw_rad};
  } else {
    const double k = w / v, yaw1 = r.yaw_rad + w * dt;
    n = {r.x_m + (std::sin(yaw1) - std::sin(r.yaw_rad)) / k, r.y_m + (std::cos(r.yaw_rad) - std::cos(yaw1)) / k,
         aula::geometry::wrapAngle(yaw1)};
  }
  return rearAxleToCentre(n, car);
}

}  // namespace

TEST(OccupancyGrid, MarkAndQueryRoundTrip) {
  OccupancyGrid grid(-1.0, -2.0, 0.05, 100, 80);  // x in [-1, 4), y in [-2, 2)
  EXPECT_FALSE(grid.occupiedAt(0.333, 0.777));
  grid.markOccupied(0.333, 0.777);
  EXPECT_TRUE(grid.occupiedAt(0.333, 0.777));
  EXPECT_TRUE(grid.occupiedAt(0.301, 0.751));   // same cell [0.30, 0.35) x [0.75, 0.80)
  EXPECT_FALSE(grid.occupiedAt(0.36, 0.777));   // next cell
  EXPECT_FALSE(grid.occupiedAt(0.333, 0.70));
  int col = 0, row = 0;
  ASSERT_TRUE(grid.worldToCell(0.333, 0.777, col, row));
  EXPECT_EQ(col, 26);
  EXPECT_EQ(row, 24);  // north-up: row 0 is the top edge, y = 2
  EXPECT_TRUE(grid.occupied(col, row));
  EXPECT_EQ(grid.occupiedCount(), 1);
  grid.markOccupied(10.0, 10.0);                // outside: ignored
  EXPECT_EQ(grid.occupiedCount(), 1);
  EXPECT_TRUE(grid.occupiedAt(-1.01, 0.0));     // outside counts as occupied
  EXPECT_TRUE(grid.occupied(100, 0));
  grid.clear();
  EXPECT_EQ(grid.occupiedCount(), 0);
}

TEST(CarGeometry, CentreRearAxleConversion) {
  const CarGeometry car;
  const Pose2D c{1.0, 2.0, 0.7};
  const Pose2D r = centreToRearAxle(c, car);
  EXPECT_NEAR(r.x_m, 1.0 - 1.3 * std::cos(0.7), 1e-12);
  EXPECT_NEAR(r.y_m, 2.0 - 1.3 * std::sin(0.7), 1e-12);
  EXPECT_DOUBLE_EQ(r.yaw_rad, 0.7);
  const Pose2D back = rearAxleToCentre(r, car);
  EXPECT_NEAR(back.x_m, c.x_m, 1e-12);
  EXPECT_NEAR(back.y_m, c.y_m, 1e-12);
  EXPECT_NEAR(back.yaw_rad, c.yaw_rad, 1e-12);
  // Yaw 0: rear axle 0.7 m ahead of the rear bumper.
  EXPECT_NEAR(centreToRearAxle({0, 0, 0}, car).x_m - (-car.length_m / 2), 0.7, 1e-12);
}

TEST(FootprintChecker, AgreesWithBoxesOnTheStreet) {
  const StreetScenario street = makeParallelParkingStreet(5.2);
  const OccupancyGrid grid = street.makeGrid(0.05);
  const CarGeometry car;
  const FootprintChecker checker(grid, car, 0.15);
  EXPECT_TRUE(checker.freeCentre(street.goal_centre));
  EXPECT_TRUE(checker.freeCentre(street.start_centre));
  Pose2D into_car = street.goal_centre;
  into_car.x_m = street.slot_rear_x_m;  // overlaps the car behind
  EXPECT_FALSE(checker.freeCentre(into_car));
  EXPECT_TRUE(footprintHitsBoxes(into_car, car, street.obstacles));
  Pose2D on_curb = street.goal_centre;
  on_curb.y_m = -3.2;  // body bottom at -4.2: 0.05 m from the curb face, inside the clearance
  EXPECT_FALSE(checker.freeCentre(on_curb));
  EXPECT_TRUE(checker.freeCentre(on_curb, 0.0));
  EXPECT_FALSE(footprintHitsBoxes(on_curb, car, street.obstacles));
}

TEST(ParkingPlanner, PlansIntoA13LSlotCollisionFreeAndKinematicallyFeasible) {
  const StreetScenario street = makeParallelParkingStreet(5.2);
  const OccupancyGrid grid = street.makeGrid(0.05);
  const CarGeometry car;
  const ParkingPlanner planner(car, options(1));
  const PlannedPath path = planner.plan(grid, street.start_centre, street.goal_centre);
  ASSERT_TRUE(path.solved) << path.message;
  ASSERT_GE(path.poses.size(), 10u);
  ASSERT_EQ(path.direction.size(), path.poses.size());
  ASSERT_EQ(path.curvature_per_m.size(), path.poses.size());
  EXPECT_LE(path.planning_time_s, 1.0);

  // Starts at the start, ends at the goal.
  EXPECT_NEAR(path.poses.front().x_m, street.start_centre.x_m, 1e-6);
  EXPECT_NEAR(path.poses.front().y_m, street.start_centre.y_m, 1e-6);
  const Pose2D& end = path.poses.back();
  EXPECT_LT(std::hypot(end.x_m - street.goal_centre.x_m, end.y_m - street.goal_centre.y_m), 0.1);
  EXPECT_LT(std::abs(aula::geometry::wrapAngle(end.yaw_rad - street.goal_centre.yaw_rad)), 2 * kDeg);

  int cusps = 0;
  for (size_t i = 0; i < path.poses.size(); ++i) {
    // Collision-free, checked against the boxes (not the grid), with a little margin.
    ASSERT_FALSE(footprintHitsBoxes(path.poses[i], car, street.obstacles, 0.05)) << "pose " << i;
    ASSERT_TRUE(path.direction[i] == 1 || path.direction[i] == -1);
    if (i == 0) continue;
    const Pose2D a = centreToRearAxle(path.poses[i - 1], car), b = centreToRearAxle(path.poses[i], car);
    const double ds = std::hypot(b.x_m - a.x_m, b.y_m - a.y_m);
    ASSERT_LE(ds, 0.1 + 1e-9) << "pose " << i;
    ASSERT_LE(std::hypot(path.poses[i].x_m - path.poses[i - 1].x_m, path.poses[i].y_m - path.poses[i - 1].y_m), 0.1 + 1e-9);
    // Curvature of the rear-axle path never tighter than 1 / R: on a circle of radius R a chord
    // ds turns the heading by 2 asin(ds / 2R); any wider curve turns it less.
    const double max_turn = 2.0 * std::asin(std::min(1.0, ds / (2.0 * car.min_turn_radius_m)));
    ASSERT_LE(std::abs(aula::geometry::wrapAngle(b.yaw_rad - a.yaw_rad)), max_turn * (1 + 1e-6) + 1e-9) << "pose " << i;
    ASSERT_LE(std::abs(path.curvature_per_m[i]), 1.0 / car.min_turn_radius_m + 1e-12);
    // The motion between consecutive rear-axle poses goes along the heading (no side slip),
    // in the stated direction.
    const double along = std::cos(a.yaw_rad) * (b.x_m - a.x_m) + std::sin(a.yaw_rad) * (b.y_m - a.y_m);
    ASSERT_GT(along * path.direction[i], 0.0) << "pose " << i;
    if (path.direction[i] != path.direction[i - 1]) ++cusps;
  }
  EXPECT_EQ(cusps, path.cusps);
  EXPECT_GE(path.cusps, 1);  // a parallel park ends in reverse, after a forward approach

  // Same seed -> same path.
  const PlannedPath again = ParkingPlanner(car, options(1)).plan(grid, street.start_centre, street.goal_centre);
  ASSERT_TRUE(again.solved);
  ASSERT_EQ(again.poses.size(), path.poses.size());
  for (size_t i = 0; i < path.poses.size(); ++i) {
    ASSERT_DOUBLE_EQ(again.poses[i].x_m, path.poses[i].x_m);
    ASSERT_DOUBLE_EQ(again.poses[i].y_m, path.poses[i].y_m);
    ASSERT_DOUBLE_EQ(again.poses[i].yaw_rad, path.poses[i].yaw_rad);
  }
}

TEST(ParkingPlanner, SolvesTheTightestSlotOverSeveralSeeds) {
  const StreetScenario street = makeParallelParkingStreet(4.8);  // 1.2 car lengths
  const OccupancyGrid grid = street.makeGrid(0.05);
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const PlannedPath path = ParkingPlanner(CarGeometry{}, options(seed)).plan(grid, street.start_centre, street.goal_centre);
    EXPECT_TRUE(path.solved) << "seed " << seed << ": " << path.message;
  }
}

TEST(ParkingPlanner, APathIsRefusedWhereTheBodyLeavesTheMappedStreet) {
  const CarGeometry car;
  const MappedStreet street{-20, 30, -4.25, 5};
  PlannedPath path;
  path.poses = {{0, 2.5, 0}, {10, 2.5, 0}, {27.9, 2.5, 0}};  // the front bumper at 29.9
  EXPECT_EQ(pathLeavesStreet(path, car, street), "");
  path.poses.push_back({28.1, 2.5, 0});  // ... at 30.1
  EXPECT_EQ(pathLeavesStreet(path, car, street),
            "leaves the mapped street at x 28.10 y 2.50 (mapped x -20.00 to 30.00, y -4.25 to 5.00)");
  path.poses = {{0, 4.2, 0}};  // the left side at 5.2: over the far curb
  EXPECT_NE(pathLeavesStreet(path, car, street), "");
  path.poses = {{0, 2.5, M_PI / 2}};  // across the street, inside it
  EXPECT_EQ(pathLeavesStreet(path, car, street), "");
}

TEST(ParkingPlanner, BlockedSlotFailsWithinTheTimeLimit) {
  const StreetScenario street = makeParallelParkingStreet(3.5);  // shorter than the car
  const OccupancyGrid grid = street.makeGrid(0.05);
  for (bool escape : {true, false}) {
    ParkingPlanner::Options o = options(3);
    o.time_limit_s = 0.5;
    o.use_escape = escape;
    const PlannedPath path = ParkingPlanner(CarGeometry{}, o).plan(grid, street.start_centre, street.goal_centre);
    EXPECT_FALSE(path.solved);
    EXPECT_TRUE(path.poses.empty());
    EXPECT_FALSE(path.message.empty());
    EXPECT_LE(path.planning_time_s, o.time_limit_s + 0.2);
  }
  // A 4.4 m (1.1 L) slot: the goal is free (at the minimum in-slot clearance) but no escape is
  // found with R = 5 m; the planner must give up within the time limit.
  StreetScenario pocket = makeParallelParkingStreet(4.4);
  ParkingPlanner::Options o = options(3);
  o.time_limit_s = 0.5;
  const OccupancyGrid g2 = pocket.makeGrid(0.05);
  const PlannedPath p2 = ParkingPlanner(CarGeometry{}, o).plan(g2, pocket.start_centre, pocket.goal_centre);
  EXPECT_FALSE(p2.solved);
  EXPECT_LE(p2.planning_time_s, o.time_limit_s + 0.2);
}

// The references plan on sim time only: a repeatable plan's budgets are counts, so no clock (here a
// time limit far too short to plan in) changes its path, and a blocked slot still ends.
TEST(ParkingPlanner, ARepeatablePlanIsTheSameWhateverTheClockSays) {
  const StreetScenario street = makeParallelParkingStreet(4.8);
  const OccupancyGrid grid = street.makeGrid(0.05);
  ParkingPlanner::Options o = options(2);
  o.repeatable = true;
  o.time_limit_s = 1e-9;
  const PlannedPath hurried = ParkingPlanner(CarGeometry{}, o).plan(grid, street.start_centre, street.goal_centre);
  o.time_limit_s = 100;
  const PlannedPath leisurely = ParkingPlanner(CarGeometry{}, o).plan(grid, street.start_centre, street.goal_centre);
  ASSERT_TRUE(hurried.solved) << hurried.message;
  ASSERT_EQ(hurried.poses.size(), leisurely.poses.size());
  for (size_t i = 0; i < hurried.poses.size(); ++i) {
    EXPECT_EQ(hurried.poses[i].x_m, leisurely.poses[i].x_m);
    EXPECT_EQ(hurried.poses[i].y_m, leisurely.poses[i].y_m);
    EXPECT_EQ(hurried.poses[i].yaw_rad, leisurely.poses[i].yaw_rad);
  }
  o.repeatable = false;
  o.time_limit_s = 1e-9;
  EXPECT_FALSE(ParkingPlanner(CarGeometry{}, o).plan(grid, street.start_centre, street.goal_centre).solved);
  const StreetScenario blocked = makeParallelParkingStreet(3.5);  // shorter than the car
  ParkingPlanner::Options b = options(3);
  b.repeatable = true;
  b.use_escape = false;
  EXPECT_FALSE(ParkingPlanner(CarGeometry{}, b).plan(blocked.makeGrid(0.05), blocked.start_centre, blocked.goal_centre).solved);
}

class PathTrackerSlot : public ::testing::TestWithParam<double> {};

TEST_P(PathTrackerSlot, ClosedLoopAckermannParks) {
  const StreetScenario street = makeParallelParkingStreet(GetParam());
  const OccupancyGrid grid = street.makeGrid(0.05);
  const CarGeometry car;
  const PlannedPath path = ParkingPlanner(car, options(2)).plan(grid, street.start_centre, street.goal_centre);
  ASSERT_TRUE(path.solved) << path.message;

  PathTracker tracker(path, car);
  EXPECT_EQ(tracker.segmentCount(), path.cusps + 1);
  Pose2D pose = street.start_centre;
  const double dt = 0.05;
  bool done = false;
  int reversals = 0;
  double last_v = 0.0;
  for (int step = 0; step < 6000 && !done; ++step) {
    const PathTracker::Command cmd = tracker.update(pose);
    done = cmd.done;
    ASSERT_LE(std::abs(cmd.w_radps), std::abs(cmd.v_mps) / car.min_turn_radius_m + 1e-9) << "step " << step;
    ASSERT_LE(cmd.v_mps, 1.0 + 1e-9);
    ASSERT_GE(cmd.v_mps, -0.7 - 1e-9);
    if (cmd.v_mps != 0.0) {
      if (last_v != 0.0 && (cmd.v_mps > 0) != (last_v > 0)) ++reversals;
      last_v = cmd.v_mps;
      pose = stepAckermann(pose, cmd.v_mps, cmd.w_radps, dt, car);
    }
    ASSERT_FALSE(footprintHitsBoxes(pose, car, street.obstacles)) << "step " << step;
  }
  ASSERT_TRUE(done);
  EXPECT_EQ(reversals, path.cusps);
  EXPECT_LT(std::hypot(pose.x_m - street.goal_centre.x_m, pose.y_m - street.goal_centre.y_m), 0.25);
  EXPECT_LT(std::abs(aula::geometry::wrapAngle(pose.yaw_rad - street.goal_centre.yaw_rad)), 5 * kDeg);
}

INSTANTIATE_TEST_SUITE_P(Slots, PathTrackerSlot, ::testing::Values(5.2, 4.8));  // 1.3 L and 1.2 L
