#include <aula/autopark/street_scenario.hpp>

#include <array>
#include <cmath>

namespace aula::autopark {

namespace {
using Poly = std::array<std::array<double, 2>, 4>;

Poly corners(const Pose2D& c, double length_m, double width_m) {
  CarGeometry g;
  g.length_m = length_m;
  g.width_m = width_m;
  return footprintCorners(c, g, 0.0);
}

bool separated(const Poly& a, const Poly& b) {
  for (const Poly* p : {&a, &b}) {
    for (int i = 0; i < 4; ++i) {
      const auto& u = (*p)[i];
      const auto& v = (*p)[(i + 1) % 4];
      const double nx = -(v[1] - u[1]), ny = v[0] - u[0];
      double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
      for (const auto& q : a) {
        const double d = nx * q[0] + ny * q[1];
        amin = std::min(amin, d);
        amax = std::max(amax, d);
      }
      for (const auto& q : b) {
        const double d = nx * q[0] + ny * q[1];
        bmin = std::min(bmin, d);
        bmax = std::max(bmax, d);
      }
      if (amax < bmin || bmax < amin) return true;
    }
  }
  return false;
}
}  // namespace

OccupancyGrid StreetScenario::makeGrid(double resolution_m) const {
  const int w = static_cast<int>(std::lround((grid_max_x_m - grid_min_x_m) / resolution_m));
  const int h = static_cast<int>(std::lround((grid_max_y_m - grid_min_y_m) / resolution_m));
  OccupancyGrid grid(grid_min_x_m, grid_min_y_m, resolution_m, w, h);
  for (const Box& b : obstacles) grid.markBox(b.centre, b.length_m, b.width_m);
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

bool footprintHitsBoxes(const Pose2D& centre, const CarGeometry& car, const std::vector<Box>& boxes,
                        double inflation_m) {
  const Poly me = footprintCorners(centre, car, inflation_m);
  for (const Box& b : boxes) {
    if (!separated(me, corners(b.centre, b.length_m, b.width_m))) return true;
  }
  return false;
}

}  // namespace aula::autopark
