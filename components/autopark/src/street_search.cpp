#include "aula/autopark/street_search.hpp"

#include <aula/autopark/car_geometry.hpp>
#include <aula/autopark/street_end.hpp>
#include <aula/geometry/angles.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aula::autopark {
double rangeAhead(const component::LaserData& scan, double half_width_rad) {
  double m = scan.maxRange;
  for (int i = 0; i < scan.numLaser && i < static_cast<int>(scan.values_m.size()); ++i) {
    if (std::abs(scan.angle(i)) <= half_width_rad) m = std::min<double>(m, scan.values_m[i]);
  }
  return m;
}

double clearanceAhead(const component::LaserData& scan, double half_width_m) {
  double nearest = scan.maxRange;
  for (int i = 0; i < scan.numLaser && i < static_cast<int>(scan.values_m.size()); ++i) {
    const double r = scan.values_m[i], a = scan.angle(i);
    if (!(r > scan.minRange) || r >= scan.maxRange - 0.05) continue;
    const double ahead = r * std::cos(a), aside = r * std::sin(a);
    if (ahead > 0 && std::abs(aside) <= half_width_m) nearest = std::min(nearest, ahead);
  }
  return nearest;
}

bool laneBlockedAhead(double x_m, double y_m, double yaw_rad, const LaserMount& mount, const component::LaserData& scan,
                      int direction, double lane_y_m, double half_band_m, double within_m) {
  bool blocked = false;
  forEachEcho(x_m, y_m, yaw_rad, mount, scan, [&](double ex_m, double ey_m) {
    const double ahead_m = direction * (ex_m - x_m);
    if (ahead_m > 0 && ahead_m < within_m && std::abs(ey_m - lane_y_m) < half_band_m) blocked = true;
  });
  return blocked;
}

bool TurnRound::needed(double yaw_rad) { return std::abs(geometry::wrapAngle(yaw_rad)) > M_PI / 2; }

bool TurnRound::step(const AutoparkApi& api, double yaw_rad, double& v_mps, double& w_radps) {
  v_mps = w_radps = 0;
  const double heading_error = geometry::wrapAngle(-yaw_rad);  // to turn, towards 0
  if (std::abs(heading_error) < (api.min_turn_radius_m > 0 ? 0.3 : 0.05)) return true;
  const double turn_sign = heading_error > 0 ? 1.0 : -1.0;  // the shorter way round
  if (api.min_turn_radius_m <= 0) {
    w_radps = turn_sign * kTurnRadps;
    return false;
  }
  const double half_width = api.car_width_m / 2 + 0.2;
  if (forward_ && clearanceAhead(api.laser1.getLaserData(), half_width) < kClearanceM) forward_ = false;
  if (!forward_ && clearanceAhead(api.laser2.getLaserData(), half_width) < kClearanceM) forward_ = true;
  v_mps = forward_ ? kTurnMps : -kTurnMps;
  w_radps = turn_sign * kTurnMps / api.min_turn_radius_m;  // forward: steer to the turn; back: the other way
  return false;
}

StreetSearch::StreetSearch(const AutoparkApi& api, Settings settings)
    : settings_(settings), detector_(settings.min_slot_length_m), car_width_m_(api.car_width_m),
      lane_y_m_(std::numeric_limits<double>::quiet_NaN()) {}

void StreetSearch::addScans(const AutoparkApi& api, double x_m, double y_m, double yaw_rad) {
  detector_.addScan(x_m, y_m, yaw_rad, api.mount1, api.laser1.getLaserData());
  detector_.addScan(x_m, y_m, yaw_rad, api.mount2, api.laser2.getLaserData());
  detector_.addScan(x_m, y_m, yaw_rad, api.mount3, api.laser3.getLaserData());
}

StreetSearch::Step StreetSearch::search(const AutoparkApi& api, double x_m, double y_m, double yaw_rad) {
  addScans(api, x_m, y_m, yaw_rad);
  Step step;
  step.slot = detector_.slot(x_m);
  if (step.slot) return step;
  // At most one turn back a period: the way back is judged from the next scan.
  const bool forward = direction_ > 0;
  const double lane_y = std::isfinite(lane_y_m_) ? lane_y_m_ : y_m;  // the lane, or the present line
  if (laneBlockedAhead(x_m, y_m, yaw_rad, forward ? api.mount1 : api.mount2,
                       forward ? api.laser1.getLaserData() : api.laser2.getLaserData(), direction_, lane_y,
                       api.car_width_m / 2 + kLaneBandMarginM, api.car_length_m / 2 + settings_.street_end_m)) {
    direction_ = -direction_;
    ++reversals_;
  }
  step.v_mps = direction_ > 0 ? settings_.cruise_mps : -settings_.reverse_mps;
  if (!lane_held_) {
    if (auto edge = detector_.edgeY()) lane_y_m_ = laneYFor(*edge);
  }
  if (!std::isfinite(lane_y_m_)) lane_y_m_ = y_m;  // nothing known yet: keep to the present line
  step.w_radps = keepLane(step.v_mps, y_m, yaw_rad);
  return step;
}

double StreetSearch::keepLane(double v_mps, double y_m, double yaw_rad) const {
  const double lane_y = std::isfinite(lane_y_m_) ? lane_y_m_ : y_m;
  // Pure pursuit of a point 5 m down the lane line, in the direction of travel.
  const double lookahead_m = 5.0;
  const double heading = (v_mps >= 0 ? 1 : -1) * std::atan2(lane_y - y_m, lookahead_m);
  const double w = 1.5 * geometry::wrapAngle(heading - yaw_rad) * std::abs(v_mps);
  const double limit = std::abs(v_mps) / settings_.turn_radius_m;
  return std::clamp(w, -limit, limit);
}

}  // namespace aula::autopark
