#include <aula/autopark/occupancy_grid.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aula::autopark {

OccupancyGrid::OccupancyGrid(double min_x_m, double min_y_m, double resolution_m, int width, int height)
    : transform_{resolution_m, min_x_m, min_y_m + height * resolution_m, width, height} {
  if (!(resolution_m > 0) || width <= 0 || height <= 0) {
    throw std::invalid_argument("OccupancyGrid: resolution_m, width and height must be > 0");
  }
  cells_.assign(static_cast<size_t>(width) * static_cast<size_t>(height), 0);
}

bool OccupancyGrid::worldToCell(double x_m, double y_m, int& col, int& row) const {
  // Bounds checked on the floored doubles: a far point must not overflow the int cast.
  const double fc = std::floor(transform_.worldToColF(x_m));
  const double fr = std::floor(transform_.worldToRowF(y_m));
  if (!(fc >= 0 && fr >= 0 && fc < width() && fr < height())) return false;
  col = static_cast<int>(fc);
  row = static_cast<int>(fr);
  return true;
}

void OccupancyGrid::cellCentre(int col, int row, double& x_m, double& y_m) const {
  x_m = transform_.colToWorldX(col);
  y_m = transform_.rowToWorldY(row);
}

void OccupancyGrid::markOccupied(double x_m, double y_m) {
  int c = 0, r = 0;
  if (worldToCell(x_m, y_m, c, r)) markCell(c, r);
}

void OccupancyGrid::markCell(int col, int row) {
  if (inBounds(col, row)) cells_[static_cast<size_t>(row) * width() + col] = 1;
}

void OccupancyGrid::markBox(const geometry::OrientedBox& box) {
  geometry::rasterise(box, transform_, [this](int col, int row) { markCell(col, row); });
}

void OccupancyGrid::clear() { std::fill(cells_.begin(), cells_.end(), 0); }

bool OccupancyGrid::occupied(int col, int row) const {
  if (!inBounds(col, row)) return true;
  return cells_[static_cast<size_t>(row) * width() + col] != 0;
}

bool OccupancyGrid::occupiedAt(double x_m, double y_m) const {
  int c = 0, r = 0;
  if (!worldToCell(x_m, y_m, c, r)) return true;
  return occupied(c, r);
}

int OccupancyGrid::occupiedCount() const {
  return static_cast<int>(std::count(cells_.begin(), cells_.end(), std::uint8_t{1}));
}

}  // namespace aula::autopark
