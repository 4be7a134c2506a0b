#include <aula/autopark/path_tracker.hpp>
#include <aula/geometry/angles.hpp>

#include <algorithm>
#include <cmath>

namespace aula::autopark {

PathTracker::PathTracker(const PlannedPath& path, CarGeometry car, Options options)
    : car_(car), opt_(options) {
  if (!path.solved || path.poses.size() < 2) {
    done_ = true;
    return;
  }
  const size_t n = path.poses.size();
  rear_.reserve(n);
  for (const Pose2D& c : path.poses) rear_.push_back(centreToRearAxle(c, car_));
  s_.assign(n, 0.0);
  for (size_t i = 1; i < n; ++i) {
    s_[i] = s_[i - 1] + std::hypot(rear_[i].x_m - rear_[i - 1].x_m, rear_[i].y_m - rear_[i - 1].y_m);
  }
  kappa_ = path.curvature_per_m;
  kappa_.resize(n, 0.0);
  std::vector<int> dir = path.direction;
  dir.resize(n, 1);
  // Segment k: poses [begin, end], all motions arriving at begin+1..end share one direction.
  int begin = 0;
  for (int i = 1; i < static_cast<int>(n); ++i) {
    const bool last = i + 1 == static_cast<int>(n);
    if (last || dir[i + 1] != dir[i]) {
      segments_.push_back({begin, i, dir[i]});
      begin = i;
    }
  }
  index_ = 0;
}

PathTracker::Command PathTracker::update(const Pose2D& current_centre) {
  Command cmd;
  if (done_) {
    cmd.done = true;
    return cmd;
  }
  const Pose2D p = centreToRearAxle(current_centre, car_);
  const Segment& seg = segments_[segment_];
  index_ = std::max(index_, seg.begin);
  // Nearest pose ahead (monotone progress within the segment).
  int best = index_;
  double best_d2 = 1e300;
  const int last = std::min(seg.end, index_ + opt_.search_window);
  for (int i = index_; i <= last; ++i) {
    const double d2 = std::pow(p.x_m - rear_[i].x_m, 2) + std::pow(p.y_m - rear_[i].y_m, 2);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = i;
    }
  }
  index_ = best;
  const Pose2D& r = rear_[index_];
  const double c = std::cos(r.yaw_rad), s = std::sin(r.yaw_rad);
  const double dx = p.x_m - r.x_m, dy = p.y_m - r.y_m;
  const double along = seg.dir * (c * dx + s * dy);  // progress past pose index_, metres
  const double remaining = (s_[seg.end] - s_[index_]) - along;
  if (remaining <= opt_.segment_end_tolerance_m) {
    // Segment finished: stop here (a cusp, or the goal) and move on next call.
    ++segment_;
    if (segment_ >= static_cast<int>(segments_.size())) {
      done_ = true;
      cmd.done = true;
    }
    return cmd;  // v = w = 0 for one period
  }
  const double vmax = seg.dir > 0 ? opt_.forward_speed_mps : opt_.reverse_speed_mps;
  const double vmag = std::clamp(std::sqrt(2.0 * opt_.decel_mps2 * remaining), opt_.min_speed_mps, vmax);
  const double v = seg.dir * vmag;
  const double e = -s * dx + c * dy;  // lateral error, + to the left of the path
  const double eth = geometry::wrapAngle(p.yaw_rad - r.yaw_rad);
  const double kref = kappa_[std::min(index_ + 1, seg.end)];
  const double sinc = std::abs(eth) < 1e-6 ? 1.0 : std::sin(eth) / eth;
  const double denom = std::max(0.2, 1.0 - kref * e);
  double w = v * kref * std::cos(eth) / denom - opt_.k_heading * vmag * eth - opt_.k_lateral * v * e * sinc;
  const double wmax = vmag / car_.min_turn_radius_m;
  w = std::clamp(w, -wmax, wmax);
  last_lateral_error_m_ = e;
  cmd.v_mps = v;
  cmd.w_radps = w;
  return cmd;
}

}  // namespace aula::autopark
