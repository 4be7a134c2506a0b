#include "aula/world/obstacle_slice.hpp"

namespace aula::world {

geometry::Obstacles2D sliceAtHeight(const WorldSpec& world, double z_m) {
  geometry::Obstacles2D out;
  for (const auto& o : world.statics) {
    const double half = o.shape.halfHeight();
    const double z = o.pose.translation().z();
    if (z_m < z - half || z_m > z + half) continue;
    const Eigen::Vector2d c = o.pose.translation().head<2>();
    if (o.shape.kind == ShapeKind::Cylinder) {
      out.circles.push_back({c, o.shape.radius_m});
    } else {
      out.rects.push_back({{c.x(), c.y(), yawOf(o.pose)}, o.shape.box_size_m.x(), o.shape.box_size_m.y()});
    }
  }
  return out;
}

}  // namespace aula::world
