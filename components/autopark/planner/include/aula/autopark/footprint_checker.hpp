#pragma once
// Exact (cell-conservative) test of the car footprint against an occupancy grid: a pose is free
// when no occupied cell overlaps the body box inflated by inflation_m and the box lies inside the
// grid. Per-row prefix sums make one test O(rows spanned), about 50-100 rows at 0.05 m.

#include <aula/autopark/car_geometry.hpp>
#include <aula/autopark/occupancy_grid.hpp>

#include <array>
#include <limits>
#include <vector>

namespace aula::autopark {

// A convex quadrilateral (the car's box) read row by row: the x span it covers at a height, or
// within a horizontal band, so a row of the grid can be tested with one prefix-sum lookup.
class BoxChord {
 public:
  // The x range covered, empty (lo_x > hi_x) until something widens it.
  struct Span {
    double lo_x = std::numeric_limits<double>::infinity(), hi_x = -std::numeric_limits<double>::infinity();
  };
  explicit BoxChord(const std::array<Eigen::Vector2d, 4>& corners);
  // The chord at the box's lowest height (a vertex or a horizontal edge).
  Span bottom(double ymin) const;
  // The chord at a band's upper bound b1 (clipped to ymax; at ymax, the top vertex or edge).
  Span top(double b1, double ymax) const;
  // The span within the band [b0, b1] from the chords at its two bounds and the corners inside it.
  Span band(const Span& below, const Span& above, double b0, double b1) const;

 private:
  // A non-horizontal edge as x(y) = x0 + (y - y0) * slope over [y0, y1].
  struct Edge {
    double y0, y1, x0, slope;
  };
  void widen(double y, double& lo_x, double& hi_x) const;
  void widenByCorners(bool (*keep)(double corner_y, double y0, double y1), double y0, double y1, double& lo_x,
                      double& hi_x) const;
  std::array<Eigen::Vector2d, 4> corners_;
  Edge edges_[4];
  int count_ = 0;
};

class FootprintChecker {
 public:
  // Copies what it needs from the grid: later changes to the grid are not seen.
  FootprintChecker(const OccupancyGrid& grid, const CarGeometry& car, double inflation_m);

  bool freeCentre(const Pose2D& centre) const;
  bool freeRearAxle(const Pose2D& rear_axle) const { return freeCentre(rearAxleToCentre(rear_axle, car_)); }
  // Same test with a different inflation (e.g. "well clear" tests).
  bool freeCentre(const Pose2D& centre, double inflation_m) const;

  const CarGeometry& car() const { return car_; }
  double inflation_m() const { return inflation_m_; }

 private:
  // Any occupied cell (or the grid's outside) between lo_x and hi_x in band `row`.
  bool rowBlocked(int row, double lo_x, double hi_x) const;
  double ox_, oy_, res_;
  int width_, height_;
  std::vector<int> prefix_;  // height x (width + 1): occupied cells in band r (from min y) with col < c
  CarGeometry car_;
  double inflation_m_;
};

}  // namespace aula::autopark
