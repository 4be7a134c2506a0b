// Your Autopark solution. execute() runs every Autopark.Period of simulated time.
//   api.pose3d.getX(), getY(), getYaw()   the car's centre (m) and heading (rad)
//   api.laser1 / laser2 / laser3          front, rear, right: getLaserData().values_m[i] (m) or
//                                         .distanceData[i] (mm), beam i at .angle(i) (rad, -90..90 deg)
//   api.mount1 / mount2 / mount3          where each laser sits on the car (x forward, y left)
//   api.motors.sendV(v), sendW(w)         m/s and rad/s (clamped to Autopark.MaxV / MaxW)
//   api.time_s()                          sim time of this period, seconds (time your moves with it)
// Find the free slot beside the curb between the parked cars and park in it, parallel to the
// curb. The reference solutions: `aula run autopark --algorithm=reactive` or `--algorithm=planner`.
#include <aula/autopark/autopark_algorithm.hpp>

namespace aula::autopark {
namespace {

class MyAlgorithm : public AutoparkAlgorithm {
 public:
  void execute(AutoparkApi& api) override {
    // Example: drive slowly along the street and stop when something is close ahead.
    const auto& front = api.laser1.getLaserData();
    if (front.numLaser == 0) return;
    const double straight_ahead_m = front.values_m[front.numLaser / 2];
    api.motors.sendV(straight_ahead_m > 3.0 ? 1.0 : 0.0);
    api.motors.sendW(0.0);
  }
};

}  // namespace

std::unique_ptr<AutoparkAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<MyAlgorithm>(); }

}  // namespace aula::autopark
