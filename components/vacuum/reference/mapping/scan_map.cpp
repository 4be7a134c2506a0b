#include "scan_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace aula::vacuum::mapping {

ScanMap::ScanMap(const ScanMapSettings& settings) : s_(settings) {
  n_ = static_cast<int>(std::ceil(s_.size_m / s_.cell_m));
  origin_m_ = -0.5 * n_ * s_.cell_m;
  unit_m_ = s_.field_radius_m / 250.0;
  const size_t cells = static_cast<size_t>(n_) * n_;
  logodds_.assign(cells, 0);
  occupied_.assign(cells, 0);
  distance_.assign(cells, 255);
  for (auto& d : side_distance_) d.assign(cells, 255);
  for (auto& n : side_nearest_) n.assign(cells, {0, 0});
  const int reach = static_cast<int>(std::ceil(s_.field_radius_m / s_.cell_m)) + 1;
  for (int dj = -reach; dj <= reach; ++dj) {
    for (int di = -reach; di <= reach; ++di) {
      if ((std::hypot(di, dj) - 1) * s_.cell_m < s_.field_radius_m) stamp_.emplace_back(di, dj);
    }
  }
  min_i_ = min_j_ = n_;
  max_i_ = max_j_ = -1;
}

int ScanMap::col(double x_m) const { return static_cast<int>(std::floor((x_m - origin_m_) / s_.cell_m)); }
int ScanMap::row(double y_m) const { return static_cast<int>(std::floor((y_m - origin_m_) / s_.cell_m)); }
Point2 ScanMap::centre(int i, int j) const {
  return {origin_m_ + (i + 0.5) * s_.cell_m, origin_m_ + (j + 0.5) * s_.cell_m};
}

double ScanMap::clearanceM(int i, int j) const {
  if (!inside(i, j)) return 0.0;
  const uint8_t d = distance_[idx(i, j)];
  return d == 255 ? s_.field_radius_m : d * unit_m_;
}

namespace {

// The beams' directions, by rotating the first one a beam at a time (one sincos per scan, not
// one per beam: the largest cost of drawing a scan).
class BeamDirections {
 public:
  BeamDirections(const component::LaserData& scan, double laser_yaw_rad)
      : c_(std::cos(laser_yaw_rad + scan.minAngle)), s_(std::sin(laser_yaw_rad + scan.minAngle)),
        dc_(std::cos(scan.angleIncrement)), ds_(std::sin(scan.angleIncrement)) {}
  double cos() const { return c_; }
  double sin() const { return s_; }
  void next() {
    const double c = c_ * dc_ - s_ * ds_;
    s_ = s_ * dc_ + c_ * ds_;
    c_ = c;
  }

 private:
  double c_, s_, dc_, ds_;
};

}  // namespace

// Beams k and m (next to each other) hit the same surface: their hits are nearer than a beam step
// at a steep glance (0.05 m plus 0.1 m a metre of range), not across a depth step.
bool ScanMap::neighbours(const component::LaserData& scan, int k, int m) {
  const double rk = scan.values_m[k], rm = scan.values_m[m];
  const double gap_m = 0.05 + 0.1 * rk;
  // The law of cosines: the hits' distance from their ranges and the beams' angle.
  const double step_rad = (m - k) * scan.angleIncrement;
  return rk * rk + rm * rm - 2 * rk * rm * std::cos(step_rad) < gap_m * gap_m;
}

std::vector<Point2> ScanMap::surfaceLooks(const component::LaserData& scan, double laser_yaw_rad, double max_range_m) {
  const int n = scan.numLaser;
  const double limit_m = std::min(max_range_m, scan.maxRange - 1e-3);
  std::vector<Point2> end(n);
  std::vector<char> hit(n, 0);
  BeamDirections beam(scan, laser_yaw_rad);
  for (int k = 0; k < n; ++k, beam.next()) {
    const double r = scan.values_m[k];
    hit[k] = r > scan.minRange && r < limit_m;
    end[k] = {r * beam.cos(), r * beam.sin()};
  }
  const auto near = [&](int k, int m) { return m >= 0 && m < n && hit[m] && neighbours(scan, k, m); };
  std::vector<Point2> out(n);
  for (int k = 0; k < n; ++k) {
    if (!hit[k]) continue;
    const int a = near(k, k - 1) ? k - 1 : k, b = near(k, k + 1) ? k + 1 : k;
    if (a == b) {
      out[k] = end[k];
      continue;
    }
    double nx = -(end[b].y_m - end[a].y_m), ny = end[b].x_m - end[a].x_m;  // square to the surface
    if (nx * end[k].x_m + ny * end[k].y_m < 0) {
      nx = -nx;  // looking at the surface, away from the laser
      ny = -ny;
    }
    out[k] = {nx, ny};
  }
  return out;
}

