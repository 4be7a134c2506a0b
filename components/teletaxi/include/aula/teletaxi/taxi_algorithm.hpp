#pragma once
// What the TeleTaxi student writes: one class with generatePath() (runs once, on
// "Generate Path") and execute() (runs every control period of sim time after "GO!").
// The API mirrors the original exercise: sensor/pose3d, vel/motors and the Grid.

#include <aula/component/devices.hpp>
#include <aula/teletaxi/grid.hpp>

#include <memory>
#include <string>

namespace aula::teletaxi {

struct TaxiApi {
  component::Pose3d& pose3d;  ///< getX/getY m, getYaw rad: the taxi in the world frame (or getRobotX/getRobotY/getRobotTheta)
  component::Motors& motors;  ///< sendV m/s, sendW rad/s, or setV/setW (clamped to TeleTaxi.MaxV / TeleTaxi.MaxW)
  Grid& grid;                 ///< the city's map, its destination and the path (grid.hpp)
  // The original names of pose3d and motors.
  component::Pose3d& sensor;  ///< the same as pose3d (the original's name)
  component::Motors& vel;     ///< the same as motors (the original's name)
  component::SimClock clock{};  ///< the sim time of this call (the component sets it)

  /// Sim time of this call, seconds since the simulation started.
  double time_s() const { return clock.time_s(); }

  TaxiApi(component::Pose3d& p, component::Motors& m, Grid& g)
      : pose3d(p), motors(m), grid(g), sensor(p), vel(m) {}
};

class TaxiAlgorithm {
 public:
  virtual ~TaxiAlgorithm() = default;
  /** Once, on "Generate Path": fill the grid's path to the destination. */ virtual void generatePath(TaxiApi& api) = 0;
  /** Every control period of sim time after "GO!": drive along the path. */ virtual void execute(TaxiApi& api) = 0;
};

/// The student's algorithm (student/MyAlgorithm.cpp; the reference is not part of the API).
std::unique_ptr<TaxiAlgorithm> makeStudentAlgorithm();

}  // namespace aula::teletaxi
