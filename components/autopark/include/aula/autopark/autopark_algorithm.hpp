#pragma once
// What the Autopark student writes: execute(), every control period of simulated time, with the
// car's pose, its three lasers and its motors (the original's API).

#include <aula/component/proxies.hpp>

#include <cstdint>
#include <memory>

namespace aula::autopark {

// Where a laser sits on the car: body frame (x forward, y left), metres and radians.
struct LaserMount {
  double x_m = 0, y_m = 0, yaw_rad = 0;
};

struct AutoparkApi {
  component::Pose3dProxy& pose3d;  // getX(), getY(), getYaw(): the car's centre, metres, radians
  component::LaserProxy& laser1;   // front: 180 beams over -90..90 degrees, metres and mm
  component::LaserProxy& laser2;   // rear
  component::LaserProxy& laser3;   // right
  component::MotorsProxy& motors;  // sendV(), sendW(), clamped to MaxV / MaxW
  double period_s;                 // sim seconds between execute() calls
  LaserMount mount1, mount2, mount3;  // the lasers' mounting poses (from the world)
  double car_length_m = 4.0, car_width_m = 2.0;
  // Turning radius the car needs: 0 for a car that turns in place ("diff"), else |w| <= |v| / R.
  double min_turn_radius_m = 0.0;
  // Body-frame x of the point the car turns about: 0 (its centre) for a car that turns in place,
  // its rear axle (about -1.3 m) for a car-like one. That point moves on circles of radius v / w.
  double turn_centre_x_m = 0.0;
  double wheelbase_m = 2.6;  // for drawing the wheels
};

class AutoparkAlgorithm {
 public:
  virtual ~AutoparkAlgorithm() = default;
  virtual void execute(AutoparkApi& api) = 0;
};

std::unique_ptr<AutoparkAlgorithm> makeStudentAlgorithm(uint64_t seed);
// The thesis's reactive solution: find the slot, stop alongside the car ahead, reverse in two arcs, centre.
std::unique_ptr<AutoparkAlgorithm> makeReactiveAlgorithm(uint64_t seed);
// Maps the street from the lasers, plans a Reeds-Shepp path into the slot (OMPL), tracks it.
std::unique_ptr<AutoparkAlgorithm> makePlannedAlgorithm(uint64_t seed);

}  // namespace aula::autopark
