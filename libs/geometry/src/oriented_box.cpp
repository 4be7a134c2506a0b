#include "aula/geometry/oriented_box.hpp"

#include <limits>

namespace aula::geometry {
namespace {

using Corners = std::array<Eigen::Vector2d, 4>;

// The least overlap of the projections of a and b on the edge normals of either (unit length),
// m: negative when some normal separates them.
double leastOverlap(const Corners& a, const Corners& b) {
  double least = std::numeric_limits<double>::infinity();
  for (const Corners* p : {&a, &b}) {
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector2d& u = (*p)[i];
      const Eigen::Vector2d& v = (*p)[(i + 1) % 4];
      const double length = std::hypot(v.x() - u.x(), v.y() - u.y());
      if (!(length > 0)) continue;  // a degenerate edge has no normal
      const double nx = -(v.y() - u.y()) / length, ny = (v.x() - u.x()) / length;
      double amin = std::numeric_limits<double>::infinity(), amax = -amin, bmin = amin, bmax = -amin;
      for (const auto& q : a) {
        const double d = nx * q.x() + ny * q.y();
        amin = std::min(amin, d);
        amax = std::max(amax, d);
      }
      for (const auto& q : b) {
        const double d = nx * q.x() + ny * q.y();
        bmin = std::min(bmin, d);
        bmax = std::max(bmax, d);
      }
      least = std::min(least, std::min(amax, bmax) - std::max(amin, bmin));
      if (least < 0) return least;
    }
  }
  return least;
}

// True when some edge normal of a or b separates their projections.
bool separated(const Corners& a, const Corners& b) { return leastOverlap(a, b) < 0; }

double pointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x() - (a.x() + t * dx), p.y() - (a.y() + t * dy));
}

}  // namespace

bool overlap(const OrientedBox& a, const OrientedBox& b) { return !separated(a.corners(), b.corners()); }

double penetration(const OrientedBox& a, const OrientedBox& b) {
  return std::max(0.0, leastOverlap(a.corners(), b.corners()));
}

double distance(const OrientedBox& a, const OrientedBox& b) {
  const Corners ca = a.corners(), cb = b.corners();
  if (!separated(ca, cb)) return 0.0;
  // Disjoint convex polygons: the closest pair involves a vertex of one and an edge of the other.
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      best = std::min(best, pointSegmentDistance(ca[i], cb[j], cb[(j + 1) % 4]));
      best = std::min(best, pointSegmentDistance(cb[j], ca[i], ca[(i + 1) % 4]));
    }
  }
  return best;
}

}  // namespace aula::geometry
