#include "aula/teletaxi/path_pilot.hpp"

#include <aula/geometry/angles.hpp>

#include <algorithm>
#include <cmath>

namespace aula::teletaxi {
using geometry::wrapAngle;

void PathPilot::setPath(std::vector<Point2> path) {
  path_ = std::move(path);
  arc_m_.assign(path_.size(), 0.0);
  for (size_t i = 1; i < path_.size(); ++i) {
    arc_m_[i] = arc_m_[i - 1] + std::hypot(path_[i].x - path_[i - 1].x, path_[i].y - path_[i - 1].y);
  }
  progress_ = 0;
}

PilotCommand PathPilot::command(double x, double y, double yaw, double speed_mps) {
  PilotCommand cmd;
  if (path_.empty()) {
    cmd.arrived = true;
    return cmd;
  }
  const Point2 goal = path_.back();
  const double to_goal = std::hypot(goal.x - x, goal.y - y);
  if (to_goal <= params_.arrival_radius_m) {
    cmd.arrived = true;
    cmd.target = goal;
    return cmd;
  }
  // Closest path point, searched forward from the last one (a window, so loops never confuse it).
  double best = std::hypot(path_[progress_].x - x, path_[progress_].y - y);
  const size_t window_end = std::min(path_.size(), progress_ + 60);
  for (size_t i = progress_ + 1; i < window_end; ++i) {
    const double d = std::hypot(path_[i].x - x, path_[i].y - y);
    if (d < best) {
      best = d;
      progress_ = i;
    }
  }
  const double lookahead = params_.min_lookahead_m + params_.lookahead_gain_s * std::max(0.0, speed_mps);
  size_t t = progress_;
  while (t + 1 < path_.size() && arc_m_[t] - arc_m_[progress_] < lookahead) ++t;
  cmd.target = path_[t];

  const double desired = std::atan2(cmd.target.y - y, cmd.target.x - x);
  cmd.heading_error_rad = wrapAngle(desired - yaw);
  cmd.w_radps = std::clamp(params_.heading_gain * cmd.heading_error_rad, -params_.max_w_radps, params_.max_w_radps);

  // Speed: aligned with the path, slower for bends ahead and for the stop at the goal.
  const double align = std::max(0.0, std::cos(cmd.heading_error_rad));
  double v = params_.max_v_mps * align * align * align * align;
  if (std::abs(cmd.heading_error_rad) > 0.8) v = 0.0;  // turn in place first
  // Largest heading change of the path within the preview distance.
  const double base_dir = std::atan2(cmd.target.y - path_[progress_].y, cmd.target.x - path_[progress_].x);
  for (size_t i = t; i + 1 < path_.size() && arc_m_[i] - arc_m_[progress_] < params_.curve_preview_m; ++i) {
    const double dir = std::atan2(path_[i + 1].y - path_[i].y, path_[i + 1].x - path_[i].x);
    const double change = std::abs(wrapAngle(dir - base_dir));
    // A bend farther away allows more speed now (time to brake).
    const double distance = arc_m_[i] - arc_m_[progress_];
    const double bend_speed = params_.curve_speed_mps * (M_PI / 2) / std::max(change, 0.1);
    const double allowed = std::sqrt(bend_speed * bend_speed + 2 * params_.braking_mps2 * std::max(0.0, distance - lookahead));
    v = std::min(v, allowed);
  }
  const double remaining = arc_m_.back() - arc_m_[progress_];
  v = std::min(v, std::sqrt(2 * params_.braking_mps2 * std::max(0.0, std::min(remaining, to_goal) - params_.arrival_radius_m * 0.5)));
  cmd.v_mps = std::clamp(v, 0.0, params_.max_v_mps);
  return cmd;
}

}  // namespace aula::teletaxi
