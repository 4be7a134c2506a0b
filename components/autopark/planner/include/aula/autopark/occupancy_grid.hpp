#pragma once
// A 2D occupancy grid in world coordinates: cell (col, row) covers
// [origin_x + col*res, origin_x + (col+1)*res) x [origin_y + row*res, origin_y + (row+1)*res).
// The planner treats everything outside the grid as occupied.

#include <aula/autopark/car_geometry.hpp>

#include <cstdint>
#include <vector>

namespace aula::autopark {

class OccupancyGrid {
 public:
  OccupancyGrid() = default;
  // width x height cells of resolution_m; (origin_x_m, origin_y_m) is the outer corner of cell (0, 0).
  OccupancyGrid(double origin_x_m, double origin_y_m, double resolution_m, int width, int height);

  double originX_m() const { return origin_x_m_; }
  double originY_m() const { return origin_y_m_; }
  double resolution_m() const { return resolution_m_; }
  int width() const { return width_; }
  int height() const { return height_; }

  bool inBounds(int col, int row) const { return col >= 0 && row >= 0 && col < width_ && row < height_; }
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
  double origin_x_m_ = 0.0;
  double origin_y_m_ = 0.0;
  double resolution_m_ = 0.1;
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> cells_;
};

}  // namespace aula::autopark
