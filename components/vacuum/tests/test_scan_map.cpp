// The mapping reference's localization on ray-cast scans of two shipped houses
// (tests/unit/support/plain_robot.hpp): a map drawn from a spin at one spot, then a scan from a
// known translation away (up to 0.3 m), matched from a prediction at the first spot.
#include "support/plain_robot.hpp"
#include "support/synthetic_scan.hpp"

#include <scan_map.hpp>

#include <gtest/gtest.h>

#include <cmath>

using aula::vacuum::mapping::Point2;
using aula::vacuum::mapping::ScanMap;

namespace {

// The laser plugin `name` of the robot ("": its only one).
Eigen::Isometry3d mountOf(const aula::test::PlainRobot& robot, const std::string& name) {
  for (const auto& plugin : robot.spec().plugins) {
    if (plugin.type == "laser" && (name.empty() || plugin.name == name)) return plugin.getPose("pose");
  }
  throw std::out_of_range("no laser " + name);
}

// Where the laser is when the robot's centre is at (x, y, yaw).
Point2 laserAt(const aula::test::PlainRobot& robot, const std::string& laser, double x_m, double y_m, double yaw_rad) {
  const Eigen::Vector3d mount = mountOf(robot, laser).translation();
  return {x_m + std::cos(yaw_rad) * mount.x() - std::sin(yaw_rad) * mount.y(),
          y_m + std::sin(yaw_rad) * mount.x() + std::cos(yaw_rad) * mount.y()};
}

double laserYaw(const aula::test::PlainRobot& robot, const std::string& laser, double yaw_rad) {
  return yaw_rad + aula::world::yawOf(mountOf(robot, laser));
}

struct Spot {
  double x_m, y_m;
};

// Maps from a spin at `from` (eight headings), then for each translation scans from from + t at
// `yaw` and matches from the prediction "did not move". The map's frame is the world's shifted
// to `from`, as the reference's is its start. Returns the largest error, metres.
double worstRecovery(const std::string& world, const std::string& robot_name, const std::string& laser, Spot from,
                     double yaw_rad, const std::vector<Spot>& translations) {
  aula::test::PlainRobot robot(world, robot_name, 1, 1);
  ScanMap map;
  const auto local = [&](Point2 p) { return Point2{p.x_m - from.x_m, p.y_m - from.y_m}; };
  for (int k = 0; k < 8; ++k) {
    const double yaw = yaw_rad + k * M_PI / 4;
    robot.place(from.x_m, from.y_m, yaw);
    map.insert(robot.laser(laser).getLaserData(), laserYaw(robot, laser, yaw),
               local(laserAt(robot, laser, from.x_m, from.y_m, yaw)));
  }
  const Point2 predicted = local(laserAt(robot, laser, from.x_m, from.y_m, yaw_rad));
  double worst_m = 0;
  for (const Spot& t : translations) {
    const double x = from.x_m + t.x_m, y = from.y_m + t.y_m;
    robot.place(x, y, yaw_rad);
    // As the reference does: only the points that end near walls seen from their side.
    const auto points = ScanMap::endpoints(robot.laser(laser).getLaserData(), laserYaw(robot, laser, yaw_rad), 9.0, 2);
    const auto found = map.matchSeen(points, predicted, 0.35);
    const Point2 truth = local(laserAt(robot, laser, x, y, yaw_rad));
    const double error_m = std::hypot(found.laser_m.x_m - truth.x_m, found.laser_m.y_m - truth.y_m);
    std::printf("%s from (%.2f, %.2f) by (%+.2f, %+.2f): error %.4f m, score %.3f (at the prediction %.3f)\n",
                world.c_str(), from.x_m, from.y_m, t.x_m, t.y_m, error_m, found.score, map.score(points, predicted));
    EXPECT_GT(found.score, 0.8) << "a good match scores near 1";
    worst_m = std::max(worst_m, error_m);
  }
  return worst_m;
}

const std::vector<Spot> kTranslations = {{0.3, 0}, {0, -0.3}, {0.2, 0.2}, {-0.21, 0.21}, {-0.1, -0.25},
                                         {0.05, -0.02}, {0.0, 0.0}, {-0.3, 0.0}, {0.12, 0.27}};

}  // namespace

TEST(ScanMap, RecoversAKnownTranslationInTheHouse) {
  // The roomba's start, the living room's middle, and the bedroom.
  for (Spot from : {Spot{-1, 1.5}, Spot{-2.0, -1.0}, Spot{2.2, -1.9}}) {
    for (double yaw : {0.0, 2.0}) {
      SCOPED_TRACE("from " + std::to_string(from.x_m) + ", " + std::to_string(from.y_m) + " yaw " + std::to_string(yaw));
      EXPECT_LT(worstRecovery("vacuum.world", "roomba", "", from, yaw, kTranslations), 0.02);
    }
  }
}

