#include "aula/scoring/parking_geometry.hpp"

#include <aula/geometry/angles.hpp>
#include <aula/geometry/oriented_box.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace aula::scoring {

using geometry::OrientedBox;

double ParkingScene::slotLengthM() const {
  return (front_car.centre.x_m - front_car.length_m / 2) - (rear_car.centre.x_m + rear_car.length_m / 2);
}

double ParkingScene::idealGapM() const { return (slotLengthM() - car_length_m) / 2; }

namespace {

using world::footprintOf;

// A static the street is made of: a box, or a mesh standing above the ground (an RA car mesh).
bool streetPart(const world::StaticObject& s) {
  if (s.shape.kind == world::ShapeKind::Box) return true;
  return s.shape.kind == world::ShapeKind::Mesh && s.shape.zRange(s.pose).second >= 0.01;
}

double lowestY(const world::StaticObject& s) {
  double y = std::numeric_limits<double>::infinity();
  for (const auto& p : footprintOf(s).corners()) y = std::min(y, p.y());
  return y;
}

double highestY(const world::StaticObject& s) {
  double y = -std::numeric_limits<double>::infinity();
  for (const auto& p : footprintOf(s).corners()) y = std::max(y, p.y());
  return y;
}

// The same rectangle with its length the side nearer the street's x axis: a car mesh whose own
// axes run across, turned 1.57 rad in the file (RoboticsAcademy's opel), is 4.9 m long along x.
OrientedBox lengthAlongX(OrientedBox box) {
  if (std::abs(std::sin(box.centre.yaw_rad)) > std::abs(std::cos(box.centre.yaw_rad))) {
    std::swap(box.length_m, box.width_m);
    box.centre.yaw_rad = geometry::wrapAngle(box.centre.yaw_rad - M_PI / 2);
  }
  return box;
}

// How far a street with no curb runs past its first and last parked cars.
constexpr double kStreetEndM = 10.0;

// A curb: a box along the street (x), at least three times as long as wide.
bool alongTheStreet(const world::StaticObject& s) {
  const OrientedBox f = footprintOf(s);
  return std::abs(std::sin(f.centre.yaw_rad)) < 0.05 && f.length_m >= 3 * f.width_m;
}

bool named(const std::string& full, const std::string& name) {
  return full == name || (full.size() > name.size() + 2 && full.compare(full.size() - name.size() - 2, std::string::npos, "::" + name) == 0);
}

// The parking-side curb (see fromWorld), or nullptr; also the far curb when there is one.
const world::StaticObject* findCurbs(const world::WorldSpec& world, double start_y_m, const std::string& curb_name,
                                     const world::StaticObject*& far_curb) {
  const world::StaticObject* curb = nullptr;
  for (const auto& s : world.statics) {
    if (!streetPart(s)) continue;
    if (!curb_name.empty()) {
      if (named(s.name, curb_name)) curb = &s;
    } else if (alongTheStreet(s) && highestY(s) < start_y_m && (curb == nullptr || highestY(s) > highestY(*curb))) {
      curb = &s;
    }
    if (alongTheStreet(s) && lowestY(s) > start_y_m && (far_curb == nullptr || lowestY(s) < lowestY(*far_curb))) {
      far_curb = &s;
    }
  }
  return curb;
}

}  // namespace

ParkingScene ParkingScene::fromWorld(const world::WorldSpec& world, const std::string& robot_name, const SceneNames& names) {
  const std::string where = world.source_path.empty() ? world.name : world.source_path;
  const world::RobotSpec* car = world.findRobot(robot_name);
  if (car == nullptr) throw world::WorldError(where + ": no robot named '" + robot_name + "'");
  if (car->shape.kind != world::ShapeKind::Box) throw world::WorldError(where + ": robot '" + robot_name + "' must be a box");
  const double start_y = car->pose.translation().y();
  ParkingScene scene;
  const world::StaticObject* far_curb = nullptr;
  const world::StaticObject* curb = findCurbs(world, start_y, names.curb, far_curb);
  if (curb == nullptr && !names.curb.empty()) {
    throw world::WorldError(where + ": no box collision named '" + names.curb + "' (Autopark.Referee.Curb)");
  }
  if (curb != nullptr) {
    scene.curb_name = curb->name;
    scene.curb_y_m = highestY(*curb);
    scene.street_west_x_m = footprintOf(*curb).centre.x_m - footprintOf(*curb).length_m / 2;
    scene.street_east_x_m = footprintOf(*curb).centre.x_m + footprintOf(*curb).length_m / 2;
  } else {
    scene.curb_y_m = -std::numeric_limits<double>::infinity();  // no curb (RoboticsAcademy's street): set below
  }
  if (far_curb != nullptr) scene.far_curb_y_m = lowestY(*far_curb);
  std::vector<OrientedBox> parked;
  double outer_y = std::numeric_limits<double>::infinity();  // the parked cars' far side
  for (const auto& s : world.statics) {
    if (!streetPart(s) || &s == curb) continue;
    const double x = footprintOf(s).centre.x_m;
    const bool between = !alongTheStreet(s) && lowestY(s) >= scene.curb_y_m - 0.05 && highestY(s) < start_y &&
                         x > scene.street_west_x_m && x < scene.street_east_x_m;
    if (names.car_prefix.empty() ? between : s.name.rfind(names.car_prefix, 0) == 0) {
      parked.push_back(lengthAlongX(footprintOf(s)));
      outer_y = std::min(outer_y, lowestY(s));
    }
  }
  if (curb == nullptr && !parked.empty()) {
    // With no curb, the parking line is the parked cars' far side (where the thesis's referee put the
    // curb of RoboticsAcademy's street), and the street is as long as its row of cars.
    scene.curb_y_m = outer_y;
    scene.street_west_x_m = std::min_element(parked.begin(), parked.end(), [](const auto& a, const auto& b) {
                              return a.centre.x_m < b.centre.x_m;
                            })->centre.x_m - kStreetEndM;
    scene.street_east_x_m = std::max_element(parked.begin(), parked.end(), [](const auto& a, const auto& b) {
                              return a.centre.x_m < b.centre.x_m;
                            })->centre.x_m + kStreetEndM;
  }
  if (parked.size() < 2) {
    throw world::WorldError(where + (names.car_prefix.empty()
                                         ? ": needs at least two parked cars (static boxes or meshes between the "
                                           "parking-side curb, if any, and the car's start; or name them with "
                                           "Autopark.Referee.CarPrefix)"
                                         : ": needs at least two static models named " + names.car_prefix +
                                               "* (Autopark.Referee.CarPrefix)"));
  }
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
  scene.car_length_m = car->shape.box_size_m.x();
  scene.car_width_m = car->shape.box_size_m.y();
  scene.ideal_x_m = (scene.rear_car.centre.x_m + scene.rear_car.length_m / 2 + scene.front_car.centre.x_m - scene.front_car.length_m / 2) / 2;
  scene.ideal_y_m = (scene.rear_car.centre.y_m + scene.front_car.centre.y_m) / 2;
  scene.ideal_yaw_rad = 0.0;
  return scene;
}

SceneNames sceneNamesOf(const config::Config& referee) {
  return {referee.getString("Autopark.Referee.Curb"), referee.getString("Autopark.Referee.CarPrefix")};
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
    deepest = std::max({deepest, scene.curb_name.empty() ? 0.0 : scene.curb_y_m - p.y(), p.y() - scene.far_curb_y_m});
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

}  // namespace aula::scoring
