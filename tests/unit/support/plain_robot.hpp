#pragma once
// A robot of a shipped world on plain data, for unit-testing the reference algorithms without
// LCM, DART or any process (the way Nav2 tests its controllers): the world's static geometry
// sliced at the lasers' height, the robot's lasers (mounts, beams, ranges from its plugins)
// ray-cast with the simulator's own caster, planar kinematics (turning about the centre, or about
// the rear axle with |w| <= |v| / R for a car-like robot), and contact as overlap with the
// statics. A move that would overlap is not made: the robot stops against the obstacle, its
// bumper pressed, and the contact is counted. The algorithm sees only the plain devices
// (component/devices.hpp).

#include <aula/component/devices.hpp>
#include <aula/geometry/oriented_box.hpp>
#include <aula/geometry/raycaster2d.hpp>
#include <aula/world/car_kinematics.hpp>
#include <aula/world/obstacle_slice.hpp>
#include <aula/world/world_spec.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace aula::test {

class PlainRobot {
 public:
  // `world`: a file under worlds/; `robot`: its model name; `max_v`, `max_w`: the motors' limits.
  PlainRobot(const std::string& world, const std::string& robot, double max_v_mps, double max_w_radps)
      : motors(max_v_mps, max_w_radps),
        world_(world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/" + world)),
        spec_(world::requireRobot(world_, robot)) {
    x_m_ = spec_.pose.translation().x();
    y_m_ = spec_.pose.translation().y();
    yaw_rad_ = world::yawOf(spec_.pose);
    for (const world::PluginSpec& p : spec_.plugins) {
      if (p.type == "laser") lasers_.push_back(p);
    }
    if (const world::PluginSpec* m = spec_.findPlugin("motors")) kinematics_ = world::readCarKinematics(*m);
    const double laser_z_m = lasers_.empty() ? 0.1 : lasers_.front().getPose("pose").translation().z();
    obstacles_ = world::sliceAtHeight(world_, laser_z_m);
    caster_ = geometry::Raycaster2D(obstacles_);
    laser_data_.resize(lasers_.size());
    sense(0);
  }

  const world::RobotSpec& spec() const { return spec_; }
  const world::CarKinematics& kinematics() const { return kinematics_; }
  // The laser plugin named `name` (Autopark's laser_front...), or the robot's only one ("").
  component::Laser& laser(const std::string& name = "") { return laser_data_[laserIndex(name)]; }

  // Moves for `dt_s` at the motors' command (5 ms steps), then updates the sensors.
  void step(double dt_s, int64_t utime_after) {
    const int substeps = std::max(1, static_cast<int>(std::lround(dt_s / 0.005)));
    const double h = dt_s / substeps;
    double v = motors.getV(), w = motors.getW();
    if (kinematics_.ackermann && kinematics_.min_turn_radius_m > 0) {
      const double w_max = std::abs(v) / kinematics_.min_turn_radius_m;  // as the motors driver clamps
      w = std::clamp(w, -w_max, w_max);
    }
    pressed_ = false;
    for (int i = 0; i < substeps; ++i) {
      // The turning point (rear axle or centre) moves on a circle of radius v / w.
      const double c = kinematics_.rear_axle_x_m;
      double px = x_m_ + c * std::cos(yaw_rad_), py = y_m_ + c * std::sin(yaw_rad_);
      px += v * std::cos(yaw_rad_ + w * h / 2) * h;
      py += v * std::sin(yaw_rad_ + w * h / 2) * h;
      const double yaw = yaw_rad_ + w * h;
      const double x = px - c * std::cos(yaw), y = py - c * std::sin(yaw);
      if (touches(x, y, yaw)) {
        if (!in_contact_) ++contacts_;
        in_contact_ = pressed_ = true;
        break;
      }
      in_contact_ = false;
      x_m_ = x;
      y_m_ = y;
      yaw_rad_ = yaw;
    }
    sense(utime_after);
  }

  // Puts the robot at a pose (not moved there: no contact check) and senses from it, for tests
  // of what the sensors see from a chosen spot.
  void place(double x_m, double y_m, double yaw_rad) {
    x_m_ = x_m;
    y_m_ = y_m;
    yaw_rad_ = yaw_rad;
    sense(0);
  }

  bool touches(double x_m, double y_m, double yaw_rad) const {
    if (spec_.shape.kind == world::ShapeKind::Cylinder) {
      const double r = spec_.shape.radius_m;
      for (const auto& box : obstacles_.rects) {
        if (pointBoxDistance(box, x_m, y_m) < r) return true;
      }
      for (const auto& circle : obstacles_.circles) {
        if (std::hypot(circle.center_m.x() - x_m, circle.center_m.y() - y_m) < r + circle.radius_m) return true;
      }
      return false;
    }
    const geometry::OrientedBox body{{x_m, y_m, yaw_rad}, spec_.shape.box_size_m.x(), spec_.shape.box_size_m.y()};
    for (const auto& box : obstacles_.rects) {
      if (geometry::overlap(body, box)) return true;
    }
    return false;
  }

  double x() const { return x_m_; }
  double y() const { return y_m_; }
  double yaw() const { return yaw_rad_; }
  int contacts() const { return contacts_; }  // times the robot ran into something
  bool pressed() const { return pressed_; }

  component::Pose3d pose;
  component::Bumper bumper;
  component::Motors motors;

 private:
  static double pointBoxDistance(const geometry::OrientedBox& b, double x_m, double y_m) {
    const double c = std::cos(b.centre.yaw_rad), s = std::sin(b.centre.yaw_rad);
    const double dx = x_m - b.centre.x_m, dy = y_m - b.centre.y_m;
    const double lx = std::abs(c * dx + s * dy) - b.length_m / 2, ly = std::abs(-s * dx + c * dy) - b.width_m / 2;
    return std::hypot(std::max(lx, 0.0), std::max(ly, 0.0));
  }

  size_t laserIndex(const std::string& name) const {
    for (size_t i = 0; i < lasers_.size(); ++i) {
      if (name.empty() || lasers_[i].name == name) return i;
    }
    throw std::out_of_range("no laser '" + name + "' on " + spec_.name);
  }

  void sense(int64_t utime) {
    pose.set(x_m_, y_m_, yaw_rad_, utime);
    bumper.set({1, pressed_ ? 1 : 0, utime});
    for (size_t i = 0; i < lasers_.size(); ++i) {
      const world::PluginSpec& p = lasers_[i];
      const Eigen::Isometry3d mount = p.getPose("pose");
      component::LaserData d;
      d.numLaser = p.getInt("samples", 180);
      d.minAngle = p.getDouble("min_angle", -M_PI / 2);
      d.maxAngle = p.getDouble("max_angle", M_PI / 2);
      d.angleIncrement = (d.maxAngle - d.minAngle) / std::max(1, d.numLaser - 1);
      d.minRange = p.getDouble("min_range", 0.08);
      d.maxRange = p.getDouble("max_range", 10);
      d.timeStamp = utime;
      d.values_m.resize(d.numLaser);
      geometry::ScanRequest r;
      const double mx = mount.translation().x(), my = mount.translation().y();
      r.origin_m = {x_m_ + std::cos(yaw_rad_) * mx - std::sin(yaw_rad_) * my,
                    y_m_ + std::sin(yaw_rad_) * mx + std::cos(yaw_rad_) * my};
      r.yaw_rad = yaw_rad_ + world::yawOf(mount);
      r.min_angle_rad = d.minAngle;
      r.angle_increment_rad = d.angleIncrement;
      r.num_beams = d.numLaser;
      r.min_range_m = d.minRange;
      r.max_range_m = d.maxRange;
      caster_.scan(r, d.values_m.data());
      laser_data_[i].set(std::move(d));
    }
  }

  world::WorldSpec world_;
  world::RobotSpec spec_;
  world::CarKinematics kinematics_;
  std::vector<world::PluginSpec> lasers_;
  std::vector<component::Laser> laser_data_;
  geometry::Obstacles2D obstacles_;
  geometry::Raycaster2D caster_;
  double x_m_ = 0, y_m_ = 0, yaw_rad_ = 0;
  int contacts_ = 0;
  bool in_contact_ = false, pressed_ = false;
};

}  // namespace aula::test