TEST(ScanMap, RecoversAKnownTranslationInAGeneratedHouse) {
  // worlds/house_3x2.world (worlds/tools/make_house.py): the start, and two other rooms.
  for (Spot from : {Spot{-3.245, -1.61}, Spot{1.0, 0.8}, Spot{2.5, -0.5}}) {
    for (double yaw : {0.0, -2.5}) {
      SCOPED_TRACE("from " + std::to_string(from.x_m) + ", " + std::to_string(from.y_m) + " yaw " + std::to_string(yaw));
      EXPECT_LT(worstRecovery("house_3x2.world", "roomba", "", from, yaw, kTranslations), 0.02);
    }
  }
}

TEST(ScanMap, AScanOfAnotherPlaceMatchesPoorly) {
  aula::test::PlainRobot robot("vacuum.world", "roomba", 1, 1);
  ScanMap map;
  robot.place(-1, 1.5, 0);
  map.insert(robot.laser().getLaserData(), 0, {0.139, 0});
  robot.place(3.0, -2.5, 0);  // the bedroom: other walls
  const auto points = ScanMap::endpoints(robot.laser().getLaserData(), 0, 9.0, 2);
  EXPECT_LT(map.match(points, {0.139, 0}, 0.1).score, 0.6);
}

TEST(ScanMap, DrawsWallsOccupiedAndTheFloorFree) {
  aula::test::PlainRobot robot("vacuum.world", "roomba", 1, 1);
  ScanMap map;
  robot.place(-1, 1.5, 0);  // facing +x; the map's origin is this spot
  map.insert(robot.laser().getLaserData(), 0, {0.139, 0});
  // Straight ahead along y = 1.5: what the laser sees first is occupied, the floor before free.
  const double ahead_m = robot.laser().getLaserData().values_m[90] + 0.139;
  const int row = map.row(0.0);
  EXPECT_TRUE(map.occupied(map.col(ahead_m + 0.005), row) || map.occupied(map.col(ahead_m - 0.005), row)) << ahead_m;
  EXPECT_TRUE(map.knownFree(map.col(ahead_m / 2), row));
  EXPECT_FALSE(map.known(map.col(-1.0), row)) << "behind the laser nothing is seen";
  EXPECT_NEAR(map.clearanceM(map.col(ahead_m - 0.1), row), 0.1, 0.03);
}

// A thin wall seen from one side only: a scan of its other face (0.2 m behind) is new, never
// matched to the face drawn, where it would pull the estimate 0.2 m through the wall.
TEST(ScanMap, AWallsOtherFaceIsNotMatchedToTheFaceSeen) {
  const auto scan = aula::test::syntheticScan(181, -0.5, 0.5, [](double a) { return 1.0 / std::cos(a); });
  ScanMap map;
  map.insert(scan, 0, {-1.0, 0});  // facing +x, the wall's face at x = 0
  const auto same_face = ScanMap::endpoints(scan, 0, 9.0);
  EXPECT_EQ(map.seen(same_face, {-1.0, 0}).size(), same_face.size());
  // From x = 1.2 facing -x: the wall's other face, at x = 0.2.
  const auto other_face = ScanMap::endpoints(scan, M_PI, 9.0);
  EXPECT_TRUE(map.seen(other_face, {1.2, 0}).empty());
  EXPECT_LT(map.score(other_face, {1.0, 0}), 0.05) << "shifted onto the face seen, it must not fit";
}

// A beam lost (no echo: it reads the laser's maximum range, as the realistic noise's 1 % do)
// says nothing of the walls: carved free, it ran through them and drew rooms not seen yet as seen.
TEST(ScanMap, ABeamWithNoEchoCarvesNothing) {
  auto scan = aula::test::syntheticScan(181, -0.5, 0.5, [](double a) { return 1.0 / std::cos(a); });
  scan.values_m[90] = static_cast<float>(scan.maxRange);  // straight ahead: lost
  ScanMap map;
  map.insert(scan, 0, {-1.0, 0});  // facing +x, the wall's face at x = 0
  const int row = map.row(0.0);
  EXPECT_TRUE(map.knownFree(map.col(-0.5), map.row(0.1))) << "its neighbours carve the floor before the wall";
  EXPECT_FALSE(map.known(map.col(2.0), row)) << "nothing beyond the wall is seen";
  EXPECT_FALSE(map.known(map.col(-0.5), row) && !map.knownFree(map.col(-0.5), row)) << "no wall where it ended";
}

// bounded: the best fit within the window, even where a better one lies just beyond it.
TEST(ScanMap, ABoundedMatchStaysInItsWindow) {
  const auto scan = aula::test::syntheticScan(181, -0.5, 0.5, [](double a) { return 1.0 / std::cos(a); });
  ScanMap map;
  map.insert(scan, 0, {-1.0, 0});
  const auto points = ScanMap::endpoints(scan, 0, 9.0);
  const Point2 predicted{-1.12, 0};  // the laser was 0.12 m further on
  EXPECT_NEAR(map.matchSeen(points, predicted, 0.05).laser_m.x_m, -1.0, 0.01) << "the climb leaves the window";
  const auto bounded = map.matchSeen(points, predicted, 0.05, true);
  EXPECT_LE(std::abs(bounded.laser_m.x_m - predicted.x_m), 0.05 + 1e-9);
  EXPECT_GT(bounded.laser_m.x_m, predicted.x_m + 0.03) << "the window's best, towards the fit";
}
