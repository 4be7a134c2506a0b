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
// With no curb in sight, the cars' far side lies at least this far below their side line (the
// width of RoboticsAcademy's parked cars), however little of their end faces has been seen.
constexpr double kParkedCarWidthM = 2.2;
}  // namespace

SlotDetector::SlotDetector(double min_length_m, double bin_m, double from_x_m, double to_x_m)
    : min_length_m_(min_length_m), bin_m_(bin_m), from_x_m_(from_x_m),
      nearest_y_(static_cast<size_t>(std::ceil((to_x_m - from_x_m) / bin_m)), std::numeric_limits<double>::quiet_NaN()),
      lowest_y_(nearest_y_.size(), std::numeric_limits<double>::quiet_NaN()),
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
    std::vector<double> floor_y;
    while (e < n && kind(e) != Occupied) {
      if (kind(e) == Free) {
        any_free = true;
        unseen = 0;
        if (!std::isnan(nearest_y_[e])) floor_y.push_back(nearest_y_[e]);  // the curb, where a beam sees it
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
      if (!floor_y.empty()) {
        std::nth_element(floor_y.begin(), floor_y.begin() + floor_y.size() / 2, floor_y.end());
        s.curb_y_m = floor_y[floor_y.size() / 2];
      } else {
        // No curb in sight: the deepest echo on the end faces of the cars either side.
        s.curb_y_m = std::numeric_limits<double>::infinity();
        for (int f = std::max(0, b - kEndFaceBins); f <= std::min(n - 1, e + kEndFaceBins); ++f) {
          if (!std::isnan(lowest_y_[f]) && (f <= b || f >= e)) s.curb_y_m = std::min(s.curb_y_m, lowest_y_[f]);
        }
        s.curb_y_m = std::min(s.curb_y_m, edge_y - kParkedCarWidthM);
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
