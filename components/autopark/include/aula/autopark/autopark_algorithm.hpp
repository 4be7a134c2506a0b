#pragma once
// What the Autopark student writes: execute(), every control period of simulated time, with the
// car's pose, its three lasers and its motors (the original's API).

#include <aula/component/devices.hpp>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

namespace aula::autopark {

/// Where a laser sits on the car: body frame (x forward, y left), metres and radians.
struct LaserMount {
  double x_m = 0, y_m = 0, yaw_rad = 0;  ///< metres, metres, radians (0: facing forward, CCW)
};

// Calls echo(x_m, y_m) with the world position of every beam of `scan` that hit something
// (beams at max range have no echo), for a laser at `mount` on a car at (x, y, yaw).
template <class Echo>
void forEachEcho(double car_x_m, double car_y_m, double car_yaw_rad, const LaserMount& mount,
                 const component::LaserData& scan, Echo echo) {
  const double c = std::cos(car_yaw_rad), s = std::sin(car_yaw_rad);
  const double lx = car_x_m + c * mount.x_m - s * mount.y_m;
  const double ly = car_y_m + s * mount.x_m + c * mount.y_m;
  for (int i = 0; i < scan.numLaser && i < static_cast<int>(scan.values_m.size()); ++i) {
    const double r = scan.values_m[i];
    if (!(r > scan.minRange) || r >= scan.maxRange - 0.05) continue;  // no echo
    const double a = car_yaw_rad + mount.yaw_rad + scan.angle(i);
    echo(lx + r * std::cos(a), ly + r * std::sin(a));
  }
}

// Calls miss(x_m, y_m) at points every step_m along each beam of `scan` that had no echo (it
// read max range, or inf): the path it proves free, from the laser to its max range.
template <class Miss>
void forEachMissPoint(double car_x_m, double car_y_m, double car_yaw_rad, const LaserMount& mount,
                      const component::LaserData& scan, double step_m, Miss miss) {
  const double c = std::cos(car_yaw_rad), s = std::sin(car_yaw_rad);
  const double lx = car_x_m + c * mount.x_m - s * mount.y_m;
  const double ly = car_y_m + s * mount.x_m + c * mount.y_m;
  for (int i = 0; i < scan.numLaser && i < static_cast<int>(scan.values_m.size()); ++i) {
    const double r = scan.values_m[i];
    if (r < scan.maxRange - 0.05) continue;  // an echo (or a reading below min range)
    const double a = car_yaw_rad + mount.yaw_rad + scan.angle(i);
    for (double d = step_m; d < scan.maxRange - 0.05; d += step_m) miss(lx + d * std::cos(a), ly + d * std::sin(a));
  }
}

struct AutoparkApi {
  component::Pose3d& pose3d;  ///< getX(), getY(), getYaw(): the car's centre in the world frame, metres, radians
  component::Laser& laser1;   ///< front: 180 beams over -90..90 degrees of its mount, metres and mm
  component::Laser& laser2;   ///< rear: the same, mounted backwards
  component::Laser& laser3;   ///< right: the same, mounted facing right
  component::Motors& motors;  ///< sendV() m/s, sendW() rad/s, clamped to Autopark.MaxV / Autopark.MaxW
  double period_s;            ///< sim seconds between execute() calls (> 0)
  LaserMount mount1, mount2, mount3;  ///< the lasers' mounting poses, body frame (from the world)
  double car_length_m = 4.0, car_width_m = 2.0;  ///< the car's footprint, metres
  /// Turning radius the car needs, m: 0 for a car that turns in place ("diff"), else |w| <= |v| / R.
  double min_turn_radius_m = 0.0;
  /// Body-frame x of the point the car turns about, m: 0 (its centre) for a car that turns in place,
  /// its rear axle (about -1.3 m) for a car-like one. That point moves on circles of radius v / w.
  double turn_centre_x_m = 0.0;
  double wheelbase_m = 2.6;  ///< metres, for drawing the wheels
  /// What the algorithm says about where it stands ("slot too short for a reactive park: 5.0 m,
  /// need 5.9 m"): the window shows it under the car's numbers.
  std::string status{};
  component::SimClock clock{};  ///< the sim time of this period (the component sets it)

  /// Sim time of this control period, seconds since the simulation started.
  double time_s() const { return clock.time_s(); }
};

class AutoparkAlgorithm {
 public:
  virtual ~AutoparkAlgorithm() = default;
  /** Every control period of sim time (api.period_s): read the pose and lasers, send the motors. */ virtual void execute(AutoparkApi& api) = 0;
};

std::unique_ptr<AutoparkAlgorithm> makeStudentAlgorithm(uint64_t seed);

}  // namespace aula::autopark
