#pragma once
// Car geometry and the centre <-> rear-axle pose conversions used by the parking planner.

#include <aula/geometry/oriented_box.hpp>
#include <aula/geometry/pose2d.hpp>

namespace aula::autopark {

using geometry::Pose2D;

// The car body is a length_m x width_m box around its centre pose. The planner's Reeds-Shepp
// reference point is the rear axle, rear_axle_from_centre_m behind the centre along the heading
// (1.3 m: 0.7 m from the rear bumper; wheelbase 2.6 m, so R = 2.6 / tan(0.48) = 5.0 m).
struct CarGeometry {
  double length_m = 4.0;
  double width_m = 2.0;
  double rear_axle_from_centre_m = 1.3;
  double min_turn_radius_m = 5.0;  // of the rear axle
};

Pose2D centreToRearAxle(const Pose2D& centre, const CarGeometry& car);
Pose2D rearAxleToCentre(const Pose2D& rear_axle, const CarGeometry& car);

// The body box inflated by inflation_m on every side.
geometry::OrientedBox footprint(const Pose2D& centre, const CarGeometry& car, double inflation_m);

}  // namespace aula::autopark
