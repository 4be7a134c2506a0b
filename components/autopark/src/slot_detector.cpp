#include "aula/autopark/slot_detector.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace aula::autopark {
namespace {
// A bin is free when what is nearest to the lane there lies this far below the cars' side.
constexpr double kFreeDepthM = 1.0;
// Unseen stretch tolerated inside a free run (sparse beams far away), metres.
constexpr double kMaxUnseenM = 0.4;
// A slot's ends must be parked cars: no higher than the cars' side plus this. A wall across the
// street's end rises to the lane, so a gap between the last car and the wall is not a slot.
constexpr double kCarLevelToleranceM = 0.3;
// Levels of the parking side are told apart in buckets of this height.
constexpr double kLevelM = 0.1;
// Bins either side of a slot whose echoes may show the end faces of the cars bounding it.
constexpr int kEndFaceBins = 3;
// Deep echoes inside a slot over at least this much of it are a curb the lasers see.
constexpr double kCurbSeenM = 0.5;
// A reading this near max range (or beyond it: inf) is a beam with no echo.
constexpr double kNoEchoM = 0.05;
// A beam with no echo bounds a face's bottom only where it would have met the face this far
// within its range: nearer max range, noise and the echo's own error could make a face's echo a miss.
constexpr double kBottomInRangeM = 0.5;
// An end face's bottom is known once its deepest echo and the highest beam with no echo that
// passed below it are this close: far away, beams a degree apart leave 0.2 m and more of a face
// between them, and a line placed at the deepest echo then would be that much too high.
constexpr double kBottomResolutionM = 0.1;

// Calls passed(x_m, y_m) where a beam of `scan` with no echo passed below an echo of its
// neighbour at that echo's x (an upright face, as a parked car's end, ends above that point),
// well within the laser's range. Where the next beam down was out of range or hit something in
// front (a face seen only in part), nothing is said: where the face ends is not known.
template <class Passed>
void forEachPassBelowAFace(double car_x_m, double car_y_m, double car_yaw_rad, const LaserMount& mount,
                           const component::LaserData& scan, Passed passed) {
  const double c = std::cos(car_yaw_rad), s = std::sin(car_yaw_rad);
  const double lx = car_x_m + c * mount.x_m - s * mount.y_m, ly = car_y_m + s * mount.x_m + c * mount.y_m;
  const int n = std::min(scan.numLaser, static_cast<int>(scan.values_m.size()));
  auto miss = [&](int i) { return i >= 0 && i < n && !(scan.values_m[i] < scan.maxRange - kNoEchoM); };
  for (int i = 0; i < n; ++i) {
    const double r = scan.values_m[i];
    if (!(r > scan.minRange) || miss(i)) continue;
    const double a = car_yaw_rad + mount.yaw_rad + scan.angle(i);
    const double ex = lx + r * std::cos(a), ey = ly + r * std::sin(a);
    for (const int j : {i - 1, i + 1}) {
      const double aj = car_yaw_rad + mount.yaw_rad + scan.angle(j);
      if (!miss(j) || std::abs(std::cos(aj)) < 1e-6) continue;
      const double t = (ex - lx) / std::cos(aj);  // along beam j to the echo's x
      const double y_m = ly + t * std::sin(aj);
      if (t > 0 && t < scan.maxRange - kBottomInRangeM && y_m < ey) passed(ex, y_m);
    }
  }
}
}  // namespace

SlotDetector::SlotDetector(double min_length_m, double bin_m, double from_x_m, double to_x_m)
    : min_length_m_(min_length_m), bin_m_(bin_m), from_x_m_(from_x_m),
      nearest_y_(static_cast<size_t>(std::ceil((to_x_m - from_x_m) / bin_m)), std::numeric_limits<double>::quiet_NaN()),
      lowest_y_(nearest_y_.size(), std::numeric_limits<double>::quiet_NaN()),
      passed_below_y_(nearest_y_.size(), std::numeric_limits<double>::quiet_NaN()),
      free_y_(nearest_y_.size(), std::numeric_limits<double>::quiet_NaN()) {}

