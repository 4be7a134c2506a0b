#include "aula/scoring/parking_geometry.hpp"

#include <aula/geometry/angles.hpp>
#include <aula/geometry/oriented_box.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace aula::autopark {

using geometry::OrientedBox;

double ParkingScene::slotLengthM() const {
  return (front_car.centre.x_m - front_car.length_m / 2) - (rear_car.centre.x_m + rear_car.length_m / 2);
}

double ParkingScene::idealGapM() const { return (slotLengthM() - car_length_m) / 2; }

ParkingScene ParkingScene::fromWorld(const world::WorldSpec& world, const std::string& robot_name) {
  const std::string where = world.source_path.empty() ? world.name : world.source_path;
  std::vector<OrientedBox> parked;
  bool have_curb = false;
  ParkingScene scene;
  for (const auto& s : world.statics) {
    if (s.shape.kind != world::ShapeKind::Box) continue;
    const double yaw = world::yawOf(s.pose);
    if (s.name.rfind("parked_car", 0) == 0) {
      parked.push_back(OrientedBox{{s.pose.translation().x(), s.pose.translation().y(), yaw}, s.shape.box_size_m.x(), s.shape.box_size_m.y()});
    } else if (s.name.find("curb_parking_side") != std::string::npos) {
      scene.curb_y_m = s.pose.translation().y() + s.shape.box_size_m.y() / 2;
      scene.street_west_x_m = s.pose.translation().x() - s.shape.box_size_m.x() / 2;
      scene.street_east_x_m = s.pose.translation().x() + s.shape.box_size_m.x() / 2;
      have_curb = true;
    } else if (s.name.find("curb_far_side") != std::string::npos) {
      scene.far_curb_y_m = s.pose.translation().y() - s.shape.box_size_m.y() / 2;
    }
  }
  if (!have_curb) throw world::WorldError(where + ": no collision named curb_parking_side (the parking-side curb)");
  if (parked.size() < 2) throw world::WorldError(where + ": needs at least two static models named parked_car*");
  std::sort(parked.begin(), parked.end(), [](const OrientedBox& a, const OrientedBox& b) { return a.centre.x_m < b.centre.x_m; });
  scene.parked_cars = parked;
  double widest = -1;
  for (size_t i = 0; i + 1 < parked.size(); ++i) {
    const double gap = (parked[i + 1].centre.x_m - parked[i + 1].length_m / 2) - (parked[i].centre.x_m + parked[i].length_m / 2);
    if (gap > widest) {
      widest = gap;
      scene.rear_car = parked[i];
      scene.front_car = parked[i + 1];
    }
  }
  const world::RobotSpec* car = world.findRobot(robot_name);
  if (car == nullptr) throw world::WorldError(where + ": no robot named '" + robot_name + "'");
  if (car->shape.kind != world::ShapeKind::Box) throw world::WorldError(where + ": robot '" + robot_name + "' must be a box");
  scene.car_length_m = car->shape.box_size_m.x();
  scene.car_width_m = car->shape.box_size_m.y();
  scene.ideal_x_m = (scene.rear_car.centre.x_m + scene.rear_car.length_m / 2 + scene.front_car.centre.x_m - scene.front_car.length_m / 2) / 2;
  scene.ideal_y_m = (scene.rear_car.centre.y_m + scene.front_car.centre.y_m) / 2;
  scene.ideal_yaw_rad = 0.0;
  return scene;
}

ParkingMeasures measureParking(const ParkingScene& scene, double x_m, double y_m, double yaw_rad) {
  const OrientedBox car{{x_m, y_m, yaw_rad}, scene.car_length_m, scene.car_width_m};
  ParkingMeasures m;
  m.front_gap_m = geometry::distance(car, scene.front_car);
  m.rear_gap_m = geometry::distance(car, scene.rear_car);
  m.ideal_gap_m = scene.idealGapM();
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& p : car.corners()) lowest = std::min(lowest, p.y());
  m.curb_gap_m = lowest - scene.curb_y_m;
  m.yaw_error_deg = geometry::wrapLineAngle(yaw_rad - scene.ideal_yaw_rad) * 180.0 / M_PI;
  m.position_error_m = std::hypot(x_m - scene.ideal_x_m, y_m - scene.ideal_y_m);
  const double slot_from = scene.rear_car.centre.x_m + scene.rear_car.length_m / 2;
  const double slot_to = scene.front_car.centre.x_m - scene.front_car.length_m / 2;
  const double lane_half_width = std::max(scene.rear_car.width_m, scene.front_car.width_m) / 2;
  m.inside_slot = x_m > slot_from && x_m < slot_to && std::abs(y_m - scene.ideal_y_m) < lane_half_width &&
                  std::abs(m.yaw_error_deg) < 45.0;
  return m;
}

double contactDepthM(const ParkingScene& scene, double x_m, double y_m, double yaw_rad) {
  const OrientedBox car{{x_m, y_m, yaw_rad}, scene.car_length_m, scene.car_width_m};
  double deepest = 0;
  for (const auto& parked : scene.parked_cars) deepest = std::max(deepest, geometry::penetration(car, parked));
  for (const auto& p : car.corners()) {
    deepest = std::max({deepest, scene.curb_y_m - p.y(), p.y() - scene.far_curb_y_m});
  }
  return deepest;
}

bool offStreet(const ParkingScene& scene, double x_m, double y_m) {
  return x_m < scene.street_west_x_m || x_m > scene.street_east_x_m || y_m < scene.curb_y_m || y_m > scene.far_curb_y_m;
}

bool parkedElsewhere(const ParkingScene& scene, const ParkingMeasures& m, double y_m) {
  const double lane_half_width = std::max(scene.rear_car.width_m, scene.front_car.width_m) / 2;
  return !m.inside_slot && std::abs(y_m - scene.ideal_y_m) < lane_half_width && std::abs(m.yaw_error_deg) < 45.0;
}

}  // namespace aula::autopark
