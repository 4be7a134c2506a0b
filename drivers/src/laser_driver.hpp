#pragma once
// laser: a planar range finder (aula::laser_t), like JdeRobot's Laser.
// Parameters (units in names):
//   channel        required
//   pose           "x y z roll pitch yaw" of the sensor in the robot body frame
//   samples        beams, default 180
//   min_angle, max_angle   rad, default -pi/2 .. pi/2; beams span them inclusive:
//                  increment = (max - min) / (samples - 1)
//   min_range, max_range   m, default 0.08 .. 10; no hit -> max_range, closer than min -> min_range
//   rate_hz        default 20
//   noise_stddev   m, default 0: seeded Gaussian noise on hits (the run's Simulator.Noise.LaserStddev
//                  when larger; Simulator.Noise.LaserDropout: beams with no echo read max_range)
// Rays are cast analytically against the static geometry cut at the sensor's height and against
// the other robots' footprints.

#include "aula/drivers/driver.hpp"
#include "periodic.hpp"

#include <aula/geometry/raycaster2d.hpp>
#include <aula/laser_t.hpp>

#include <random>

namespace aula::drivers {

class LaserDriver : public Driver {
 public:
  void attach(DriverContext& context, int robot, const world::PluginSpec& plugin) override;
  void step(int64_t sim_time_us) override;
  void reset() override { schedule_.reset(); }

  // One scan at the robot's current pose (also used by tests).
  void scan(aula::laser_t& out);

 private:
  DriverContext* context_ = nullptr;
  const geometry::Raycaster2D* raycaster_ = nullptr;
  int robot_ = -1;
  std::string channel_;
  Eigen::Isometry3d mount_ = Eigen::Isometry3d::Identity();
  double mount_yaw_rad_ = 0.0;
  geometry::ScanRequest request_;
  double noise_stddev_m_ = 0.0;
  double dropout_ = 0.0;  // the run's Simulator.Noise.LaserDropout
  std::mt19937_64 rng_;
  Periodic schedule_;
  aula::laser_t message_;
  geometry::Obstacles2D others_;
};

}  // namespace aula::drivers