int SlotDetector::binOf(double x_m) const { return static_cast<int>(std::floor((x_m - from_x_m_) / bin_m_)); }

void SlotDetector::addPoint(double x_m, double y_m) {
  const int b = binOf(x_m);
  if (b < 0 || b >= static_cast<int>(nearest_y_.size())) return;
  double& n = nearest_y_[b];
  if (std::isnan(n) || y_m > n) n = y_m;
  double& l = lowest_y_[b];
  if (std::isnan(l) || y_m < l) l = y_m;
}

void SlotDetector::addPassBelowAFace(double x_m, double y_m) {
  const int b = binOf(x_m);
  if (b < 0 || b >= static_cast<int>(passed_below_y_.size())) return;
  double& p = passed_below_y_[b];
  if (std::isnan(p) || y_m > p) p = y_m;
}

void SlotDetector::addFreePoint(double x_m, double y_m) {
  const int b = binOf(x_m);
  if (b < 0 || b >= static_cast<int>(free_y_.size())) return;
  double& f = free_y_[b];
  if (std::isnan(f) || y_m < f) f = y_m;
}

void SlotDetector::addScan(double car_x_m, double car_y_m, double car_yaw_rad, const LaserMount& mount,
                           const component::LaserData& scan) {
  forEachEcho(car_x_m, car_y_m, car_yaw_rad, mount, scan, [&](double x_m, double y_m) {
    // The parking side only: right of the car's body, not the far curb or the car's own lane.
    if (y_m < car_y_m - 1.2) addPoint(x_m, y_m);
  });
  // Half a bin apart along each beam, so every bin it crosses gets a point.
  forEachMissPoint(car_x_m, car_y_m, car_yaw_rad, mount, scan, bin_m_ / 2, [&](double x_m, double y_m) {
    if (y_m < car_y_m - 1.2) addFreePoint(x_m, y_m);
  });
  forEachPassBelowAFace(car_x_m, car_y_m, car_yaw_rad, mount, scan, [&](double x_m, double y_m) {
    if (y_m < car_y_m - 1.2) addPassBelowAFace(x_m, y_m);
  });
}

std::optional<double> SlotDetector::edgeY() const {
  // The cars' side is the most common level among the bins standing well above the lowest one
  // (the curb). A wall across the street's end or a pole shows in a few bins only, so it cannot
  // pull the edge towards the lane the way the single highest point would.
  double floor_y = std::numeric_limits<double>::infinity();
  for (double y : nearest_y_) {
    if (!std::isnan(y)) floor_y = std::min(floor_y, y);
  }
  for (double y : free_y_) {  // beams with no echo reached this deep: the parking side's floor
    if (!std::isnan(y)) floor_y = std::min(floor_y, y);
  }
  if (!std::isfinite(floor_y)) return std::nullopt;
  std::map<long, std::pair<int, double>> levels;  // 0.1 m bucket -> (bins, highest y)
  for (double y : nearest_y_) {
    if (std::isnan(y) || y < floor_y + kFreeDepthM) continue;
    auto& level = levels[std::lround(std::floor(y / kLevelM))];
    ++level.first;
    level.second = level.first == 1 ? y : std::max(level.second, y);
  }
  // Until both the curb and the cars have been seen, one level alone could be either.
  if (levels.empty()) return std::nullopt;
  const auto mode = std::max_element(levels.begin(), levels.end(),
                                     [](const auto& a, const auto& b) { return a.second.first < b.second.first; });
  return mode->second.second;
}

