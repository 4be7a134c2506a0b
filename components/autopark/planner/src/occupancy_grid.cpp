#include <aula/autopark/occupancy_grid.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aula::autopark {

OccupancyGrid::OccupancyGrid(double origin_x_m, double origin_y_m, double resolution_m, int width,
                             int height)
    : origin_x_m_(origin_x_m), origin_y_m_(origin_y_m), resolution_m_(resolution_m), width_(width),
      height_(height) {
  if (!(resolution_m > 0) || width <= 0 || height <= 0) {
    throw std::invalid_argument("OccupancyGrid: resolution_m, width and height must be > 0");
  }
  cells_.assign(static_cast<size_t>(width) * static_cast<size_t>(height), 0);
}

bool OccupancyGrid::worldToCell(double x_m, double y_m, int& col, int& row) const {
  const double fc = std::floor((x_m - origin_x_m_) / resolution_m_);
  const double fr = std::floor((y_m - origin_y_m_) / resolution_m_);
  if (!(fc >= 0 && fr >= 0 && fc < width_ && fr < height_)) return false;
  col = static_cast<int>(fc);
  row = static_cast<int>(fr);
  return true;
}

void OccupancyGrid::cellCentre(int col, int row, double& x_m, double& y_m) const {
  x_m = origin_x_m_ + (col + 0.5) * resolution_m_;
  y_m = origin_y_m_ + (row + 0.5) * resolution_m_;
}

void OccupancyGrid::markOccupied(double x_m, double y_m) {
  int c = 0, r = 0;
  if (worldToCell(x_m, y_m, c, r)) cells_[static_cast<size_t>(r) * width_ + c] = 1;
}

void OccupancyGrid::markCell(int col, int row) {
  if (inBounds(col, row)) cells_[static_cast<size_t>(row) * width_ + col] = 1;
}

void OccupancyGrid::markBox(const geometry::OrientedBox& box) {
  const Pose2D& centre = box.centre;
  const double c = std::cos(centre.yaw_rad), s = std::sin(centre.yaw_rad);
  const Eigen::Vector2d half = box.boundingHalfExtents();
  const double ex = half.x(), ey = half.y();
  const int c0 = std::max(0, static_cast<int>(std::floor((centre.x_m - ex - origin_x_m_) / resolution_m_)));
  const int c1 = std::min(width_ - 1, static_cast<int>(std::floor((centre.x_m + ex - origin_x_m_) / resolution_m_)));
  const int r0 = std::max(0, static_cast<int>(std::floor((centre.y_m - ey - origin_y_m_) / resolution_m_)));
  const int r1 = std::min(height_ - 1, static_cast<int>(std::floor((centre.y_m + ey - origin_y_m_) / resolution_m_)));
  for (int r = r0; r <= r1; ++r) {
    for (int col = c0; col <= c1; ++col) {
      double x = 0, y = 0;
      cellCentre(col, r, x, y);
      if (box.containsOffset(c, s, x - centre.x_m, y - centre.y_m)) markCell(col, r);
    }
  }
}

void OccupancyGrid::clear() { std::fill(cells_.begin(), cells_.end(), 0); }

bool OccupancyGrid::occupied(int col, int row) const {
  if (!inBounds(col, row)) return true;
  return cells_[static_cast<size_t>(row) * width_ + col] != 0;
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
