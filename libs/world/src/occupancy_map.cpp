#include "aula/world/occupancy_map.hpp"
#include "reader_version.hpp"

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

// Marks every cell a segment passes through (a wall of no thickness must still block the map).
void drawSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const geometry::MapTransform& t, cv::Mat& map) {
  const double length = (b - a).norm();
  const int steps = std::max(1, static_cast<int>(std::ceil(4 * length / t.resolution_m)));
  for (int i = 0; i <= steps; ++i) {
    const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(i) / steps);
    const int col = t.worldToCol(p.x()), row = t.worldToRow(p.y());
    if (t.contains(col, row)) map.at<uint8_t>(row, col) = 0;
  }
}

// A convex polygon seen from above (a clipped triangle): the cells whose centre lies in it, and
// its edges (a vertical wall projects to a line).
void drawPolygon(const std::vector<Eigen::Vector2d>& poly, const geometry::MapTransform& t, cv::Mat& map) {
  double area2 = 0;
  Eigen::AlignedBox2d box;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d& p = poly[i];
    const Eigen::Vector2d& q = poly[(i + 1) % poly.size()];
    area2 += p.x() * q.y() - q.x() * p.y();
    box.extend(p);
    drawSegment(p, q, t, map);
  }
  if (std::abs(area2) < 1e-12) return;
  const double sign = area2 > 0 ? 1.0 : -1.0;
  const int col0 = std::max(0, t.worldToCol(box.min().x())), col1 = std::min(t.width_px - 1, t.worldToCol(box.max().x()));
  const int row0 = std::max(0, t.worldToRow(box.max().y())), row1 = std::min(t.height_px - 1, t.worldToRow(box.min().y()));
  for (int row = row0; row <= row1; ++row) {
    const double y = t.rowToWorldY(row);
    for (int col = col0; col <= col1; ++col) {
      const double x = t.colToWorldX(col);
      bool inside = true;
      for (std::size_t i = 0; i < poly.size() && inside; ++i) {
        const Eigen::Vector2d& p = poly[i];
        const Eigen::Vector2d& q = poly[(i + 1) % poly.size()];
        inside = sign * ((q.x() - p.x()) * (y - p.y()) - (q.y() - p.y()) * (x - p.x())) >= 0;
      }
      if (inside) map.at<uint8_t>(row, col) = 0;
    }
  }
}

// The inside of closed outlines (a mesh's cross-section): cells whose centre has an odd number of
// segments to its left on its row (even-odd rule, so a courtyard stays free).
void fillOutlines(const std::vector<geometry::Segment2>& segments, const geometry::MapTransform& t, cv::Mat& map) {
  std::vector<std::vector<double>> crossings(static_cast<std::size_t>(t.height_px));
  for (const auto& s : segments) {
    const int row0 = std::max(0, t.worldToRow(std::max(s.a_m.y(), s.b_m.y())));
    const int row1 = std::min(t.height_px - 1, t.worldToRow(std::min(s.a_m.y(), s.b_m.y())));
    for (int row = row0; row <= row1; ++row) {
      const double y = t.rowToWorldY(row);
      if ((s.a_m.y() > y) == (s.b_m.y() > y)) continue;  // half-open: a shared end counts once
      crossings[row].push_back(s.a_m.x() + (y - s.a_m.y()) / (s.b_m.y() - s.a_m.y()) * (s.b_m.x() - s.a_m.x()));
    }
  }
  for (int row = 0; row < t.height_px; ++row) {
    auto& xs = crossings[row];
    if (xs.size() < 2) continue;
    std::sort(xs.begin(), xs.end());
    uint8_t* line = map.ptr<uint8_t>(row);
    for (std::size_t i = 0; i + 1 < xs.size(); i += 2) {
      const int col0 = std::max(0, static_cast<int>(std::ceil(t.worldToColF(xs[i]) - 0.5)));
      const int col1 = std::min(t.width_px - 1, static_cast<int>(std::floor(t.worldToColF(xs[i + 1]) - 0.5)));
      for (int col = col0; col <= col1; ++col) line[col] = 0;
    }
  }
}

// A mesh in the band [z_min_m, z_max_m]: what its triangles cover within the band seen from above
// (roofs, walls as lines), and the inside of its cross-sections at the band's lowest and highest
// heights it reaches (a building taller than the band is solid, not an outline).
void drawMesh(const StaticObject& o, const geometry::MapTransform& t, double z_min_m, double z_max_m, cv::Mat& map) {
  std::vector<std::vector<Eigen::Vector2d>> polygons;
  projectMesh(*o.shape.mesh, o.pose, z_min_m, z_max_m, polygons);
  for (const auto& poly : polygons) drawPolygon(poly, t, map);
  const auto [z0, z1] = o.shape.zRange(o.pose);
  const double kInside = 1e-6;  // a plane through the mesh's top or bottom face cuts nothing
  for (const double z : {std::max(z_min_m, z0 + kInside), std::min(z_max_m, z1 - kInside)}) {
    if (z < z0 || z > z1) continue;
    std::vector<geometry::Segment2> outline;
    sliceMesh(*o.shape.mesh, o.pose, z, outline);
    fillOutlines(outline, t, map);
  }
}

}  // namespace

Eigen::Vector4d staticBounds(const WorldSpec& world) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  double x1 = -x0, y1 = -x0;
  auto extend = [&](double x, double y) {
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  };
  for (const auto& o : world.statics) {
    if (o.shape.kind == ShapeKind::Mesh) {
      for (const auto& v : o.shape.mesh->vertices_m) {
        const Eigen::Vector3d p = o.pose * v;
        extend(p.x(), p.y());
      }
      continue;
    }
    const Eigen::Vector2d c = o.pose.translation().head<2>();
    const Eigen::Vector2d r = o.shape.kind == ShapeKind::Cylinder ? Eigen::Vector2d::Constant(o.shape.radius_m)
                                                                  : footprintOf(o).boundingHalfExtents();
    extend(c.x() - r.x(), c.y() - r.y());
    extend(c.x() + r.x(), c.y() + r.y());
  }
  return {x0, y0, x1, y1};
}

cv::Mat rasterizeOccupancy(const WorldSpec& world, const geometry::MapTransform& t, double z_min_m, double z_max_m) {
  cv::Mat map(t.height_px, t.width_px, CV_8UC1, cv::Scalar(255));
  for (const auto& o : world.statics) {
    const auto [z0, z1] = o.shape.zRange(o.pose);
    if (z1 < z_min_m || z0 > z_max_m) continue;
    if (o.shape.kind == ShapeKind::Mesh) {
      drawMesh(o, t, z_min_m, z_max_m, map);
      continue;
    }
    if (o.shape.kind == ShapeKind::Box) {
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
  // Key: everything the raster depends on, printed exactly, the rasterizer's own sources among them.
  std::ostringstream key;
  key << std::setprecision(17) << "aula-map-v1 " << kReaderSourceSha256 << ' ' << params.resolution_m << ' ' << params.z_min_m << ' '
      << params.z_max_m << '\n';
  for (const auto& o : world.statics) {
    key << static_cast<int>(o.shape.kind) << ' ' << o.shape.box_size_m.transpose() << ' ' << o.shape.radius_m << ' '
        << o.shape.length_m << ' ' << o.pose.matrix().reshaped().transpose() << '\n';
    if (o.shape.kind == ShapeKind::Mesh) {  // the mesh's file's content and how it is read
      const MeshSource& m = o.shape.mesh_source;
      key << "mesh " << o.shape.mesh->file_sha256 << ' ' << m.scale.transpose() << ' ' << m.submesh << ' '
          << m.center_submesh << '\n';
    }
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
