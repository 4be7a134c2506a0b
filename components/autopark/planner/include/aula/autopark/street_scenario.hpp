#pragma once
// Ground-truth parallel-parking street (as in worlds/autopark_*.world): curbs at y = -4.25 and
// y = +5, parked 4.5 x 1.8 m cars centred at y = -3, a free gap between two of them. Used by the
// planner's tests and benchmark; the component builds its grid from the lasers instead.

#include <aula/autopark/car_geometry.hpp>
#include <aula/autopark/occupancy_grid.hpp>

#include <vector>

namespace aula::autopark {

struct StreetScenario {
  std::vector<geometry::OrientedBox> obstacles;  // curbs and parked cars
  Pose2D goal_centre;          // slot centre, y = -3, yaw 0
  Pose2D start_centre;         // in the lane, before the slot
  double slot_rear_x_m = 0.0;  // front bumper of the car behind the slot
  double slot_front_x_m = 0.0; // rear bumper of the car ahead of the slot
  double grid_min_x_m = 0.0, grid_min_y_m = 0.0, grid_max_x_m = 0.0, grid_max_y_m = 0.0;

  // Rasterises the obstacles (cells whose centre is inside a box) into a grid covering the street.
  OccupancyGrid makeGrid(double resolution_m = 0.05) const;
};

// gap_m: free length between the bumpers. The car behind the slot is centred at x = 0.5 (front
// bumper 2.75); start (centre) at (slot_rear_x - 7, 1.5), yaw 0 unless given.
StreetScenario makeParallelParkingStreet(double gap_m, double start_x_offset_m = -7.0, double start_y_m = 1.5);

// True if the car box at `centre` (inflated by inflation_m) intersects any obstacle box
// (independent of the grid).
bool footprintHitsBoxes(const Pose2D& centre, const CarGeometry& car, const std::vector<geometry::OrientedBox>& boxes,
                        double inflation_m = 0.0);

}  // namespace aula::autopark
