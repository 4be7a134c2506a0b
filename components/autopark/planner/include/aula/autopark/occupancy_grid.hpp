#pragma once
// A 2D occupancy grid in world coordinates on the one geometry::MapTransform (north-up: row 0 is
// the grid's top edge). The planner treats everything outside the grid as occupied.

#include <aula/autopark/car_geometry.hpp>
#include <aula/geometry/map_transform.hpp>
#include <aula/geometry/oriented_box.hpp>

#include <cstdint>
#include <vector>

namespace aula::autopark {

class OccupancyGrid {
 public:
  OccupancyGrid() = default;
  // width x height cells of resolution_m over [min_x_m, min_x_m + width * resolution_m) x
  // [min_y_m, min_y_m + height * resolution_m).
  OccupancyGrid(double min_x_m, double min_y_m, double resolution_m, int width, int height);

  const geometry::MapTransform& transform() const { return transform_; }
  double minX_m() const { return transform_.origin_x_m; }
  double minY_m() const { return transform_.origin_y_m - transform_.height_px * transform_.resolution_m; }
  double maxX_m() const { return transform_.origin_x_m + transform_.width_px * transform_.resolution_m; }
  double maxY_m() const { return transform_.origin_y_m; }
  double resolution_m() const { return transform_.resolution_m; }
  int width() const { return transform_.width_px; }
  int height() const { return transform_.height_px; }

  bool inBounds(int col, int row) const { return transform_.contains(col, row); }
  // Cell containing a world point; false if outside the grid.
  bool worldToCell(double x_m, double y_m, int& col, int& row) const;
  // World coordinates of a cell centre.
  void cellCentre(int col, int row, double& x_m, double& y_m) const;

  // Marks the cell containing (x, y); points outside the grid are ignored (e.g. laser hits).
  void markOccupied(double x_m, double y_m);
  void markCell(int col, int row);
  // Marks every cell whose centre lies in the box (ground-truth obstacles: parked cars, curbs).
  void markBox(const geometry::OrientedBox& box);
  void clear();

  // Outside the grid counts as occupied.
  bool occupied(int col, int row) const;
  bool occupiedAt(double x_m, double y_m) const;
  int occupiedCount() const;
  const std::vector<std::uint8_t>& cells() const { return cells_; }  // row-major, 1 = occupied

 private:
  geometry::MapTransform transform_{0.1, 0.0, 0.0, 0, 0};
  std::vector<std::uint8_t> cells_;
};

}  // namespace aula::autopark
