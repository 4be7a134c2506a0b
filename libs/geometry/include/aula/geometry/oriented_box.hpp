#pragma once
// A box lying in the plane: length_m along its heading, width_m across, centred on `centre` and
// turned by centre.yaw_rad about it. The one rectangle of Aula: car footprints (the parking
// referee's distances, the planner's collision checks) and static obstacles (occupancy maps,
// laser ray casting).

#include <aula/geometry/map_transform.hpp>
#include <aula/geometry/pose2d.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>

namespace aula::geometry {

struct OrientedBox {
  Pose2D centre;
  double length_m = 0.0;
  double width_m = 0.0;

  // Counter-clockwise, starting at the rear-right corner.
  std::array<Eigen::Vector2d, 4> corners() const {
    const double c = std::cos(centre.yaw_rad), s = std::sin(centre.yaw_rad);
    const double hl = length_m / 2, hw = width_m / 2;
    auto at = [&](double lx, double ly) { return Eigen::Vector2d(centre.x_m + c * lx - s * ly, centre.y_m + s * lx + c * ly); };
    return {at(-hl, -hw), at(hl, -hw), at(hl, hw), at(-hl, hw)};
  }

  // Inside or on the boundary.
  bool contains(double x_m, double y_m) const {
    return containsOffset(std::cos(centre.yaw_rad), std::sin(centre.yaw_rad), x_m - centre.x_m, y_m - centre.y_m);
  }

  // Half sizes of the smallest axis-aligned box around it.
  Eigen::Vector2d boundingHalfExtents() const {
    const double c = std::abs(std::cos(centre.yaw_rad)), s = std::abs(std::sin(centre.yaw_rad));
    const double hl = length_m / 2, hw = width_m / 2;
    return {c * hl + s * hw, s * hl + c * hw};
  }

  // The same box grown by margin_m on every side (a safety clearance).
  OrientedBox inflated(double margin_m) const { return {centre, length_m + 2 * margin_m, width_m + 2 * margin_m}; }

  // contains() for an offset (dx_m, dy_m) from the centre, with the heading's cos and sin given:
  // loops over many points compute them once.
  bool containsOffset(double cos_yaw, double sin_yaw, double dx_m, double dy_m) const {
    return std::abs(cos_yaw * dx_m + sin_yaw * dy_m) <= length_m / 2 &&
           std::abs(-sin_yaw * dx_m + cos_yaw * dy_m) <= width_m / 2;
  }
};

// True when the boxes share a point (touching counts). Separating-axis test on the four edge
// normals.
bool overlap(const OrientedBox& a, const OrientedBox& b);

// Minimum distance between the two boxes; 0 when they overlap.
double distance(const OrientedBox& a, const OrientedBox& b);

// How deep the boxes overlap: the least distance one must move to separate them (along an edge
// normal); 0 when they do not overlap.
double penetration(const OrientedBox& a, const OrientedBox& b);

// Calls mark_cell(col, row) for every cell of `grid` whose centre lies in the box (cells off the
// grid are skipped).
template <class MarkCell>
void rasterise(const OrientedBox& box, const MapTransform& grid, MarkCell&& mark_cell) {
  const double x = box.centre.x_m, y = box.centre.y_m;
  // The half diagonal bounds the box under any rotation, so rounding of a rotated footprint
  // cannot drop an edge cell out of the window.
  const double reach = 0.5 * std::sqrt(box.length_m * box.length_m + box.width_m * box.width_m);
  const int col0 = std::max(0, grid.worldToCol(x - reach));
  const int col1 = std::min(grid.width_px - 1, grid.worldToCol(x + reach));
  const int row0 = std::max(0, grid.worldToRow(y + reach));
  const int row1 = std::min(grid.height_px - 1, grid.worldToRow(y - reach));
  const double c = std::cos(box.centre.yaw_rad), s = std::sin(box.centre.yaw_rad);
  for (int row = row0; row <= row1; ++row) {
    const double dy = grid.rowToWorldY(row) - y;
    for (int col = col0; col <= col1; ++col) {
      if (box.containsOffset(c, s, grid.colToWorldX(col) - x, dy)) mark_cell(col, row);
    }
  }
}

}  // namespace aula::geometry
