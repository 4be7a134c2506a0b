#include "aula/geometry/raycaster2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace aula::geometry {

RectFrame RectFrame::of(const OrientedBox& r) {
  RectFrame f;
  f.x_m = r.centre.x_m;
  f.y_m = r.centre.y_m;
  f.cos_yaw = std::cos(r.centre.yaw_rad);
  f.sin_yaw = std::sin(r.centre.yaw_rad);
  f.half_length_m = r.length_m / 2;
  f.half_width_m = r.width_m / 2;
  return f;
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A ray's origin in a rectangle's frame: the same for every beam of a scan.
struct LocalOrigin {
  double x, y;
};

LocalOrigin localOrigin(const Eigen::Vector2d& o, const RectFrame& r) {
  const double c = r.cos_yaw, s = r.sin_yaw;
  const double rx = o.x() - r.x_m, ry = o.y() - r.y_m;
  return {c * rx + s * ry, -s * rx + c * ry};
}

// Entry distance of the ray o + t d (|d| = 1) into an oriented rectangle, 0 if o is inside,
// +inf on a miss. Slab test in the rectangle's frame, `local` being o there. +inf too when the
// first slab already shows that the entry is not below `beat` (a nearer hit is known): the
// nearest hit is the same, and a test costs two divisions instead of four.
double rayRect(const LocalOrigin& local, const Eigen::Vector2d& d, const RectFrame& r, double beat = kInf) {
  const double c = r.cos_yaw, s = r.sin_yaw;
  const double ox = local.x, oy = local.y;
  const double dx = c * d.x() + s * d.y(), dy = -s * d.x() + c * d.y();
  double t0 = -kInf, t1 = kInf;
  const double hx = r.half_length_m, hy = r.half_width_m;
  if (std::abs(dx) < 1e-15) {
    if (ox < -hx || ox > hx) return kInf;
  } else {
    double a = (-hx - ox) / dx, b = (hx - ox) / dx;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t1 < 0 || t0 >= beat) return kInf;  // the entry is at t0 or later, the exit before 0
  }
  if (std::abs(dy) < 1e-15) {
    if (oy < -hy || oy > hy) return kInf;
  } else {
    double a = (-hy - oy) / dy, b = (hy - oy) / dy;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  if (t0 > t1 || t1 < 0) return kInf;
  return std::max(t0, 0.0);
}

double rayRect(const Eigen::Vector2d& o, const Eigen::Vector2d& d, const RectFrame& r) {
  return rayRect(localOrigin(o, r), d, r);
}

double rayRect(const Eigen::Vector2d& o, const Eigen::Vector2d& d, const OrientedBox& r) {
  return rayRect(o, d, RectFrame::of(r));
}

double rayCircle(const Eigen::Vector2d& o, const Eigen::Vector2d& d, const Circle2& c) {
  const Eigen::Vector2d rel = o - c.center_m;
  const double b = rel.dot(d);
  const double cc = rel.squaredNorm() - c.radius_m * c.radius_m;
  if (cc <= 0) return 0.0;  // inside
  const double disc = b * b - cc;
  if (disc < 0) return kInf;
  const double t = -b - std::sqrt(disc);
  return t >= 0 ? t : kInf;
}

// Where the ray o + t d meets the segment (the nearer end when it runs along it), +inf on a miss.
double raySegment(const Eigen::Vector2d& o, const Eigen::Vector2d& d, const Segment2& s) {
  const Eigen::Vector2d e = s.b_m - s.a_m, w = s.a_m - o;
  const double denom = d.x() * e.y() - d.y() * e.x();
  if (std::abs(denom) < 1e-15) {  // parallel: a hit only when the ray runs along the segment
    if (std::abs(w.x() * d.y() - w.y() * d.x()) > 1e-12) return kInf;
    const double ta = w.dot(d), tb = (s.b_m - o).dot(d);
    if (std::max(ta, tb) < 0) return kInf;
    return std::max(0.0, std::min(ta, tb));
  }
  const double t = (w.x() * e.y() - w.y() * e.x()) / denom;
  const double u = (w.x() * d.y() - w.y() * d.x()) / denom;
  return t >= 0 && u >= 0 && u <= 1 ? t : kInf;
}

double castBrute(const Eigen::Vector2d& o, const Eigen::Vector2d& d, const Obstacles2D& obstacles, double best) {
  for (const auto& r : obstacles.rects) best = std::min(best, rayRect(o, d, r));
  for (const auto& c : obstacles.circles) best = std::min(best, rayCircle(o, d, c));
  for (const auto& s : obstacles.segments) best = std::min(best, raySegment(o, d, s));
  return best;
}

// Axis-aligned bounds of an obstacle's footprint.
void boundsOf(const OrientedBox& r, Eigen::Vector2d& lo, Eigen::Vector2d& hi) {
  const Eigen::Vector2d centre(r.centre.x_m, r.centre.y_m), ext = r.boundingHalfExtents();
  lo = centre - ext;
  hi = centre + ext;
}
void boundsOf(const Circle2& c, Eigen::Vector2d& lo, Eigen::Vector2d& hi) {
  lo = c.center_m - Eigen::Vector2d::Constant(c.radius_m);
  hi = c.center_m + Eigen::Vector2d::Constant(c.radius_m);
}
void boundsOf(const Segment2& s, Eigen::Vector2d& lo, Eigen::Vector2d& hi) {
  lo = s.a_m.cwiseMin(s.b_m);
  hi = s.a_m.cwiseMax(s.b_m);
}

}  // namespace

