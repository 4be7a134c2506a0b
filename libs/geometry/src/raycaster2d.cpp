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

// A direction's angle in quarter turns, [0, 4), monotonic in the true angle and without atan2:
// p(-v) = p(v) + 2. Only orders directions; v must not be zero.
double pseudoAngle(double x, double y) {
  if (y >= 0) return x >= 0 ? y / (x + y) : 1 - x / (y - x);
  return x < 0 ? 2 - y / (-x - y) : 3 + x / (x - y);
}

// A scan's candidates are skipped only with margins far above the functions' rounding (their t
// is within ~1e-12 relative of the exact hit, which is never nearer than the object's distance):
// nearer than kNear_m, an object is tried on every beam; a direction within kTurnSlack of its
// outline's counts as reaching it; a beam is spared an object only when the object's distance,
// less kDistanceSlack of it and of a metre, is not below the beam's best.
constexpr double kNear_m = 1e-2;
constexpr double kTurnSlack = 1e-6;
constexpr double kDistanceSlack = 1e-6;
// Beyond it a nearly parallel segment test could land nearer than its slack allows: scans cast farther walk.
constexpr double kMaxFastRange_m = 1000.0;

// The origin (nearly) on a segment's line: a ray along it divides rounding noise by rounding
// noise, hitting anywhere, even behind. Such scans walk, as they always did.
bool onItsLine(const Eigen::Vector2d& o, const Segment2& s) {
  const Eigen::Vector2d e = s.b_m - s.a_m, w = s.a_m - o;
  const double len = e.norm();
  return std::abs(w.x() * e.y() - w.y() * e.x()) < kTurnSlack * len * (1 + w.norm() + len);
}

// The beams, as up to two spans [first, last], whose direction is within the angular span of
// `points` seen from o, widened by kTurnSlack and by a beam on each side. `turn0` is beam 0's
// pseudo-angle, first_beam[b] the first beam whose pseudo-angle from beam 0 is at least b * 4 / B
// (B = first_beam.size() - 1 buckets, a power of two). The points' span is under half a turn
// (the origin is outside their hull) unless it straddles half a turn within the slack: every beam then.
void beamSpans(const Eigen::Vector2d* points, int count, const Eigen::Vector2d& o, double turn0,
               const std::vector<int>& first_beam, int spans[2][2]) {
  const int buckets = static_cast<int>(first_beam.size()) - 1, n = first_beam.back();
  spans[0][0] = 0;
  spans[0][1] = n - 1;
  spans[1][0] = 0;
  spans[1][1] = -1;
  double q[4], lo = 4, hi = 0;
  for (int k = 0; k < count; ++k) {
    q[k] = pseudoAngle(points[k].x() - o.x(), points[k].y() - o.y()) - turn0;
    if (q[k] < 0) q[k] += 4;
    if (!(q[k] >= 0)) return;
    lo = std::min(lo, q[k]);
    hi = std::max(hi, q[k]);
  }
  double from = lo, to = hi;  // on the circle of pseudo-angles, from <= to
  if (hi - lo >= 2 + kTurnSlack) {  // across beam 0's direction
    double below = 0, above = 4;
    for (int k = 0; k < count; ++k) {
      if (q[k] < 2) {
        below = std::max(below, q[k]);
      } else {
        above = std::min(above, q[k]);
      }
    }
    from = above;
    to = below + 4;
  } else if (hi - lo > 2 - kTurnSlack) {
    return;
  }
  from -= kTurnSlack;
  to += kTurnSlack;
  auto bucket = [&](double x) { return static_cast<int>(std::clamp(x * buckets / 4, 0.0, buckets - 1.0)); };
  auto beams = [&](double a, double b, int* span) {  // 0 <= a, b < 4 or past it
    span[0] = std::max(first_beam[static_cast<size_t>(bucket(a))] - 1, 0);
    span[1] = std::min(first_beam[static_cast<size_t>(bucket(b)) + 1], n);  // the last one's index + 1, plus a beam
  };
  if (from < 0) {
    beams(from + 4, 4, spans[0]);
    beams(0, to, spans[1]);
  } else if (to >= 4) {
    beams(from, 4, spans[0]);
    beams(0, to - 4, spans[1]);
  } else {
    beams(from, to, spans[0]);
  }
  for (int k = 0; k < 2; ++k) spans[k][1] = std::min(spans[k][1], n - 1);
}

