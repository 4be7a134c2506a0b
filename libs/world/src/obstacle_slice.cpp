#include "aula/world/obstacle_slice.hpp"

namespace aula::world {

geometry::Obstacles2D sliceAtHeight(const WorldSpec& world, double z_m) {
  geometry::Obstacles2D out;
  for (const auto& o : world.statics) {
    if (o.shape.kind == ShapeKind::Mesh) {  // its cross-section, exactly
      sliceMesh(*o.shape.mesh, o.pose, z_m, out.segments);
      continue;
    }
    const auto [z0, z1] = o.shape.zRange(o.pose);
    if (z_m < z0 || z_m > z1) continue;
    const Eigen::Vector2d c = o.pose.translation().head<2>();
    if (o.shape.kind == ShapeKind::Cylinder) {
      out.circles.push_back({c, o.shape.radius_m});
    } else {
      out.rects.push_back(footprintOf(o));
    }
  }
  return out;
}

}  // namespace aula::world