std::vector<ScanPoint> ScanMap::endpoints(const component::LaserData& scan, double laser_yaw_rad, double max_range_m,
                                          int stride) {
  std::vector<ScanPoint> out;
  stride = std::max(1, stride);
  out.reserve(scan.numLaser / stride + 1);
  const std::vector<Point2> looks = surfaceLooks(scan, laser_yaw_rad, max_range_m);
  BeamDirections beam(scan, laser_yaw_rad);
  for (int i = 0; i < scan.numLaser; ++i, beam.next()) {
    const Point2 look = looks[i];
    if (i % stride != 0 || (look.x_m == 0 && look.y_m == 0)) continue;
    const double r = scan.values_m[i];
    out.push_back({r * beam.cos(), r * beam.sin(), side(look.x_m, look.y_m)});
  }
  return out;
}

void ScanMap::touch(int i, int j) {
  min_i_ = std::min(min_i_, i);
  max_i_ = std::max(max_i_, i);
  min_j_ = std::min(min_j_, j);
  max_j_ = std::max(max_j_, j);
}

int ScanMap::side(double dx, double dy) {
  if (std::abs(dx) >= std::abs(dy)) return dx > 0 ? 0 : 2;
  return dy > 0 ? 1 : 3;
}

// The match fields are stamped from the hit itself, not its cell's centre: a wall then sits
// where the laser saw it, not up to half a cell off. A hit goes into the field of its beam's
// side, and of the next side too unless the beam is within 11.5 degrees of an axis (a scan's
// beam at 44 degrees and the map's at 46 see the same face; 0.3 m away, the same wall point is
// seen up to 20 degrees apart). Measured on the ray-cast tests: 22.5 degrees left one match 8 cm
// off (test_scan_map), 30 degrees lost the plain-data run in house_3x2 (test_mapping_reference).
void ScanMap::occupy(int i, int j, Point2 hit_m, double beam_x, double beam_y) {
  uint8_t& cell = occupied_[idx(i, j)];
  if (!cell) {
    ++occupied_count_;
    touch(i, j);
    stamp(i, j, hit_m, -1);
    cell = kOccupiedBit;
  }
  const int own = side(beam_x, beam_y);
  int sides = 1 << own;
  constexpr double kNearDiagonal = 0.2;  // sin(11.5 degrees)
  if (std::min(std::abs(beam_x), std::abs(beam_y)) > kNearDiagonal * std::hypot(beam_x, beam_y)) {
    sides |= 1 << (own % 2 == 0 ? side(0, beam_y) : side(beam_x, 0));
  }
  for (int k = 0; k < kSides; ++k) {
    if ((sides & (1 << k)) && !(cell & (1 << k))) {
      cell |= static_cast<uint8_t>(1 << k);
      stamp(i, j, hit_m, k);
    }
  }
}

// side_index -1: the clearance (all sides); else that side's match field.
void ScanMap::stamp(int i, int j, Point2 hit_m, int side_index) {
  auto& distance = side_index < 0 ? distance_ : side_distance_[side_index];
  for (const auto& [di, dj] : stamp_) {
    const int a = i + di, b = j + dj;
    if (!inside(a, b)) continue;
    const Point2 c = centre(a, b);
    const double d_m = std::hypot(c.x_m - hit_m.x_m, c.y_m - hit_m.y_m);
    if (d_m >= s_.field_radius_m) continue;
    const uint8_t d = static_cast<uint8_t>(std::lround(d_m / unit_m_));
    if (d >= distance[idx(a, b)]) continue;
    distance[idx(a, b)] = d;
    if (side_index >= 0) {
      side_nearest_[side_index][idx(a, b)] = {static_cast<int16_t>(std::lround((hit_m.x_m - c.x_m) / kOffsetUnitM)),
                                              static_cast<int16_t>(std::lround((hit_m.y_m - c.y_m) / kOffsetUnitM))};
    }
  }
}

void ScanMap::markFree(Point2 centre_m, double radius_m) {
  const int reach = static_cast<int>(std::ceil(radius_m / s_.cell_m));
  const int i0 = col(centre_m.x_m), j0 = row(centre_m.y_m);
  for (int j = j0 - reach; j <= j0 + reach; ++j) {
    for (int i = i0 - reach; i <= i0 + reach; ++i) {
      if (!inside(i, j) || occupied_[idx(i, j)] || logodds_[idx(i, j)] < 0) continue;
      const Point2 c = centre(i, j);
      if ((c.x_m - centre_m.x_m) * (c.x_m - centre_m.x_m) + (c.y_m - centre_m.y_m) * (c.y_m - centre_m.y_m) > radius_m * radius_m) continue;
      logodds_[idx(i, j)] = -1;
      touch(i, j);
    }
  }
}