Raycaster2D::Raycaster2D(Obstacles2D statics, double cell_size_m)
    : statics_(std::move(statics)), cell_m_(cell_size_m) {
  rect_frames_.reserve(statics_.rects.size());
  for (const auto& r : statics_.rects) rect_frames_.push_back(RectFrame::of(r));
  const size_t count = statics_.rects.size() + statics_.circles.size() + statics_.segments.size();
  if (count == 0) return;
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(kInf), hi = -lo;
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> boxes;
  boxes.reserve(count);
  for (const auto& r : statics_.rects) {
    Eigen::Vector2d a, b;
    boundsOf(r, a, b);
    boxes.emplace_back(a, b);
  }
  for (const auto& c : statics_.circles) {
    Eigen::Vector2d a, b;
    boundsOf(c, a, b);
    boxes.emplace_back(a, b);
  }
  for (const auto& s : statics_.segments) {
    Eigen::Vector2d a, b;
    boundsOf(s, a, b);
    boxes.emplace_back(a, b);
  }
  for (const auto& [a, b] : boxes) {
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(b);
  }
  grid_min_ = lo - Eigen::Vector2d::Constant(1e-6);
  cols_ = std::max(1, static_cast<int>(std::ceil((hi.x() - grid_min_.x()) / cell_m_)) + 1);
  rows_ = std::max(1, static_cast<int>(std::ceil((hi.y() - grid_min_.y()) / cell_m_)) + 1);
  cells_.assign(static_cast<size_t>(cols_) * rows_, {});
  for (size_t i = 0; i < boxes.size(); ++i) {
    const int id = static_cast<int>(i);
    const int c0 = std::clamp(static_cast<int>((boxes[i].first.x() - grid_min_.x()) / cell_m_), 0, cols_ - 1);
    const int c1 = std::clamp(static_cast<int>((boxes[i].second.x() - grid_min_.x()) / cell_m_), 0, cols_ - 1);
    const int r0 = std::clamp(static_cast<int>((boxes[i].first.y() - grid_min_.y()) / cell_m_), 0, rows_ - 1);
    const int r1 = std::clamp(static_cast<int>((boxes[i].second.y() - grid_min_.y()) / cell_m_), 0, rows_ - 1);
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) cells_[static_cast<size_t>(r) * cols_ + c].push_back(id);
    }
  }
}

double Raycaster2D::cast(const Eigen::Vector2d& origin, double angle_rad, double max_range_m,
                         const Obstacles2D* dynamic) const {
  return castAlong(origin, Eigen::Vector2d(std::cos(angle_rad), std::sin(angle_rad)), max_range_m, dynamic, nullptr);
}

// What a scan's beams share: the origin in each rectangle's frame. Only the work changes: every
// test computes what cast() computes.
struct Raycaster2D::ScanScratch {
  std::vector<LocalOrigin> local;  // per rectangle
};

