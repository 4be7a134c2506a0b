#include "aula/world/occupancy_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace aula::world {
namespace {

// Vertical extent of a primitive (its local z axis assumed close to vertical).
std::pair<double, double> zRange(const StaticObject& o) {
  const double half = o.shape.halfHeight();
  const double z = o.pose.translation().z();
  return {z - half, z + half};
}

}  // namespace

Eigen::Vector4d staticBounds(const WorldSpec& world) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  double x1 = -x0, y1 = -x0;
  for (const auto& o : world.statics) {
    const Eigen::Vector2d c = o.pose.translation().head<2>();
    double rx, ry;
    if (o.shape.kind == ShapeKind::Cylinder) {
      rx = ry = o.shape.radius_m;
    } else {
      const double yaw = yawOf(o.pose);
      const double hx = o.shape.box_size_m.x() / 2, hy = o.shape.box_size_m.y() / 2;
      rx = std::abs(std::cos(yaw)) * hx + std::abs(std::sin(yaw)) * hy;
      ry = std::abs(std::sin(yaw)) * hx + std::abs(std::cos(yaw)) * hy;
    }
    x0 = std::min(x0, c.x() - rx);
    x1 = std::max(x1, c.x() + rx);
    y0 = std::min(y0, c.y() - ry);
    y1 = std::max(y1, c.y() + ry);
  }
  return {x0, y0, x1, y1};
}

cv::Mat rasterizeOccupancy(const WorldSpec& world, const MapTransform& t, double z_min_m, double z_max_m) {
  cv::Mat map(t.height_px, t.width_px, CV_8UC1, cv::Scalar(255));
  for (const auto& o : world.statics) {
    const auto [z0, z1] = zRange(o);
    if (z1 < z_min_m || z0 > z_max_m) continue;
    const Eigen::Vector2d c = o.pose.translation().head<2>();
    const double yaw = yawOf(o.pose);
    const double cs = std::cos(yaw), sn = std::sin(yaw);
    double reach;  // footprint radius bound, for the pixel window
    if (o.shape.kind == ShapeKind::Cylinder) {
      reach = o.shape.radius_m;
    } else {
      reach = 0.5 * o.shape.box_size_m.head<2>().norm();
    }
    const int col0 = std::max(0, t.worldToCol(c.x() - reach));
    const int col1 = std::min(t.width_px - 1, t.worldToCol(c.x() + reach));
    const int row0 = std::max(0, t.worldToRow(c.y() + reach));
    const int row1 = std::min(t.height_px - 1, t.worldToRow(c.y() - reach));
    for (int row = row0; row <= row1; ++row) {
      uint8_t* line = map.ptr<uint8_t>(row);
      const double dy = t.rowToWorldY(row) - c.y();
      for (int col = col0; col <= col1; ++col) {
        const double dx = t.colToWorldX(col) - c.x();
        bool inside;
        if (o.shape.kind == ShapeKind::Cylinder) {
          inside = dx * dx + dy * dy <= o.shape.radius_m * o.shape.radius_m;
        } else {
          const double lx = cs * dx + sn * dy, ly = -sn * dx + cs * dy;
          inside = std::abs(lx) <= o.shape.box_size_m.x() / 2 && std::abs(ly) <= o.shape.box_size_m.y() / 2;
        }
        if (inside) line[col] = 0;
      }
    }
  }
  return map;
}

}  // namespace aula::world
