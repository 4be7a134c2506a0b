#pragma once
// What the vacuum cleaner student writes: execute(), every control period of simulated time.
// There is no localization in this exercise: the API gives the yaw, the laser, the bumper and
// the motors, and nothing that tells where the robot is.

#include <aula/component/devices.hpp>

#include <cstdint>
#include <memory>
#include <string>

namespace aula::vacuum {

/// The only part of the pose the student gets: the heading.
class YawSensor {
 public:
  explicit YawSensor(const component::Pose3d& pose) : pose_(pose) {}
  /** heading, radians, counter-clockwise from the world's +x, in (-pi, pi] */ double getYaw() const { return pose_.getYaw(); }

 private:
  const component::Pose3d& pose_;
};
/// What execute() reads and writes, this control period.
struct VacuumApi {
  YawSensor& pose3d;           ///< getYaw(): the heading, rad (no position: this exercise has no localization)
  component::Laser& laser;     ///< getLaserData(): 180 beams over -90..90 degrees (beam 0 on the right), m and mm
  component::Bumper& bumper;   ///< getBumperData().state == 1 when pressed
  component::Motors& motors;   ///< sendV() m/s, sendW() rad/s, clamped to Vacuum.MaxV / Vacuum.MaxW
  component::Belief& belief;   ///< setPose(), setMap(): what the algorithm believes, shown, never graded
  double period_s;             ///< the control period: sim seconds between execute() calls (> 0)
  component::SimClock clock{};  ///< the sim time of this period (the component sets it)

  /// Sim time of this control period, seconds since the simulation started.
  double time_s() const { return clock.time_s(); }
};
/// The student's algorithm: MyAlgorithm derives from it.
class VacuumAlgorithm {
 public:
  virtual ~VacuumAlgorithm() = default;
  /** Called every control period of sim time (api.period_s): read the sensors, send the motors. */ virtual void execute(VacuumApi& api) = 0;
};

/// seed: the run's seed (aula run --seed), for algorithms that draw random turns.
std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t seed);

}  // namespace aula::vacuum