// Bresenham from (i0, j0) to the cell of end_m: every cell seen free.
void ScanMap::ray(int i0, int j0, Point2 end_m) {
  const int i1 = col(end_m.x_m), j1 = row(end_m.y_m);
  const int di = std::abs(i1 - i0), dj = -std::abs(j1 - j0);
  const int si = i0 < i1 ? 1 : -1, sj = j0 < j1 ? 1 : -1;
  int err = di + dj;
  int i = i0, j = j0;
  while (true) {
    if (!inside(i, j)) return;
    int8_t& l = logodds_[idx(i, j)];
    l = static_cast<int8_t>(std::max(-100, l - s_.free_logodds));
    touch(i, j);
    if (i == i1 && j == j1) return;
    const int e2 = 2 * err;
    if (e2 >= dj) {
      err += dj;
      i += si;
    }
    if (e2 <= di) {
      err += di;
      j += sj;
    }
  }
}

void ScanMap::insert(const component::LaserData& scan, double laser_yaw_rad, Point2 laser_m) {
  const int i0 = col(laser_m.x_m), j0 = row(laser_m.y_m);
  if (!inside(i0, j0)) return;
  const std::vector<Point2> looks = surfaceLooks(scan, laser_yaw_rad, s_.hit_max_m + 1e-9);
  Point2 prev_end;
  BeamDirections beam(scan, laser_yaw_rad);
  for (int k = 0; k < scan.numLaser; ++k, beam.next()) {
    const double r = scan.values_m[k];
    const bool hit = r > scan.minRange && (looks[k].x_m != 0 || looks[k].y_m != 0);
    const bool prev_hit = k > 0 && neighbours(scan, k - 1, k) && (looks[k - 1].x_m != 0 || looks[k - 1].y_m != 0);
    // No echo (a beam lost reads the laser's maximum): it says nothing of where the walls are, and
    // carved free, it runs through them (1 % of beams under realistic noise drew rays through
    // every wall, and rooms not seen yet as seen).
    if (!(r > scan.minRange) || r >= scan.maxRange) continue;
    const double c = beam.cos(), s = beam.sin();
    // Free up to a little short of a hit: a beam that ends on a wall runs through the cells of
    // the wall's face beside its own at a glance, and would carve that face free; the face then
    // never turns occupied, and a scan of it fits the same wall's other face (0.2 m off) better.
    const double free_m = std::min(hit ? r - s_.hit_margin_m : r, s_.free_max_m);
    if (free_m > 0) ray(i0, j0, {laser_m.x_m + free_m * c, laser_m.y_m + free_m * s});
    if (!hit) continue;
    const Point2 end{laser_m.x_m + r * c, laser_m.y_m + r * s};
    const int i = col(end.x_m), j = row(end.y_m);
    if (!inside(i, j)) continue;
    // A hit outweighs every beam that passed through the cell before: the laser has no noise to
    // speak of, and a face seen late was carved free by beams grazing it (at a few degrees even
    // hit_margin_m short of their own hit is within millimetres of it): h2's box face along a
    // 0.43 m corridor stayed free, and the plans led the robot into it for 700 bumps.
    int8_t& l = logodds_[idx(i, j)];
    l = static_cast<int8_t>(std::min(100, std::max<int>(l, 0) + s_.hit_logodds));
    touch(i, j);
    if (l >= s_.occupied_logodds) occupy(i, j, end, looks[k].x_m, looks[k].y_m);
    if (k > 0 && prev_hit) joinHits(prev_end, end, looks[k]);
    prev_end = end;
  }
}

// Two neighbouring beams' hits on the same surface (surfaceLooks' test), seen at a glance, lie
// up to 0.3 m apart along it: the cells between them are that surface too. Left free, the face
// of a box seen only along a corridor had gaps that the plans took for floor (h2: 0.12 m from
// the box, the robot pressed on it).
void ScanMap::joinHits(Point2 a_m, Point2 b_m, Point2 look) {
  const double gap_m = std::hypot(b_m.x_m - a_m.x_m, b_m.y_m - a_m.y_m);
  if (gap_m <= s_.cell_m || gap_m > s_.join_max_m) return;
  const int steps = static_cast<int>(std::ceil(2 * gap_m / s_.cell_m));
  for (int n = 1; n < steps; ++n) {
    const double f = static_cast<double>(n) / steps;
    const Point2 p{a_m.x_m + f * (b_m.x_m - a_m.x_m), a_m.y_m + f * (b_m.y_m - a_m.y_m)};
    const int i = col(p.x_m), j = row(p.y_m);
    if (!inside(i, j)) continue;
    int8_t& l = logodds_[idx(i, j)];
    l = static_cast<int8_t>(std::max<int>(l, s_.occupied_logodds));
    touch(i, j);
    occupy(i, j, p, look.x_m, look.y_m);
  }
}

