#include <aula/geometry/raycaster2d.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace aula::geometry;

namespace {
OrientedBox rect(double cx, double cy, double yaw, double hx, double hy) { return {{cx, cy, yaw}, 2 * hx, 2 * hy}; }

// Brute force reference: every obstacle, exact intersections by sampling-free formulas.
double bruteForce(const Obstacles2D& obstacles, const Eigen::Vector2d& o, double angle, double max_range) {
  Raycaster2D none;  // no statics: only the "dynamic" list, tested brute force
  return none.cast(o, angle, max_range, &obstacles);
}
}  // namespace

TEST(Raycaster2D, HitsRotatedBoxesAndCirclesExactly) {
  Obstacles2D obs;
  obs.rects.push_back(rect(5, 0, 0, 1, 1));             // face at x = 4
  obs.rects.push_back(rect(0, 5, M_PI / 4, 1, 1));      // diamond: corner at y = 5 - sqrt(2)
  obs.circles.push_back({{-5, 0}, 0.5});                // surface at x = -4.5
  const Raycaster2D caster(obs);
  EXPECT_NEAR(caster.cast({0, 0}, 0.0, 10), 4.0, 1e-9);
  EXPECT_NEAR(caster.cast({0, 0}, M_PI / 2, 10), 5 - std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(caster.cast({0, 0}, M_PI, 10), 4.5, 1e-9);
  EXPECT_NEAR(caster.cast({0, 0}, -M_PI / 2, 10), 10.0, 1e-12);  // miss: max range
  EXPECT_NEAR(caster.cast({0, 0}, 0.0, 3.0), 3.0, 1e-12);        // beyond range
  // Oblique hit on the face x = 4 at 10 degrees (y = 0.705, inside the face).
  EXPECT_NEAR(caster.cast({0, 0}, M_PI / 18, 10), 4.0 / std::cos(M_PI / 18), 1e-9);
  EXPECT_NEAR(caster.cast({0, 0}, M_PI / 6, 10), 10.0, 1e-12);  // y = 2.3 at x = 4: passes the box
  // Grazing the box's corner (4, 1) exactly.
  EXPECT_NEAR(caster.cast({0, 0}, std::atan2(1.0, 4.0), 10), std::hypot(4.0, 1.0), 1e-9);
  // Inside an obstacle: distance 0.
  EXPECT_NEAR(caster.cast({5, 0}, 0.3, 10), 0.0, 1e-12);
}

TEST(Raycaster2D, ScanClampsToTheSensorRange) {
  Obstacles2D obs;
  obs.rects.push_back(rect(0.05, 0, 0, 0.01, 5));  // a wall 4 cm ahead
  const Raycaster2D caster(obs);
  ScanRequest req;
  req.num_beams = 3;
  req.min_angle_rad = -0.1;
  req.angle_increment_rad = 0.1;
  req.min_range_m = 0.08;
  req.max_range_m = 10;
  float ranges[3];
  caster.scan(req, ranges);
  for (float r : ranges) EXPECT_FLOAT_EQ(r, 0.08f) << "a touching wall must not look free";
  req.yaw_rad = M_PI;  // facing away: nothing
  caster.scan(req, ranges);
  for (float r : ranges) EXPECT_FLOAT_EQ(r, 10.0f);
}

TEST(Raycaster2D, GridAgreesWithBruteForceOnRandomWorlds) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> pos(-50, 50), size(0.1, 6), angle(-M_PI, M_PI), radius(0.1, 3);
  Obstacles2D obs;
  for (int i = 0; i < 150; ++i) obs.rects.push_back(rect(pos(rng), pos(rng), angle(rng), size(rng), size(rng) / 3));
  for (int i = 0; i < 50; ++i) obs.circles.push_back({{pos(rng), pos(rng)}, radius(rng)});
  for (int i = 0; i < 100; ++i) {  // a mesh's cross-section: segments of any length and direction
    const Eigen::Vector2d a(pos(rng), pos(rng));
    obs.segments.push_back({a, a + size(rng) * Eigen::Vector2d(std::cos(angle(rng)), std::sin(angle(rng)))});
  }
  for (double cell : {0.5, 1.0, 4.0}) {
    const Raycaster2D caster(obs, cell);
    for (int i = 0; i < 3000; ++i) {
      const Eigen::Vector2d o(pos(rng) * 1.2, pos(rng) * 1.2);
      const double a = i % 100 == 0 ? 0.0 : (i % 100 == 1 ? M_PI / 2 : angle(rng));  // axis-aligned too
      const double range = i % 2 ? 10.0 : 80.0;
      EXPECT_NEAR(caster.cast(o, a, range), bruteForce(obs, o, a, range), 1e-9) << "ray " << i << " cell " << cell;
    }
  }
}

TEST(Raycaster2D, DynamicObstaclesAreSeenToo) {
  Obstacles2D statics;
  statics.rects.push_back(rect(10, 0, 0, 1, 1));
  const Raycaster2D caster(statics);
  Obstacles2D robots;
  robots.circles.push_back({{3, 0}, 0.165});
  EXPECT_NEAR(caster.cast({0, 0}, 0, 20, &robots), 3 - 0.165, 1e-9);
  EXPECT_NEAR(caster.cast({0, 0}, 0, 20), 9.0, 1e-9);
}

TEST(Raycaster2D, SegmentsAreWallsOfNoThickness) {
  Obstacles2D obs;
  obs.segments.push_back({{4, -1}, {4, 1}});   // across the x axis at x = 4
  obs.segments.push_back({{-3, 0}, {-6, 0}});  // along the -x axis: the ray meets its nearer end
  const Raycaster2D caster(obs);
  EXPECT_NEAR(caster.cast({0, 0}, 0.0, 10), 4.0, 1e-12);
  EXPECT_NEAR(caster.cast({0, 0}, std::atan2(1.0, 4.0), 10), std::hypot(4.0, 1.0), 1e-9);  // its end
  EXPECT_NEAR(caster.cast({0, 0}, std::atan2(1.1, 4.0), 10), 10.0, 1e-12);                 // past its end
  EXPECT_NEAR(caster.cast({0, 0}, M_PI, 10), 3.0, 1e-12);
  EXPECT_NEAR(caster.cast({5, 0}, 0.0, 10), 10.0, 1e-12);  // behind the wall: nothing
}
