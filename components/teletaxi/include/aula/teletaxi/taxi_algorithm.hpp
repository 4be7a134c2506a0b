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
  component::Pose3d& pose3d;  // getX/getY/getYaw, or getRobotX/getRobotY/getRobotTheta
  component::Motors& motors;  // sendV/sendW, or setV/setW (clamped to MaxV/MaxW)
  Grid& grid;
  // The original names.
  component::Pose3d& sensor;
  component::Motors& vel;
  component::SimClock clock{};  // the sim time of this call (the component sets it)

  // Sim time of this call, seconds since the simulation started.
  double time_s() const { return clock.time_s(); }

  TaxiApi(component::Pose3d& p, component::Motors& m, Grid& g)
      : pose3d(p), motors(m), grid(g), sensor(p), vel(m) {}
};

class TaxiAlgorithm {
 public:
  virtual ~TaxiAlgorithm() = default;
  virtual void generatePath(TaxiApi& api) = 0;
  virtual void execute(TaxiApi& api) = 0;
};

// The student's algorithm (student/MyAlgorithm.cpp; the reference is not part of the API).
std::unique_ptr<TaxiAlgorithm> makeStudentAlgorithm();

}  // namespace aula::teletaxi