double distanceToSegment(const Eigen::Vector2d& o, const Segment2& s) {
  const Eigen::Vector2d e = s.b_m - s.a_m, w = o - s.a_m;
  const double len2 = e.squaredNorm();
  const double u = len2 > 0 ? std::clamp(w.dot(e) / len2, 0.0, 1.0) : 0.0;
  return (w - u * e).norm();
}

}  // namespace

Raycaster2D::Raycaster2D(Obstacles2D statics, double cell_size_m)
    : statics_(std::move(statics)), cell_m_(cell_size_m) {
  rect_frames_.reserve(statics_.rects.size());
  for (const auto& r : statics_.rects) rect_frames_.push_back(RectFrame::of(r));
  rect_corners_.reserve(statics_.rects.size());
  for (const auto& r : statics_.rects) rect_corners_.push_back(r.corners());
  // Objects the grid would file oddly (non-finite, negative sizes) keep every scan on the walk.
  auto finite = [](const Eigen::Vector2d& v) { return v.allFinite(); };
  for (const auto& r : statics_.rects) {
    walk_only_ |= !(std::isfinite(r.centre.x_m) && std::isfinite(r.centre.y_m) && std::isfinite(r.centre.yaw_rad) &&
                    r.length_m >= 0 && r.width_m >= 0 && std::isfinite(r.length_m) && std::isfinite(r.width_m));
  }
  for (const auto& c : statics_.circles) walk_only_ |= !(finite(c.center_m) && c.radius_m >= 0 && std::isfinite(c.radius_m));
  for (const auto& g : statics_.segments) walk_only_ |= !(finite(g.a_m) && finite(g.b_m));
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

// What a scan's beams share: the origin in each rectangle's frame, and for the scan by objects
// the beams' directions, their best hits so far and the objects within reach. Only the work
// changes: every test computes what cast() computes.
struct Raycaster2D::ScanScratch {
  std::vector<LocalOrigin> local;        // per rectangle
  std::vector<Eigen::Vector2d> beam;     // per beam: (cos, sin) of its angle
  std::vector<double> turn;              // per beam: pseudo-angle from beam 0's, nondecreasing
  std::vector<double> best;              // per beam: nearest hit so far
  std::vector<int> first_beam;           // per pseudo-angle bucket: first beam at or past its start
  double turn0 = 0.0;                    // beam 0's pseudo-angle
  std::vector<std::pair<double, int>> candidates;  // (distance, id), objects within reach
  std::vector<unsigned> seen;            // per object: the scan that listed it (grid listing)
  unsigned stamp = 0;
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
  thread_local ScanScratch scratch;  // one per thread: scan() stays const and shareable, and allocates once
  scratch.local.clear();
  for (const RectFrame& r : rect_frames_) scratch.local.push_back(localOrigin(request.origin_m, r));
  const bool by_objects = scanByObjects(request, dynamic, scratch);
  for (int i = 0; i < request.num_beams; ++i) {
    double r;
    if (by_objects) {
      r = scratch.best[static_cast<size_t>(i)];
    } else {
      const double angle = request.yaw_rad + request.min_angle_rad + i * request.angle_increment_rad;
      r = castAlong(request.origin_m, Eigen::Vector2d(std::cos(angle), std::sin(angle)), request.max_range_m,
                    dynamic, &scratch);
    }
    r = std::clamp(r, request.min_range_m, request.max_range_m);
    ranges_m[i] = static_cast<float>(r);
  }
}

// The scan by objects: each beam's best is the minimum of the same tests castAlong would make,
// over every object that could beat it. False (nothing decided) for scans it does not cover: a
// full turn of beams, beams not in angular order, non-finite input, very long range, the origin
// on a segment's line.
bool Raycaster2D::scanByObjects(const ScanRequest& request, const Obstacles2D* dynamic, ScanScratch& s) const {
  const int n = request.num_beams;
  if (cells_.empty() || walk_only_ || n < 2 || !request.origin_m.allFinite() || !(request.max_range_m > 0) ||
      !(request.max_range_m <= kMaxFastRange_m)) {
    return false;
  }
  const auto beams = static_cast<size_t>(n);
  s.beam.resize(beams);
  s.turn.resize(beams);
  for (int i = 0; i < n; ++i) {
    const double angle = request.yaw_rad + request.min_angle_rad + i * request.angle_increment_rad;
    s.beam[static_cast<size_t>(i)] = Eigen::Vector2d(std::cos(angle), std::sin(angle));  // as castAlong's caller
  }
  s.turn0 = pseudoAngle(s.beam[0].x(), s.beam[0].y());
  for (size_t i = 0; i < beams; ++i) {
    double q = pseudoAngle(s.beam[i].x(), s.beam[i].y()) - s.turn0;
    if (q < 0) q += 4;
    if (!(q <= 4 - kTurnSlack) || (i > 0 && q < s.turn[i - 1])) return false;
    s.turn[i] = q;
  }
  // Buckets of pseudo-angle (a power of two of them, so that a bucket's start is exact).
  int buckets = 1;
  while (buckets < 2 * n && buckets < 8192) buckets *= 2;
  s.first_beam.resize(static_cast<size_t>(buckets) + 1);
  const double width = 4.0 / buckets;
  for (int b = 0, i = 0; b < buckets; ++b) {
    while (i < n && s.turn[static_cast<size_t>(i)] < b * width) ++i;
    s.first_beam[static_cast<size_t>(b)] = i;
  }
  s.first_beam[static_cast<size_t>(buckets)] = n;

  if (!collectCandidates(request, s)) return false;
  s.best.assign(beams, request.max_range_m);
  if (dynamic != nullptr) {
    for (size_t i = 0; i < beams; ++i) s.best[i] = std::min(s.best[i], castBrute(request.origin_m, s.beam[i], *dynamic, kInf));
  }
  std::sort(s.candidates.begin(), s.candidates.end());  // nearest first: they bound the farther ones' beams
  // Past the farthest best, no object can beat any beam: `bound` is at least that, refreshed
  // when an object reaches it, and the candidates' distances only grow.
  double bound = request.max_range_m;
  size_t since_bound = 0;
  for (const auto& [distance_m, id] : s.candidates) {
    const double beat_m = distance_m * (1 - kDistanceSlack) - kDistanceSlack;  // no test of it returns less
    if (!(beat_m < bound) && since_bound > 0) {
      bound = *std::max_element(s.best.begin(), s.best.end());
      since_bound = 0;
    }
    if (!(beat_m < bound)) break;
    castObject(request, id, beat_m, distance_m < kNear_m, s);
    ++since_bound;
  }
  return true;
}

// Objects whose distance from the origin is within max_range: the grid's, from the cells around
// the origin, when they are fewer than all objects; else all objects. False when the origin lies
// on a segment's line (the scan walks).
bool Raycaster2D::collectCandidates(const ScanRequest& request, ScanScratch& s) const {
  const int rects = static_cast<int>(statics_.rects.size()), circles = static_cast<int>(statics_.circles.size());
  const int count = rects + circles + static_cast<int>(statics_.segments.size());
  const Eigen::Vector2d& o = request.origin_m;
  s.candidates.clear();
  auto consider = [&](int id) {  // false: on a segment's line
    double distance_m;
    if (id < rects) {
      const LocalOrigin& l = s.local[static_cast<size_t>(id)];
      const RectFrame& f = rect_frames_[static_cast<size_t>(id)];
      const double ex = std::max(std::abs(l.x) - f.half_length_m, 0.0), ey = std::max(std::abs(l.y) - f.half_width_m, 0.0);
      distance_m = std::sqrt(ex * ex + ey * ey);
    } else if (id < rects + circles) {
      const Circle2& c = statics_.circles[static_cast<size_t>(id - rects)];
      distance_m = std::max((o - c.center_m).norm() - c.radius_m, 0.0);
    } else {
      const Segment2& g = statics_.segments[static_cast<size_t>(id - rects - circles)];
      if (onItsLine(o, g)) return false;
      distance_m = distanceToSegment(o, g);
    }
    if (distance_m * (1 - kDistanceSlack) - kDistanceSlack < request.max_range_m) s.candidates.emplace_back(distance_m, id);
    return true;
  };
  // Cells as the constructor numbers them (monotonic in x and y), the double clamped before the cast.
  const double reach_m = request.max_range_m * (1 + 1e-3) + 1e-3;
  auto cell = [&](double v, double lo, int n) {
    return std::clamp(static_cast<int>(std::clamp((v - lo) / cell_m_, -1.0, static_cast<double>(n))), 0, n - 1);
  };
  const int c0 = cell(o.x() - reach_m, grid_min_.x(), cols_), c1 = cell(o.x() + reach_m, grid_min_.x(), cols_);
  const int r0 = cell(o.y() - reach_m, grid_min_.y(), rows_), r1 = cell(o.y() + reach_m, grid_min_.y(), rows_);
  if (static_cast<long>(c1 - c0 + 1) * (r1 - r0 + 1) >= count) {
    for (int id = 0; id < count; ++id) {
      if (!consider(id)) return false;
    }
    return true;
  }
  if (s.seen.size() < static_cast<size_t>(count)) s.seen.resize(static_cast<size_t>(count), 0);
  if (++s.stamp == 0) {  // wrapped: forget every scan's marks
    std::fill(s.seen.begin(), s.seen.end(), 0u);
    s.stamp = 1;
  }
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      for (const int id : cells_[static_cast<size_t>(r) * cols_ + c]) {
        if (s.seen[static_cast<size_t>(id)] == s.stamp) continue;
        s.seen[static_cast<size_t>(id)] = s.stamp;
        if (!consider(id)) return false;
      }
    }
  }
  return true;
}

