#pragma once
// Gradient Path Planning (the thesis's GPP, done fast): a navigation field over an occupancy
// grid, grown as a wavefront from the destination over the free cells (8-connected, straight
// step 1, diagonal step sqrt(2)) plus a per-cell obstacle penalty that decreases with distance
// to the nearest obstacle, so that paths keep off the walls. The path is the steepest descent
// of the field from the robot to the destination.
//
// Cells are (x, y) = (column, row) everywhere. The whole field is computed, not a partial one.
// Costs are fixed point (kScale units per cell; diagonal 141/100) so that a bucket queue
// (Dial's algorithm) replaces the heap: the 400 x 400 city field takes well under 2 ms.

#include <opencv2/core.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace aula::teletaxi {

struct FieldParams {
  double core_radius_cells = 2.0;     // cells closer than this to an obstacle are forbidden
  double penalty_radius_cells = 8.0;  // the penalty fades to zero at this distance
  double penalty_max = 6.0;           // extra cost (in cells of travel) at the core's edge
};

struct Cell {
  int x = 0, y = 0;
  bool operator==(const Cell& o) const { return x == o.x && y == o.y; }
};

class GradientField {
 public:
  static constexpr uint32_t kScale = 100;  // fixed-point units per cell of travel
  static constexpr uint32_t kUnreached = std::numeric_limits<uint32_t>::max();

  // map: CV_8UC1, 0 = obstacle. Precomputes the per-cell penalty (it depends on the map only).
  GradientField(const cv::Mat& map, const FieldParams& params = {});

  // The full field from `goal`; false if the goal is an obstacle or in the penalty core.
  bool compute(Cell goal);

  int width() const { return width_; }
  int height() const { return height_; }
  bool traversable(int x, int y) const;            // free and outside the core
  float value(int x, int y) const;                 // cells of travel + penalty; +inf if unreached
  float penalty(int x, int y) const;               // the obstacle penalty of a cell
  // Steepest descent from `start` to the goal; empty if start is unreached.
  std::vector<Cell> descend(Cell start) const;

 private:
  size_t index(int x, int y) const { return static_cast<size_t>(y + 1) * stride_ + (x + 1); }

  int width_ = 0, height_ = 0;
  size_t stride_ = 0;
  // Padded grid, field and cost side by side so one cache line serves both. Blocked cells keep
  // field = 0 during a computation, so no relaxation ever improves them (no branch needed).
  struct CellData {
    uint32_t field;
    uint32_t cost;  // per-cell penalty in units; kUnreached = blocked
  };
  std::vector<CellData> cells_;
  std::vector<std::vector<uint32_t>> buckets_;
  uint32_t max_edge_ = 0;  // largest single-step cost, sizes the bucket ring
  Cell goal_{-1, -1};
};

}  // namespace aula::teletaxi
