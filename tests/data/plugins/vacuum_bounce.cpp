// A vacuum bounce with no random draw, for the test that one API serves two languages: its
// Python port (tests/data/python/vacuum_bounce/MyAlgorithm.py) must earn the same report, byte
// for byte but the algorithm's name. It reads every part of the API: the yaw, the laser in
// metres and in mm, a beam's angle, the bumper and the period. Keep the two in step, line by line.
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <algorithm>
#include <cmath>

namespace aula::vacuum {
namespace {

double wrap(double a) {
  while (a > M_PI) a -= 2 * M_PI;
  while (a < -M_PI) a += 2 * M_PI;
  return a;
}

class Bounce : public VacuumAlgorithm {
 public:
  void execute(VacuumApi& api) override {
    t_ += api.period_s;
    const double yaw = api.pose3d.getYaw();
    const component::LaserData& scan = api.laser.getLaserData();
    int front_mm = 100000;
    for (int i = 80; i < 100 && i < static_cast<int>(scan.distanceData.size()); ++i) {
      front_mm = std::min(front_mm, scan.distanceData[i]);
    }
    if (phase_ == 0 && (api.bumper.getBumperData().state == 1 || front_mm < 350)) {
      phase_ = 1;
      phase_start_ = t_;
      turns_ += 1;
    }
    double v = 0.5, w = 0.0;
    if (phase_ == 1) {  // back off
      v = -0.15;
      if (t_ - phase_start_ > 0.35) {
        phase_ = 2;
        phase_start_ = t_;
        // Towards the freer side (the beams at +-60 degrees), further at every 4th bounce.
        const double left_m = beamAt(scan, M_PI / 3), right_m = beamAt(scan, -M_PI / 3);
        const double side = left_m > right_m ? 1.0 : -1.0;
        target_ = wrap(yaw + side * (1.2 + 0.3 * (turns_ % 4)));
      }
    } else if (phase_ == 2) {  // turn
      v = 0.0;
      const double error = wrap(target_ - yaw);
      w = std::copysign(std::min(2.5, 0.4 + 3.0 * std::abs(error)), error);
      if (std::abs(error) < 0.08 || t_ - phase_start_ > 4.0) phase_ = 0;
    }
    api.motors.sendV(v);
    api.motors.sendW(w);
  }

 private:
  // The range of the first beam at or past `angle_rad`, in metres.
  static double beamAt(const component::LaserData& scan, double angle_rad) {
    for (int i = 0; i < scan.numLaser; ++i) {
      if (scan.angle(i) >= angle_rad) return scan.values_m[i];
    }
    return 0.0;
  }

  double t_ = 0, phase_start_ = 0, target_ = 0;
  int phase_ = 0, turns_ = 0;
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<Bounce>(); }

}  // namespace aula::vacuum
