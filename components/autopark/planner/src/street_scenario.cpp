#include <aula/autopark/street_scenario.hpp>

#include <algorithm>
#include <cmath>

namespace aula::autopark {

OccupancyGrid StreetScenario::makeGrid(double resolution_m) const {
  const int w = static_cast<int>(std::lround((grid_max_x_m - grid_min_x_m) / resolution_m));
  const int h = static_cast<int>(std::lround((grid_max_y_m - grid_min_y_m) / resolution_m));
  OccupancyGrid grid(grid_min_x_m, grid_min_y_m, resolution_m, w, h);
  for (const auto& b : obstacles) grid.markBox(b);
  return grid;
}

StreetScenario makeParallelParkingStreet(double gap_m, double start_x_offset_m, double start_y_m) {
  StreetScenario s;
  const double car_l = 4.5, car_w = 1.8, car_y = -3.0;
  const double rear_car_x = 0.5;
  s.slot_rear_x_m = rear_car_x + 0.5 * car_l;
  s.slot_front_x_m = s.slot_rear_x_m + gap_m;
  const double front_car_x = s.slot_front_x_m + 0.5 * car_l;
  s.grid_min_x_m = -15.0;
  s.grid_max_x_m = front_car_x + 12.0;
  s.grid_min_y_m = -5.0;
  s.grid_max_y_m = 5.5;
  const double mid_x = 0.5 * (s.grid_min_x_m + s.grid_max_x_m);
  const double len_x = s.grid_max_x_m - s.grid_min_x_m + 2.0;
  s.obstacles.push_back({{mid_x, -4.75, 0.0}, len_x, 1.0});  // parking-side curb, face y = -4.25
  s.obstacles.push_back({{mid_x, 5.5, 0.0}, len_x, 1.0});    // far curb, face y = +5
  for (double x : {rear_car_x - 13.0, rear_car_x - 6.5, rear_car_x}) s.obstacles.push_back({{x, car_y, 0.0}, car_l, car_w});
  for (double x : {front_car_x, front_car_x + 7.5}) s.obstacles.push_back({{x, car_y, 0.0}, car_l, car_w});
  s.goal_centre = {s.slot_rear_x_m + 0.5 * gap_m, car_y, 0.0};
  s.start_centre = {s.slot_rear_x_m + start_x_offset_m, start_y_m, 0.0};
  return s;
}

bool footprintHitsBoxes(const Pose2D& centre, const CarGeometry& car, const std::vector<geometry::OrientedBox>& boxes,
                        double inflation_m) {
  const geometry::OrientedBox me = footprint(centre, car, inflation_m);
  return std::any_of(boxes.begin(), boxes.end(), [&](const geometry::OrientedBox& b) { return geometry::overlap(me, b); });
}

}  // namespace aula::autopark
