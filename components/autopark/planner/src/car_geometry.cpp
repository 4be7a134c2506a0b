#include <aula/autopark/car_geometry.hpp>

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

geometry::OrientedBox footprint(const Pose2D& centre, const CarGeometry& car, double inflation_m) {
  return geometry::OrientedBox{centre, car.length_m, car.width_m}.inflated(inflation_m);
}

}  // namespace aula::autopark
