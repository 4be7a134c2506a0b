#pragma once
// A pose in the plane: position and heading (counter-clockwise from world +x).

namespace aula::geometry {

struct Pose2D {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_rad = 0.0;
};

}  // namespace aula::geometry
