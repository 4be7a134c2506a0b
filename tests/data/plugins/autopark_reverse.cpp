// An Autopark algorithm that reverses into the slot, for the test that one API serves two
// languages: its Python port (tests/data/python/autopark_reverse/MyAlgorithm.py) must earn the
// same report, byte for byte but the algorithm's name. For a car that turns in place
// (autopark.world): along the lane, the right laser's side beam finds a parked car, the gap, and
// the next car; past the gap it reverses in two arcs of 5 m (right, then left until parallel)
// and centres between the cars with the front and rear lasers. No random draw. Keep the two in
// step, line by line.
#include <aula/autopark/autopark_algorithm.hpp>

#include <algorithm>
#include <cmath>

namespace aula::autopark {
namespace {

const double kRadiusM = 5.0, kLaneY = 0.0, kCarNearM = 2.6, kCurbMarginM = 0.3;

double sideRange(const component::LaserData& scan) { return scan.values_m[scan.numLaser / 2]; }

class Reverse : public AutoparkAlgorithm {
 public:
  void execute(AutoparkApi& api) override {
    const component::LaserData& right = api.laser3.getLaserData();
    if (right.numLaser == 0 || api.laser1.getLaserData().numLaser == 0 || api.laser2.getLaserData().numLaser == 0) {
      return;
    }
    const double x = api.pose3d.getX(), y = api.pose3d.getY(), yaw = api.pose3d.getYaw();
    const double side_m = sideRange(right), laser_x = x + api.mount3.x_m;
    double v = 0.0, w = 0.0;
    if (phase_ == 0) {  // along the lane: a car, the gap, the next car
      v = 1.5;
      w = std::clamp(-0.5 * (y - kLaneY) - 1.5 * yaw, -0.3, 0.3);
      if (side_m < kCarNearM) {
        goal_y_ = y + api.mount3.y_m - side_m - api.car_width_m / 2 + kCurbMarginM;
        if (gap_start_x_ > -1e9 && laser_x - gap_start_x_ > api.car_length_m + 1.5) {
          gap_end_x_ = laser_x;
          phase_ = 1;
          api.status = "slot found";
        }
        seen_car_ = true;
        gap_start_x_ = -1e10;
      } else if (seen_car_ && gap_start_x_ < -1e9) {
        gap_start_x_ = laser_x;
      }
    } else if (phase_ == 1) {  // on until the arcs' start
      v = 1.0;
      w = std::clamp(-0.5 * (y - kLaneY) - 1.5 * yaw, -0.3, 0.3);
      if (x >= gap_end_x_ + 1.6) phase_ = 2;
    } else if (phase_ == 2) {  // reverse, the rear swinging right
      v = -0.8;
      w = 0.8 / kRadiusM;
      if (y - goal_y_ <= kRadiusM * (1 - std::cos(yaw))) phase_ = 3;
    } else if (phase_ == 3) {  // reverse, straightening
      v = -0.8;
      w = -0.8 / kRadiusM;
      if (yaw <= 0.0) phase_ = 4;
    } else if (phase_ == 4) {  // centre between the cars
      const double error = (sideRange(api.laser1.getLaserData()) - sideRange(api.laser2.getLaserData())) / 2;
      if (std::abs(error) < 0.1) {
        phase_ = 5;
        api.status = "parked";
      } else {
        v = std::clamp(0.8 * error, -0.5, 0.5);
        w = -yaw;
      }
    }
    api.motors.sendV(v);
    api.motors.sendW(w);
  }

 private:
  int phase_ = 0;
  bool seen_car_ = false;
  double gap_start_x_ = -1e10, gap_end_x_ = 0.0, goal_y_ = 0.0;
};

}  // namespace

std::unique_ptr<AutoparkAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<Reverse>(); }

}  // namespace aula::autopark