bool SlotDetector::placeLine(Slot& s, int b, int e, double edge_y) const {
  // The curb, where beams see it: the median of the deep echoes inside the slot, away from its
  // ends (an end face's echoes may fall in the slot's first bins), over enough of it to be a curb.
  std::vector<double> curb_y;
  for (int f = b + 1 + kEndFaceBins; f < e - kEndFaceBins; ++f) {
    if (!std::isnan(nearest_y_[f]) && nearest_y_[f] < edge_y - kFreeDepthM) curb_y.push_back(nearest_y_[f]);
  }
  if (curb_y.size() * bin_m_ >= kCurbSeenM) {
    std::nth_element(curb_y.begin(), curb_y.begin() + curb_y.size() / 2, curb_y.end());
    s.curb_y_m = curb_y[curb_y.size() / 2];
    s.curb_seen = true;
    return true;
  }
  // No curb in sight: the cars' far side, the deeper of the two end faces' bottoms known.
  std::optional<double> line;
  for (const int face : {b, e}) {
    const std::optional<double> bottom = faceBottom(face);
    if (bottom && *bottom < edge_y - kFreeDepthM && (!line || *bottom < *line)) line = bottom;
  }
  if (!line) return false;  // none known yet: where to park in the slot is not known
  s.curb_y_m = *line;
  s.curb_seen = false;
  return true;
}

std::optional<double> SlotDetector::faceBottom(int face) const {
  // The face's deepest echo, once a beam with no echo passed close below it: the face ends between.
  double deepest_echo_y = std::numeric_limits<double>::infinity();
  double passed_y = -std::numeric_limits<double>::infinity();
  const int n = static_cast<int>(lowest_y_.size());
  for (int f = std::max(0, face - kEndFaceBins); f <= std::min(n - 1, face + kEndFaceBins); ++f) {
    if (!std::isnan(lowest_y_[f])) deepest_echo_y = std::min(deepest_echo_y, lowest_y_[f]);
    if (!std::isnan(passed_below_y_[f])) passed_y = std::max(passed_y, passed_below_y_[f]);
  }
  if (std::isfinite(deepest_echo_y) && deepest_echo_y - passed_y < kBottomResolutionM) return deepest_echo_y;
  return std::nullopt;
}

std::optional<Slot> SlotDetector::slot(double near_x_m) const {
  const std::optional<double> edge = edgeY();
  if (!edge) return std::nullopt;
  const double edge_y = *edge;
  const int n = static_cast<int>(nearest_y_.size());
  enum Kind { Unseen, Free, Occupied };
  auto kind = [&](int b) {
    const double y = nearest_y_[b];
    if (std::isnan(y)) return !std::isnan(free_y_[b]) && free_y_[b] < edge_y - kFreeDepthM ? Free : Unseen;
    return y < edge_y - kFreeDepthM ? Free : Occupied;
  };
  std::optional<Slot> best;
  double best_distance = std::numeric_limits<double>::infinity();
  int b = 0;
  while (b < n) {
    if (kind(b) != Occupied) {
      ++b;
      continue;
    }
    // b is occupied: look for a free run right after it, closed by another occupied bin.
    int e = b + 1, unseen = 0;
    bool any_free = false;
    while (e < n && kind(e) != Occupied) {
      if (kind(e) == Free) {
        any_free = true;
        unseen = 0;
      } else if (++unseen * bin_m_ > kMaxUnseenM) {
        break;  // a long unseen stretch: the slot's bounds are unknown
      }
      ++e;
    }
    const bool cars_at_both_ends = e < n && nearest_y_[b] <= edge_y + kCarLevelToleranceM &&
                                   nearest_y_[e] <= edge_y + kCarLevelToleranceM;
    if (e < n && kind(e) == Occupied && any_free && cars_at_both_ends) {
      Slot s;
      s.rear_x_m = from_x_m_ + (b + 1) * bin_m_;
      s.front_x_m = from_x_m_ + e * bin_m_;
      if (!placeLine(s, b, e, edge_y)) {  // where to park in it is not known yet
        b = std::max(e, b + 1);
        continue;
      }
      s.edge_y_m = edge_y;
      const double distance = std::abs(s.centreXM() - near_x_m);
      if (s.lengthM() >= min_length_m_ && distance < best_distance) {
        best = s;
        best_distance = distance;
      }
    }
    b = std::max(e, b + 1);
  }
  return best;
}

}  // namespace aula::autopark
