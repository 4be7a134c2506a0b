// ============================================================================================
//  Vacuum cleaner: YOUR algorithm goes here. Clean as much of the house as you can in 900 s.
//
//  execute(api) runs every control period (api.period_s, 80 ms of simulated time):
//      api.pose3d.getYaw()                  heading, radians (there is no x, y: no localization!)
//      api.laser.getLaserData()             .values_m (metres) / .distanceData (mm), 180 beams,
//                                           beam i at .angle(i), from -pi/2 (right) to +pi/2 (left)
//      api.bumper.getBumperData().state     1 while the bumper is pressed
//      api.motors.sendV(v_mps), sendW(w_radps)   clamped to MaxV / MaxW of the .cfg
//      api.time_s()                         sim time of this period, seconds (time your moves with it)
//
//  Ideas from real Roombas: an outward spiral, following walls, crossing rooms with random
//  turns, escaping from corners. Until you write something, this template stays still.
// ============================================================================================
#include <aula/vacuum/vacuum_algorithm.hpp>

namespace aula::vacuum {
namespace {

class MyAlgorithm : public VacuumAlgorithm {
 public:
  void execute(VacuumApi& api) override {
    // TODO: your cleaning strategy.
    api.motors.sendV(0.0);
    api.motors.sendW(0.0);
  }
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<MyAlgorithm>(); }

}  // namespace aula::vacuum