double Raycaster2D::castAlong(const Eigen::Vector2d& origin, const Eigen::Vector2d& d, double max_range_m,
                              const Obstacles2D* dynamic, ScanScratch* scratch) const {
  double best = max_range_m;
  if (dynamic != nullptr) best = std::min(best, castBrute(origin, d, *dynamic, kInf));
  if (cells_.empty()) return best;

  // Clip the ray to the grid's box, then walk the cells it crosses (Amanatides-Woo).
  const Eigen::Vector2d gmax = grid_min_ + Eigen::Vector2d(cols_ * cell_m_, rows_ * cell_m_);
  double t_enter = 0.0, t_exit = best;
  for (int a = 0; a < 2; ++a) {
    if (std::abs(d[a]) < 1e-15) {
      if (origin[a] < grid_min_[a] || origin[a] > gmax[a]) return best;
      continue;
    }
    double t0 = (grid_min_[a] - origin[a]) / d[a], t1 = (gmax[a] - origin[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    t_enter = std::max(t_enter, t0);
    t_exit = std::min(t_exit, t1);
  }
  if (t_enter > t_exit) return best;
  const Eigen::Vector2d p = origin + d * (t_enter + 1e-12);
  int cx = std::clamp(static_cast<int>(std::floor((p.x() - grid_min_.x()) / cell_m_)), 0, cols_ - 1);
  int cy = std::clamp(static_cast<int>(std::floor((p.y() - grid_min_.y()) / cell_m_)), 0, rows_ - 1);
  const int step_x = d.x() > 0 ? 1 : -1, step_y = d.y() > 0 ? 1 : -1;
  const double dt_x = std::abs(d.x()) < 1e-15 ? kInf : cell_m_ / std::abs(d.x());
  const double dt_y = std::abs(d.y()) < 1e-15 ? kInf : cell_m_ / std::abs(d.y());
  const double next_bx = grid_min_.x() + (cx + (step_x > 0 ? 1 : 0)) * cell_m_;
  const double next_by = grid_min_.y() + (cy + (step_y > 0 ? 1 : 0)) * cell_m_;
  double t_x = std::abs(d.x()) < 1e-15 ? kInf : (next_bx - origin.x()) / d.x();
  double t_y = std::abs(d.y()) < 1e-15 ? kInf : (next_by - origin.y()) / d.y();

  const int rects = static_cast<int>(statics_.rects.size()), circles = static_cast<int>(statics_.circles.size());
  for (;;) {
    // An object may be tested again in a later cell: cheap, and keeps the caster stateless
    // (const and safe to share).
    for (const int id : cells_[static_cast<size_t>(cy) * cols_ + cx]) {
      double t;
      if (scratch != nullptr) {
        t = id < rects ? rayRect(scratch->local[static_cast<size_t>(id)], d, rect_frames_[static_cast<size_t>(id)], best)
                       : castOne(origin, d, id, rects, circles);
      } else {
        t = id < rects ? rayRect(localOrigin(origin, rect_frames_[static_cast<size_t>(id)]), d,
                                 rect_frames_[static_cast<size_t>(id)], best)
                       : castOne(origin, d, id, rects, circles);
      }
      best = std::min(best, t);
    }
    const double t_cell_exit = std::min(t_x, t_y);
    // A hit before this cell's exit cannot be beaten by anything in later cells.
    if (best <= t_cell_exit || t_cell_exit > t_exit) break;
    if (t_x < t_y) {
      cx += step_x;
      t_x += dt_x;
      if (cx < 0 || cx >= cols_) break;
    } else {
      cy += step_y;
      t_y += dt_y;
      if (cy < 0 || cy >= rows_) break;
    }
  }
  return best;
}

double Raycaster2D::castOne(const Eigen::Vector2d& origin, const Eigen::Vector2d& d, int id, int rects, int circles) const {
  return id < rects + circles ? rayCircle(origin, d, statics_.circles[static_cast<size_t>(id - rects)])
                              : raySegment(origin, d, statics_.segments[static_cast<size_t>(id - rects - circles)]);
}

void Raycaster2D::scan(const ScanRequest& request, float* ranges_m, const Obstacles2D* dynamic) const {
  ScanScratch scratch;
  scratch.local.reserve(rect_frames_.size());
  for (const RectFrame& r : rect_frames_) scratch.local.push_back(localOrigin(request.origin_m, r));
  for (int i = 0; i < request.num_beams; ++i) {
    const double angle = request.yaw_rad + request.min_angle_rad + i * request.angle_increment_rad;
    double r = castAlong(request.origin_m, Eigen::Vector2d(std::cos(angle), std::sin(angle)), request.max_range_m,
                         dynamic, &scratch);
    r = std::clamp(r, request.min_range_m, request.max_range_m);
    ranges_m[i] = static_cast<float>(r);
  }
}

}  // namespace aula::geometry
