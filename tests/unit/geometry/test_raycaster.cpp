#include <aula/geometry/raycaster2d.hpp>
#include <aula/world/obstacle_slice.hpp>
#include <aula/world/world_spec.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace aula::geometry;

namespace {
OrientedBox rect(double cx, double cy, double yaw, double hx, double hy) { return {{cx, cy, yaw}, 2 * hx, 2 * hy}; }

// Brute force reference: every obstacle, exact intersections by sampling-free formulas.
double bruteForce(const Obstacles2D& obstacles, const Eigen::Vector2d& o, double angle, double max_range) {
  Raycaster2D none;  // no statics: only the "dynamic" list, tested brute force
  return none.cast(o, angle, max_range, &obstacles);
}

// Rectangles, circles and segments (a mesh's cross-section: any length and direction) strewn
// over the square of half side half_m, sizes up to size_m.
Obstacles2D randomWorld(std::mt19937& rng, double half_m, double size_m, int rects, int circles, int segments) {
  std::uniform_real_distribution<double> pos(-half_m, half_m), size(size_m / 60, size_m), angle(-M_PI, M_PI),
      radius(size_m / 60, size_m / 2);
  Obstacles2D obs;
  for (int i = 0; i < rects; ++i) obs.rects.push_back(rect(pos(rng), pos(rng), angle(rng), size(rng), size(rng) / 3));
  for (int i = 0; i < circles; ++i) obs.circles.push_back({{pos(rng), pos(rng)}, radius(rng)});
  for (int i = 0; i < segments; ++i) {
    const Eigen::Vector2d a(pos(rng), pos(rng));
    obs.segments.push_back({a, a + size(rng) * Eigen::Vector2d(std::cos(angle(rng)), std::sin(angle(rng)))});
  }
  return obs;
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
  std::uniform_real_distribution<double> pos(-50, 50), angle(-M_PI, M_PI);
  const Obstacles2D obs = randomWorld(rng, 50, 6, 150, 50, 100);
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

// scan() finds each beam's nearest object its own way (objects near to far, each on the beams
// its outline spans); its ranges must be the very floats of the walk cast() takes along each
// beam, and of the brute-force minimum over every object: same bits, not merely close.
namespace {

struct ScanCheck {
  long scans = 0, beams = 0, mismatches = 0;
  std::string first;  // the first mismatch, described
};

float clampedAsScan(double r, const ScanRequest& req) {
  return static_cast<float>(std::clamp(r, req.min_range_m, req.max_range_m));
}

Obstacles2D merged(const Obstacles2D& a, const Obstacles2D* b) {
  Obstacles2D all = a;
  if (b == nullptr) return all;
  all.rects.insert(all.rects.end(), b->rects.begin(), b->rects.end());
  all.circles.insert(all.circles.end(), b->circles.begin(), b->circles.end());
  all.segments.insert(all.segments.end(), b->segments.begin(), b->segments.end());
  return all;
}

// One scan against the walk beam by beam (and, when `brute` is given, against the minimum over
// every object of `brute`: the statics and the dynamic ones).
void checkScan(const Raycaster2D& caster, const ScanRequest& req, const Obstacles2D* dynamic, const Obstacles2D* brute,
               ScanCheck& check) {
  std::vector<float> ranges(static_cast<size_t>(req.num_beams), -1.0f);
  caster.scan(req, ranges.data(), dynamic);
  const Raycaster2D none;
  ++check.scans;
  for (int i = 0; i < req.num_beams; ++i) {
    const double angle = req.yaw_rad + req.min_angle_rad + i * req.angle_increment_rad;  // as scan() computes it
    const float walk = clampedAsScan(caster.cast(req.origin_m, angle, req.max_range_m, dynamic), req);
    const float got = ranges[static_cast<size_t>(i)];
    bool same = std::memcmp(&walk, &got, sizeof got) == 0;
    float all = walk;
    if (brute != nullptr) {
      all = clampedAsScan(none.cast(req.origin_m, angle, req.max_range_m, brute), req);
      same = same && std::memcmp(&all, &got, sizeof got) == 0;
    }
    ++check.beams;
    if (same) continue;
    if (check.mismatches++ == 0) {
      std::ostringstream out;
      out << std::setprecision(17) << "origin (" << req.origin_m.x() << ", " << req.origin_m.y() << ") yaw " << req.yaw_rad
          << " beam " << i << " of " << req.num_beams << ": scan " << got << ", walk " << walk << ", brute force " << all;
      check.first = out.str();
    }
  }
}

ScanRequest laserRequest(int beams, double fov_rad, double min_range_m, double max_range_m) {
  ScanRequest req;
  req.num_beams = beams;
  req.min_angle_rad = -fov_rad / 2;
  req.angle_increment_rad = fov_rad / (beams - 1);
  req.min_range_m = min_range_m;
  req.max_range_m = max_range_m;
  return req;
}

// The lasers scanned: the roomba's (180 beams over half a turn), narrower and wider ones, and
// one of nearly a full turn.
std::vector<ScanRequest> lasers() {
  return {laserRequest(180, M_PI, 0.08, 10.0), laserRequest(180, M_PI, 0.0, 4.0), laserRequest(61, 1.0, 0.1, 30.0),
          laserRequest(270, 1.5 * M_PI, 0.05, 80.0), laserRequest(360, 2 * M_PI * 359 / 360, 0.0, 10.0),
          laserRequest(2, 0.5, 0.0, 10.0), laserRequest(181, M_PI + 0.2, 0.0, 20.0)};
}

// The points whose directions bound the objects' shadows: corners, ends, points of circles.
std::vector<Eigen::Vector2d> vertices(const Obstacles2D& obs) {
  std::vector<Eigen::Vector2d> out;
  for (const auto& r : obs.rects) {
    for (const auto& c : r.corners()) out.push_back(c);
  }
  for (const auto& c : obs.circles) {
    for (int k = 0; k < 8; ++k) out.push_back(c.center_m + c.radius_m * Eigen::Vector2d(std::cos(k * M_PI / 4), std::sin(k * M_PI / 4)));
  }
  for (const auto& s : obs.segments) {
    out.push_back(s.a_m);
    out.push_back(s.b_m);
  }
  return out;
}

// Poses from `origins`, for every laser, headed at multiples of pi/4, at random, or so that a
// beam aims at an object's corner (grazing it).
ScanCheck scanMany(const Raycaster2D& caster, const std::vector<Eigen::Vector2d>& origins, std::mt19937& rng,
                   const Obstacles2D* dynamic = nullptr, int brute_every = 0) {
  std::uniform_real_distribution<double> heading(-M_PI, M_PI);
  const auto all = merged(caster.statics(), dynamic);
  const auto requests = lasers();
  const auto corners = vertices(caster.statics());
  ScanCheck check;
  for (size_t k = 0; k < origins.size(); ++k) {
    ScanRequest req = requests[k % requests.size()];
    req.origin_m = origins[k];
    req.yaw_rad = k % 3 == 0 ? static_cast<double>(static_cast<int>(k / 3 % 8) - 4) * M_PI / 4 : heading(rng);
    if (k % 3 == 1 && !corners.empty()) {
      const Eigen::Vector2d to = corners[rng() % corners.size()] - req.origin_m;
      const int beam = static_cast<int>(rng() % static_cast<unsigned>(req.num_beams));
      req.yaw_rad = std::atan2(to.y(), to.x()) - req.min_angle_rad - beam * req.angle_increment_rad;
    }
    const bool brute = brute_every > 0 && k % static_cast<size_t>(brute_every) == 0;
    checkScan(caster, req, dynamic, brute ? &all : nullptr, check);
  }
  return check;
}

// Origins spread over [lo, hi] (inside and around a world), on the lines of a grid of `cell_m`
// starting at `grid_m` (the caster's cells, as its constructor places them), and near the
// objects' corners and faces.
std::vector<Eigen::Vector2d> origins(const Obstacles2D& obs, Eigen::Vector2d lo, Eigen::Vector2d hi, double grid_m,
                                     double cell_m, int count, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0, 1), tiny(-1e-9, 1e-9);
  std::vector<Eigen::Vector2d> out;
  for (int k = 0; static_cast<int>(out.size()) < count; ++k) {
    const Eigen::Vector2d p(lo.x() + unit(rng) * (hi.x() - lo.x()), lo.y() + unit(rng) * (hi.y() - lo.y()));
    switch (k % 5) {
      case 0:
      case 1:
        out.push_back(p);
        break;
      case 2: {  // on a cell's edge or corner
        const double gx = grid_m + std::floor((p.x() - grid_m) / cell_m) * cell_m;
        const double gy = grid_m + std::floor((p.y() - grid_m) / cell_m) * cell_m;
        out.push_back(k % 3 == 0 ? Eigen::Vector2d(gx, gy) : (k % 3 == 1 ? Eigen::Vector2d(gx, p.y()) : Eigen::Vector2d(p.x(), gy)));
        break;
      }
      case 3: {  // at a rectangle's corner, a hair off it, or a circle's rim
        if (!obs.rects.empty() && k % 2 == 0) {
          const auto corners = obs.rects[static_cast<size_t>(k) % obs.rects.size()].corners();
          const Eigen::Vector2d c = corners[static_cast<size_t>(k / 2) % 4];
          out.push_back(k % 4 == 0 ? c : Eigen::Vector2d(c.x() + tiny(rng), c.y() + tiny(rng)));
        } else if (!obs.circles.empty()) {
          const Circle2& c = obs.circles[static_cast<size_t>(k) % obs.circles.size()];
          const double a = 2 * M_PI * unit(rng);
          out.push_back(c.center_m + (c.radius_m + 1e-3 * unit(rng)) * Eigen::Vector2d(std::cos(a), std::sin(a)));
        } else {
          out.push_back(p);
        }
        break;
      }
      default: {  // on a segment, or its line beyond it, or a point along a rectangle's face
        if (!obs.segments.empty()) {
          const Segment2& s = obs.segments[static_cast<size_t>(k) % obs.segments.size()];
          const double u = k % 2 == 0 ? unit(rng) : 1 + unit(rng);
          out.push_back(s.a_m + u * (s.b_m - s.a_m));
        } else if (!obs.rects.empty()) {
          const auto corners = obs.rects[static_cast<size_t>(k) % obs.rects.size()].corners();
          const double u = unit(rng);
          out.push_back(corners[0] + u * (corners[1] - corners[0]) + Eigen::Vector2d(tiny(rng), tiny(rng)));
        } else {
          out.push_back(p);
        }
      }
    }
  }
  return out;
}

// A closed outline of `sides` segments around `centre`, radii alternating (a star when they differ):
// a mesh's cross-section.
void addOutline(Obstacles2D& obs, Eigen::Vector2d centre, double r_in, double r_out, int sides, double turn) {
  for (int k = 0; k < sides; ++k) {
    auto at = [&](int j) {
      const double a = turn + 2 * M_PI * j / sides, r = j % 2 ? r_in : r_out;
      return Eigen::Vector2d(centre + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
    };
    obs.segments.push_back({at(k), at(k + 1)});
  }
}

}  // namespace

TEST(Raycaster2DScan, IsTheWalkBitForBitInRoomsOnTheGrid) {
  // Axis-aligned rooms whose walls sit on whole metres, the walls of a mesh on them too, round
  // pillars: edges and origins on the cells' lines, rays along walls.
  Obstacles2D obs;
  obs.rects.push_back(rect(0, -10, 0, 10, 0.1));  // lower-left bounds corner (-10, -10.1)
  obs.rects.push_back(rect(0, 10, 0, 10, 0.1));
  obs.rects.push_back(rect(-10, 0, 0, 0.1, 10));
  obs.rects.push_back(rect(10, 0, 0, 0.1, 10));
  obs.rects.push_back(rect(0, 3, 0, 4, 0.1));
  obs.rects.push_back(rect(-3, -2, M_PI / 2, 5, 0.05));
  obs.rects.push_back(rect(5, 5, M_PI / 4, 1, 1));
  obs.rects.push_back(rect(2, -6, 0, 0, 1));  // no thickness
  obs.circles.push_back({{6, -4}, 0.5});
  obs.circles.push_back({{-6, 6}, 1.0});
  obs.segments.push_back({{-8, -8}, {-4, -8}});
  obs.segments.push_back({{-4, -8}, {-4, -5}});
  obs.segments.push_back({{-4, -5}, {-8, -8}});
  obs.segments.push_back({{1, 1}, {1, 1}});  // a point
  obs.segments.push_back({{3, 6}, {8, 6}});
  obs.segments.push_back({{-9, 8}, {9, 8}});  // long: a ray along it is not "parallel" to its test
  obs.segments.push_back({{-9.5, -9}, {-9.5, 9}});
  std::mt19937 rng(7);
  for (double cell : {1.0, 0.5, 2.0}) {
    const Raycaster2D caster(obs, cell);
    const double grid = -10.1 - 1e-6;  // the constructor's grid origin: the bounds less 1e-6
    auto points = origins(obs, {-12, -12}, {12, 12}, grid, cell, 4000, rng);
    for (int x = -11; x <= 11; ++x) {
      points.emplace_back(x, x % 3);      // on the walls' whole metres
      points.emplace_back(x + 0.25, 8);   // on a segment's line, on it and beyond it
      points.emplace_back(-9.5, x + 0.5);
      points.emplace_back(x + 0.5, 3.1);  // on a wall's face
      points.emplace_back(x, -9.9);
    }
    const auto check = scanMany(caster, points, rng, nullptr, 4);
    EXPECT_EQ(check.mismatches, 0) << check.first << " (cell " << cell << ")";
    EXPECT_GT(check.scans, 4100);
  }
}

TEST(Raycaster2DScan, IsTheWalkBitForBitInRandomAndClutteredWorlds) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> pos(-20, 20), size(0.05, 3), angle(-M_PI, M_PI);
  Obstacles2D sparse = randomWorld(rng, 20, 3, 60, 25, 40);
  for (int i = 0; i < 6; ++i) addOutline(sparse, {pos(rng), pos(rng)}, size(rng), size(rng), 2 * (3 + i * 5), angle(rng));
  Obstacles2D clutter;  // 600 small things in a 12 m room
  std::uniform_real_distribution<double> near(-6, 6), small(0.01, 0.3);
  for (int i = 0; i < 300; ++i) clutter.rects.push_back(rect(near(rng), near(rng), angle(rng), small(rng), small(rng)));
  for (int i = 0; i < 150; ++i) clutter.circles.push_back({{near(rng), near(rng)}, small(rng)});
  for (int i = 0; i < 30; ++i) addOutline(clutter, {near(rng), near(rng)}, small(rng), small(rng), 5, angle(rng));
  Obstacles2D robots;  // dynamic obstacles, tested brute force in both
  robots.circles.push_back({{1.0, 0.5}, 0.165});
  robots.rects.push_back(rect(-2, 2, 0.3, 1.0, 0.5));
  for (const auto* world : {&sparse, &clutter}) {
    for (double cell : {1.0, 0.3, 4.0}) {
      const Raycaster2D caster(*world, cell);
      const double extent = world == &sparse ? 24 : 8;
      const auto points = origins(*world, {-extent, -extent}, {extent, extent}, 0.0, cell, 3000, rng);
      auto check = scanMany(caster, points, rng, nullptr, world == &sparse ? 8 : 40);
      EXPECT_EQ(check.mismatches, 0) << check.first << " (cell " << cell << ")";
      check = scanMany(caster, std::vector<Eigen::Vector2d>(points.begin(), points.begin() + 600), rng, &robots, 40);
      EXPECT_EQ(check.mismatches, 0) << check.first << " (cell " << cell << ", with robots)";
    }
  }
}

TEST(Raycaster2DScan, IsTheWalkBitForBitInTheShippedHouse) {
  const auto spec = aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world");
  std::mt19937 rng(3);
  // 0.075 m: the roomba's laser (its mount's height in worlds/models/roomba/model.sdf, the robot on
  // the floor); and other heights, whose cuts hold other furniture.
  for (double z : {0.075, 0.02, 0.3, 0.9}) {
    const Obstacles2D obs = aula::world::sliceAtHeight(spec, z);
    ASSERT_FALSE(obs.rects.empty());
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e9), hi = -lo;
    for (const auto& r : obs.rects) {
      for (const auto& c : r.corners()) {
        lo = lo.cwiseMin(c);
        hi = hi.cwiseMax(c);
      }
    }
    const Raycaster2D caster(obs);
    const int count = z == 0.075 ? 12000 : 2000;
    const auto points = origins(obs, lo - Eigen::Vector2d::Constant(1), hi + Eigen::Vector2d::Constant(1), lo.x(), 1.0, count, rng);
    const auto check = scanMany(caster, points, rng, nullptr, 6);
    EXPECT_EQ(check.mismatches, 0) << check.first << " (z " << z << ")";
    EXPECT_EQ(check.scans, count);
  }
}
