#pragma once
// The corners of a box lying in the plane: length_m along its heading, width_m across, centred at
// (x_m, y_m) and turned by yaw_rad about its own centre. One definition for every car footprint
// (the parking referee's distances, the parking planner's collision checks).

#include <Eigen/Core>

#include <array>
#include <cmath>

namespace aula::geometry {

// Counter-clockwise, starting at the rear-right corner.
inline std::array<Eigen::Vector2d, 4> orientedBoxCorners(double x_m, double y_m, double yaw_rad, double length_m,
                                                         double width_m) {
  const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
  const double hl = length_m / 2, hw = width_m / 2;
  auto at = [&](double lx, double ly) { return Eigen::Vector2d(x_m + c * lx - s * ly, y_m + s * lx + c * ly); };
  return {at(-hl, -hw), at(hl, -hw), at(hl, hw), at(-hl, hw)};
}

}  // namespace aula::geometry
