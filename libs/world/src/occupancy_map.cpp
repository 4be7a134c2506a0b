#include "aula/world/occupancy_map.hpp"

#include <aula/config/paths.hpp>
#include <aula/geometry/oriented_box.hpp>

#include <aula/image/png.hpp>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

#include <unistd.h>

namespace aula::world {
namespace {

// Vertical extent of a primitive (its local z axis assumed close to vertical).
std::pair<double, double> zRange(const StaticObject& o) {
  const double half = o.shape.halfHeight();
  const double z = o.pose.translation().z();
  return {z - half, z + half};
}

// The footprint of a box primitive.
geometry::OrientedBox footprintOf(const StaticObject& o) {
  const Eigen::Vector3d c = o.pose.translation();
  return {{c.x(), c.y(), yawOf(o.pose)}, o.shape.box_size_m.x(), o.shape.box_size_m.y()};
}

}  // namespace

Eigen::Vector4d staticBounds(const WorldSpec& world) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  double x1 = -x0, y1 = -x0;
  for (const auto& o : world.statics) {
    const Eigen::Vector2d c = o.pose.translation().head<2>();
    const Eigen::Vector2d r = o.shape.kind == ShapeKind::Cylinder ? Eigen::Vector2d::Constant(o.shape.radius_m)
                                                                  : footprintOf(o).boundingHalfExtents();
    x0 = std::min(x0, c.x() - r.x());
    x1 = std::max(x1, c.x() + r.x());
    y0 = std::min(y0, c.y() - r.y());
    y1 = std::max(y1, c.y() + r.y());
  }
  return {x0, y0, x1, y1};
}

cv::Mat rasterizeOccupancy(const WorldSpec& world, const geometry::MapTransform& t, double z_min_m, double z_max_m) {
  cv::Mat map(t.height_px, t.width_px, CV_8UC1, cv::Scalar(255));
  for (const auto& o : world.statics) {
    const auto [z0, z1] = zRange(o);
    if (z1 < z_min_m || z0 > z_max_m) continue;
    if (o.shape.kind != ShapeKind::Cylinder) {
      geometry::rasterise(footprintOf(o), t, [&map](int col, int row) { map.at<uint8_t>(row, col) = 0; });
      continue;
    }
    const Eigen::Vector2d c = o.pose.translation().head<2>();
    const double reach = o.shape.radius_m;
    const int col0 = std::max(0, t.worldToCol(c.x() - reach));
    const int col1 = std::min(t.width_px - 1, t.worldToCol(c.x() + reach));
    const int row0 = std::max(0, t.worldToRow(c.y() + reach));
    const int row1 = std::min(t.height_px - 1, t.worldToRow(c.y() - reach));
    for (int row = row0; row <= row1; ++row) {
      uint8_t* line = map.ptr<uint8_t>(row);
      const double dy = t.rowToWorldY(row) - c.y();
      for (int col = col0; col <= col1; ++col) {
        const double dx = t.colToWorldX(col) - c.x();
        if (dx * dx + dy * dy <= o.shape.radius_m * o.shape.radius_m) line[col] = 0;
      }
    }
  }
  return map;
}

}  // namespace aula::world

namespace aula::world {

namespace {
constexpr int kMaxMapPx = 20000;  // 400 MB of map: far past any exercise's world
}  // namespace

geometry::MapTransform fitTransform(const WorldSpec& world, double resolution_m) {
  if (world.statics.empty()) throw WorldError(world.source_path + ": no static geometry to map");
  const Eigen::Vector4d bounds = staticBounds(world);
  geometry::MapTransform t;
  t.resolution_m = resolution_m;
  // The 1e-6 px tolerance absorbs rounding of rotated footprints (cos(pi/2) != 0).
  const double width_px = std::ceil((bounds[2] - bounds[0]) / resolution_m - 1e-6);
  const double height_px = std::ceil((bounds[3] - bounds[1]) / resolution_m - 1e-6);
  // Checked before it becomes an int: a huge box must be said as such, never wrap around into
  // an image size OpenCV asserts on.
  if (!(width_px <= kMaxMapPx) || !(height_px <= kMaxMapPx)) {
    char size[96];
    std::snprintf(size, sizeof size, "%.4g x %.4g px", width_px, height_px);
    throw WorldError(world.source_path + ": the map would be " + size + " (its static geometry spans " +
                     std::to_string(bounds[2] - bounds[0]) + " x " + std::to_string(bounds[3] - bounds[1]) +
                     " m); at most " + std::to_string(kMaxMapPx) + " px a side: use a coarser Map.Resolution or smaller models");
  }
  t.width_px = static_cast<int>(width_px);
  t.height_px = static_cast<int>(height_px);
  const double cx = (bounds[0] + bounds[2]) / 2, cy = (bounds[1] + bounds[3]) / 2;
  t.origin_x_m = cx - t.width_px * resolution_m / 2;
  t.origin_y_m = cy + t.height_px * resolution_m / 2;
  return t;
}

OccupancyMap occupancyMapOf(const WorldSpec& world, const MapParams& params) {
  OccupancyMap out;
  out.transform = fitTransform(world, params.resolution_m);
  // Key: everything the raster depends on, printed exactly.
  std::ostringstream key;
  key << std::setprecision(17) << "aula-map-v1 " << params.resolution_m << ' ' << params.z_min_m << ' '
      << params.z_max_m << '\n';
  for (const auto& o : world.statics) {
    key << static_cast<int>(o.shape.kind) << ' ' << o.shape.box_size_m.transpose() << ' ' << o.shape.radius_m << ' '
        << o.shape.length_m << ' ' << o.pose.matrix().reshaped().transpose() << '\n';
  }
  const std::string folder = config::cacheDir() + "/maps";
  const std::string png = folder + "/" + sha256Hex(key.str()) + ".png";
  if (std::filesystem::exists(png)) out.image = image::readGrayPng(png);
  if (!out.image.empty() && out.image.cols == out.transform.width_px && out.image.rows == out.transform.height_px) {
    return out;
  }
  out.image = rasterizeOccupancy(world, out.transform, params.z_min_m, params.z_max_m);
  // Written aside and renamed, so a parallel run never reads half a file. A cache that cannot
  // be written only costs the next run the raster.
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  const std::string partial = png + "." + std::to_string(::getpid()) + ".tmp.png";
  if (!error && image::writePng(partial, out.image)) std::filesystem::rename(partial, png, error);
  return out;
}

std::optional<std::string> pointProblem(const OccupancyMap& map, double x_m, double y_m) {
  char where[96];
  std::snprintf(where, sizeof where, "(%.1f, %.1f) ", x_m, y_m);
  const geometry::MapTransform& t = map.transform;
  const int col = t.worldToCol(x_m), row = t.worldToRow(y_m);
  if (!t.contains(col, row) || !std::isfinite(x_m) || !std::isfinite(y_m)) {
    char text[160];
    std::snprintf(text, sizeof text, "is off the map (x in [%.1f, %.1f], y in [%.1f, %.1f] m)", t.origin_x_m,
                  t.origin_x_m + t.width_px * t.resolution_m, t.origin_y_m - t.height_px * t.resolution_m, t.origin_y_m);
    return where + std::string(text);
  }
  if (map.image.at<uint8_t>(row, col) == 0) return where + std::string("is inside a building or obstacle");
  return std::nullopt;
}

}  // namespace aula::world
