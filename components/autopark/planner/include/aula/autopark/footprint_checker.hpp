#pragma once
// Exact (cell-conservative) test of the car footprint against an occupancy grid: a pose is free
// when no occupied cell overlaps the body box inflated by inflation_m and the box lies inside the
// grid. Per-row prefix sums make one test O(rows spanned), about 50-100 rows at 0.05 m.

#include <aula/autopark/car_geometry.hpp>
#include <aula/autopark/occupancy_grid.hpp>

#include <vector>

namespace aula::autopark {

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
  double ox_, oy_, res_;
  int width_, height_;
  std::vector<int> prefix_;  // height x (width + 1): occupied cells in band r (from min y) with col < c
  CarGeometry car_;
  double inflation_m_;
};

}  // namespace aula::autopark
