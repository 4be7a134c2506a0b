#include <aula/autopark/car_geometry.hpp>

#include <aula/geometry/oriented_box.hpp>

#include <cmath>

namespace aula::autopark {

Pose2D centreToRearAxle(const Pose2D& centre, const CarGeometry& car) {
  const double d = car.rear_axle_from_centre_m;
  return {centre.x_m - d * std::cos(centre.yaw_rad), centre.y_m - d * std::sin(centre.yaw_rad),
          centre.yaw_rad};
}

Pose2D rearAxleToCentre(const Pose2D& rear_axle, const CarGeometry& car) {
  const double d = car.rear_axle_from_centre_m;
  return {rear_axle.x_m + d * std::cos(rear_axle.yaw_rad),
          rear_axle.y_m + d * std::sin(rear_axle.yaw_rad), rear_axle.yaw_rad};
}

std::array<std::array<double, 2>, 4> footprintCorners(const Pose2D& centre, const CarGeometry& car,
                                                      double inflation_m) {
  const auto box = geometry::orientedBoxCorners(centre.x_m, centre.y_m, centre.yaw_rad, car.length_m + 2 * inflation_m,
                                                car.width_m + 2 * inflation_m);
  std::array<std::array<double, 2>, 4> out{};
  for (size_t i = 0; i < 4; ++i) out[i] = {box[i].x(), box[i].y()};
  return out;
}

}  // namespace aula::autopark