double ScanMap::field(double x_m, double y_m, int side_index) const {
  const int i = col(x_m), j = row(y_m);
  if (!inside(i, j) || side_distance_[side_index][idx(i, j)] == 255) return 0.0;
  const Point2 c = centre(i, j);
  const auto& o = side_nearest_[side_index][idx(i, j)];
  const double dx = c.x_m + o[0] * kOffsetUnitM - x_m, dy = c.y_m + o[1] * kOffsetUnitM - y_m;
  const double d_m = std::sqrt(dx * dx + dy * dy);  // not std::hypot: 10x slower, and this is the hot loop
  return std::max(0.0, 1.0 - d_m / s_.field_radius_m);
}

double ScanMap::score(const std::vector<ScanPoint>& points, Point2 laser_m) const {
  if (points.empty()) return 0.0;
  double sum = 0;
  for (const ScanPoint& p : points) sum += field(laser_m.x_m + p.x_m, laser_m.y_m + p.y_m, p.side);
  return sum / points.size();
}

std::vector<ScanPoint> ScanMap::seen(const std::vector<ScanPoint>& points, Point2 laser_m) const {
  std::vector<ScanPoint> out;
  out.reserve(points.size());
  for (const ScanPoint& p : points) {
    const int i = col(laser_m.x_m + p.x_m), j = row(laser_m.y_m + p.y_m);
    if (inside(i, j) && side_distance_[p.side][idx(i, j)] != 255) out.push_back(p);
  }
  return out;
}

ScanMatch ScanMap::match(const std::vector<ScanPoint>& points, Point2 predicted_m, double search_half_m,
                         bool bounded) const {
  const auto inWindow = [&](Point2 p) {
    return !bounded || (std::abs(p.x_m - predicted_m.x_m) <= search_half_m + 1e-9 &&
                        std::abs(p.y_m - predicted_m.y_m) <= search_half_m + 1e-9);
  };
  ScanMatch best{predicted_m, score(points, predicted_m), static_cast<int>(points.size())};
  // The window, on a grid of two cells: the field is 2 x field_radius_m wide, so a peak is never
  // stepped over.
  const double step_m = 2 * s_.cell_m;
  const int k = static_cast<int>(std::ceil(search_half_m / step_m));
  for (int b = -k; b <= k; ++b) {
    for (int a = -k; a <= k; ++a) {
      const Point2 p{predicted_m.x_m + a * step_m, predicted_m.y_m + b * step_m};
      if (!inWindow(p)) continue;
      const double sc = score(points, p);
      if (sc > best.score) best = {p, sc, best.points};
    }
  }
  // Hill climb over the 8 neighbours, halving the step down to about 3 mm.
  for (double h = std::min(s_.cell_m, std::max(search_half_m / 4, s_.cell_m / 2)); h >= 0.0025; h /= 2) {
    for (int moves = 0; moves < 20; ++moves) {
      ScanMatch step = best;
      for (int b = -1; b <= 1; ++b) {
        for (int a = -1; a <= 1; ++a) {
          if (a == 0 && b == 0) continue;
          const Point2 p{best.laser_m.x_m + a * h, best.laser_m.y_m + b * h};
          if (!inWindow(p)) continue;
          const double sc = score(points, p);
          if (sc > step.score) step = {p, sc, best.points};
        }
      }
      if (step.score <= best.score) break;
      best = step;
    }
  }
  const double d = ScanMatch::kSharpnessStepM;
  const Point2 p = best.laser_m;
  best.sharpness_x = best.score - std::max(score(points, {p.x_m - d, p.y_m}), score(points, {p.x_m + d, p.y_m}));
  best.sharpness_y = best.score - std::max(score(points, {p.x_m, p.y_m - d}), score(points, {p.x_m, p.y_m + d}));
  return best;
}

ScanMatch ScanMap::matchSeen(const std::vector<ScanPoint>& points, Point2 predicted_m, double search_half_m,
                             bool bounded) const {
  const std::vector<ScanPoint> first = seen(points, predicted_m);
  if (first.empty()) return {predicted_m, 0.0, 0};
  const ScanMatch m = match(first, predicted_m, search_half_m, bounded);
  const std::vector<ScanPoint> again = seen(points, m.laser_m);
  if (again.size() <= first.size()) return m;
  ScanMatch refined = match(again, m.laser_m, 2 * s_.cell_m);
  if (bounded && (std::abs(refined.laser_m.x_m - predicted_m.x_m) > search_half_m ||
                  std::abs(refined.laser_m.y_m - predicted_m.y_m) > search_half_m)) {
    return m;
  }
  refined.points = static_cast<int>(again.size());
  return refined;
}

}  // namespace aula::vacuum::mapping