// Tests one object on the beams whose direction is within its outline's angular span (every
// beam when it is `near`) and whose best so far exceeds `beat_m`, below which no test of it lands.
void Raycaster2D::castObject(const ScanRequest& request, int id, double beat_m, bool near, ScanScratch& s) const {
  const int n = request.num_beams;
  const int rects = static_cast<int>(statics_.rects.size()), circles = static_cast<int>(statics_.circles.size());
  const Eigen::Vector2d& o = request.origin_m;
  int spans[2][2] = {{0, n - 1}, {0, -1}};
  if (!near) {
    std::array<Eigen::Vector2d, 4> outline;
    int points = 2;
    if (id < rects) {
      outline = rect_corners_[static_cast<size_t>(id)];
      points = 4;
    } else if (id < rects + circles) {
      // The near corners of the square around the circle that faces the origin: its tangents lie between them.
      const Circle2& c = statics_.circles[static_cast<size_t>(id - rects)];
      const Eigen::Vector2d u = (c.center_m - o).normalized() * c.radius_m, v(-u.y(), u.x());
      outline[0] = c.center_m - u + v;
      outline[1] = c.center_m - u - v;
    } else {
      const Segment2& g = statics_.segments[static_cast<size_t>(id - rects - circles)];
      outline[0] = g.a_m;
      outline[1] = g.b_m;
    }
    beamSpans(outline.data(), points, o, s.turn0, s.first_beam, spans);
  }
  for (const auto& span : spans) {
    for (int i = span[0]; i <= span[1]; ++i) {
      double& best = s.best[static_cast<size_t>(i)];
      if (!(beat_m < best)) continue;
      const Eigen::Vector2d& d = s.beam[static_cast<size_t>(i)];
      const double t = id < rects ? rayRect(s.local[static_cast<size_t>(id)], d, rect_frames_[static_cast<size_t>(id)], best)
                                  : castOne(o, d, id, rects, circles);
      best = std::min(best, t);
    }
  }
}

}  // namespace aula::geometry
