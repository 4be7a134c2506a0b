#pragma once
// The reference solution's pilot: follows a path (world metres) with a look-ahead target on
// it, speed from the heading error, slower before curves and when close to the goal, and a
// full stop at the goal. Pure: no time, no IO (world frame, yaw CCW from +x).

#include <cstddef>
#include <vector>

namespace aula::teletaxi {

struct Point2 {
  double x = 0, y = 0;
};

struct PilotParams {
  double max_v_mps = 20.0;
  double max_w_radps = 2.0;
  double min_lookahead_m = 5.0;      // look-ahead grows with speed: min + gain * v
  double lookahead_gain_s = 0.4;
  double heading_gain = 2.5;         // w = gain * heading error
  double curve_preview_m = 35.0;     // how far ahead curves slow the taxi
  double curve_speed_mps = 4.0;      // speed for a 90-degree bend
  double braking_mps2 = 3.0;         // planned deceleration towards the goal
  double arrival_radius_m = 1.0;     // stop within this distance of the goal
};

struct PilotCommand {
  double v_mps = 0, w_radps = 0;
  bool arrived = false;
  Point2 target;                     // the look-ahead point (for the GUI)
  double heading_error_rad = 0;
};

class PathPilot {
 public:
  explicit PathPilot(PilotParams params = {}) : params_(params) {}
  void setPath(std::vector<Point2> path);  // from the robot to the goal
  const std::vector<Point2>& path() const { return path_; }
  // `speed_mps` is the robot's current speed (for the look-ahead distance).
  PilotCommand command(double x_m, double y_m, double yaw_rad, double speed_mps);

 private:
  PilotParams params_;
  std::vector<Point2> path_;
  std::vector<double> arc_m_;   // cumulative length along the path
  std::size_t progress_ = 0;         // index of the closest path point so far (never goes back)
};

}  // namespace aula::teletaxi
