#pragma once
// A robot's collision shape cut in the plane at its current pose, for other robots' lasers.

#include <aula/geometry/raycaster2d.hpp>
#include <aula/physics/physics_world.hpp>

#include <cmath>

namespace aula::drivers {

inline void appendFootprint(const physics::PhysicsWorld& physics, int robot, geometry::Obstacles2D& out) {
  const auto& spec = physics.robotSpec(robot);
  const physics::RobotState s = physics.robotState(robot);
  const double c = std::cos(s.yaw_rad), sn = std::sin(s.yaw_rad);
  const Eigen::Vector2d off = spec.shape_offset.translation().head<2>();
  const Eigen::Vector2d center =
      s.position_m.head<2>() + Eigen::Vector2d(c * off.x() - sn * off.y(), sn * off.x() + c * off.y());
  if (spec.shape.kind == world::ShapeKind::Cylinder) {
    out.circles.push_back({center, spec.shape.radius_m});
  } else {
    out.rects.push_back({{center.x(), center.y(), s.yaw_rad + world::yawOf(spec.shape_offset)},
                         spec.shape.box_size_m.x(), spec.shape.box_size_m.y()});
  }
}

}  // namespace aula::drivers
