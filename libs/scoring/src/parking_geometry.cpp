#include "aula/scoring/parking_geometry.hpp"

#include <aula/geometry/angles.hpp>
#include <aula/geometry/oriented_box.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace aula::autopark {
namespace {

double cross(Point2 o, Point2 a, Point2 b) { return (a.x_m - o.x_m) * (b.y_m - o.y_m) - (a.y_m - o.y_m) * (b.x_m - o.x_m); }

double pointSegment(Point2 p, Point2 a, Point2 b) {
  const double dx = b.x_m - a.x_m, dy = b.y_m - a.y_m;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x_m - a.x_m) * dx + (p.y_m - a.y_m) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x_m - (a.x_m + t * dx), p.y_m - (a.y_m + t * dy));
}

bool insideConvex(Point2 p, const std::array<Point2, 4>& poly) {
  for (int i = 0; i < 4; ++i) {
    if (cross(poly[i], poly[(i + 1) % 4], p) < 0) return false;
  }
  return true;
}

bool segmentsCross(Point2 a, Point2 b, Point2 c, Point2 d) {
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

}  // namespace

std::array<Point2, 4> Rect2D::corners() const {
  const auto box = geometry::orientedBoxCorners(cx_m, cy_m, yaw_rad, length_m, width_m);
  std::array<Point2, 4> out;
  for (size_t i = 0; i < 4; ++i) out[i] = Point2{box[i].x(), box[i].y()};
  return out;
}

bool rectsOverlap(const Rect2D& a, const Rect2D& b) {
  const auto ca = a.corners(), cb = b.corners();
  for (const auto& p : ca) if (insideConvex(p, cb)) return true;
  for (const auto& p : cb) if (insideConvex(p, ca)) return true;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (segmentsCross(ca[i], ca[(i + 1) % 4], cb[j], cb[(j + 1) % 4])) return true;
  return false;
}

double rectDistance(const Rect2D& a, const Rect2D& b) {
  if (rectsOverlap(a, b)) return 0.0;
  // Disjoint convex polygons: the closest pair involves a vertex of one and an edge of the other.
  const auto ca = a.corners(), cb = b.corners();
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      best = std::min(best, pointSegment(ca[i], cb[j], cb[(j + 1) % 4]));
      best = std::min(best, pointSegment(cb[j], ca[i], ca[(i + 1) % 4]));
    }
  }
  return best;
}

double ParkingScene::slotLengthM() const {
  return (front_car.cx_m - front_car.length_m / 2) - (rear_car.cx_m + rear_car.length_m / 2);
}

ParkingScene ParkingScene::fromWorld(const world::WorldSpec& world, const std::string& robot_name) {
  const std::string where = world.source_path.empty() ? world.name : world.source_path;
  std::vector<Rect2D> parked;
  bool have_curb = false;
  ParkingScene scene;
  for (const auto& s : world.statics) {
    if (s.shape.kind != world::ShapeKind::Box) continue;
    const double yaw = world::yawOf(s.pose);
    if (s.name.rfind("parked_car", 0) == 0) {
      parked.push_back(Rect2D{s.pose.translation().x(), s.pose.translation().y(), yaw, s.shape.box_size_m.x(), s.shape.box_size_m.y()});
    } else if (s.name.find("curb_parking_side") != std::string::npos) {
      scene.curb_y_m = s.pose.translation().y() + s.shape.box_size_m.y() / 2;
      have_curb = true;
    }
  }
  if (!have_curb) throw world::WorldError(where + ": no collision named curb_parking_side (the parking-side curb)");
  if (parked.size() < 2) throw world::WorldError(where + ": needs at least two static models named parked_car*");
  std::sort(parked.begin(), parked.end(), [](const Rect2D& a, const Rect2D& b) { return a.cx_m < b.cx_m; });
  double widest = -1;
  for (size_t i = 0; i + 1 < parked.size(); ++i) {
    const double gap = (parked[i + 1].cx_m - parked[i + 1].length_m / 2) - (parked[i].cx_m + parked[i].length_m / 2);
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
  scene.ideal_x_m = (scene.rear_car.cx_m + scene.rear_car.length_m / 2 + scene.front_car.cx_m - scene.front_car.length_m / 2) / 2;
  scene.ideal_y_m = (scene.rear_car.cy_m + scene.front_car.cy_m) / 2;
  scene.ideal_yaw_rad = 0.0;
  return scene;
}

ParkingMeasures measureParking(const ParkingScene& scene, double x_m, double y_m, double yaw_rad) {
  const Rect2D car{x_m, y_m, yaw_rad, scene.car_length_m, scene.car_width_m};
  ParkingMeasures m;
  m.front_gap_m = rectDistance(car, scene.front_car);
  m.rear_gap_m = rectDistance(car, scene.rear_car);
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& p : car.corners()) lowest = std::min(lowest, p.y_m);
  m.curb_gap_m = lowest - scene.curb_y_m;
  m.yaw_error_deg = geometry::wrapLineAngle(yaw_rad - scene.ideal_yaw_rad) * 180.0 / M_PI;
  m.position_error_m = std::hypot(x_m - scene.ideal_x_m, y_m - scene.ideal_y_m);
  const double slot_from = scene.rear_car.cx_m + scene.rear_car.length_m / 2;
  const double slot_to = scene.front_car.cx_m - scene.front_car.length_m / 2;
  const double lane_half_width = std::max(scene.rear_car.width_m, scene.front_car.width_m) / 2;
  m.inside_slot = x_m > slot_from && x_m < slot_to && std::abs(y_m - scene.ideal_y_m) < lane_half_width &&
                  std::abs(m.yaw_error_deg) < 45.0;
  return m;
}

}  // namespace aula::autopark
