// Vacuum cleaner reference solution, Roomba style and reactive (no localization: only yaw,
// laser, bumper and its own commands):
//   SPIRAL  an outward spiral in open space, until something is ahead;
//   WALL    right-hand wall following with the laser for a while after the first contact;
//   CROSS   straight runs across the room, each ended by a seeded random turn;
//   escape  after a bump: back off, then turn; repeated bumps in a short time widen the turn.
// It returns to the spiral when a run ends in open space, and to the wall now and then.
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace aula::vacuum {
namespace {

double wrap(double a) { return std::atan2(std::sin(a), std::cos(a)); }

class RoombaReference : public VacuumAlgorithm {
 public:
  explicit RoombaReference(uint64_t seed) : rng_(seed * 2654435761ull + 17) {}

  void execute(VacuumApi& api) override {
    const double dt = api.period_s;
    t_ += dt;
    const auto& laser = api.laser.getLaserData();
    if (laser.numLaser == 0) return;  // no scan yet
    const double front = sectorMin(laser, -0.45, 0.45);
    const double front_wide = sectorMin(laser, -0.9, 0.9);
    const double right = sectorMin(laser, -1.58, -1.2);
    const double yaw = api.pose3d.getYaw();
    const bool bumped = api.bumper.getBumperData().state == 1;

    if (bumped && mode_ != Mode::Backoff) {
      bumps_recent_ = t_ - last_bump_t_ < 4.0 ? bumps_recent_ + 1 : 1;
      last_bump_t_ = t_;
      enter(Mode::Backoff);
    }
    double v = 0, w = 0;
    switch (mode_) {
      case Mode::Spiral: {
        spiral_radius_ += 0.012 * dt / std::max(spiral_radius_, 0.1);  // constant spacing
        v = max_v_;
        w = v / spiral_radius_;
        if (front < 0.35 || front_wide < 0.22) startTurn(yaw, after_spiral_);
        break;
      }
      case Mode::Cross: {
        v = front < 0.6 ? 0.25 : max_v_;
        if (front < 0.22 || front_wide < 0.17) {
          ++runs_;
          // A long free run means open space: spiral there sometimes.
          const bool open = t_ - mode_start_ > 6.0 && sectorMin(laser, -1.57, 1.57) > 0.5;
          startTurn(yaw, open && runs_ % 3 == 0 ? Mode::Spiral : Mode::Cross);
        } else if (t_ - wall_end_t_ > 110.0) {
          startTurn(yaw, Mode::Wall, 0.0);
        }
        break;
      }
      case Mode::Wall: {
        if (front < 0.3) {
          v = 0.0;
          w = 1.6;  // corner ahead: turn left on the spot
        } else if (right > 0.6) {
          v = 0.25;
          w = -1.2;  // lost the wall: curve right to find it
        } else {
          v = 0.4;
          w = std::clamp(-6.0 * (right - 0.26), -1.5, 1.5);
        }
        if (t_ - mode_start_ > wall_time_s_) {
          wall_end_t_ = t_;
          startTurn(yaw, Mode::Cross);
        }
        break;
      }
      case Mode::Backoff: {
        v = -0.15;
        if (t_ - mode_start_ > 0.35) {
          const Mode next = first_contact_ ? Mode::Wall : Mode::Cross;
          first_contact_ = false;
          startTurn(yaw, next, bumps_recent_ >= 3 ? 1.0 : 0.0);
        }
        break;
      }
      case Mode::Turn: {
        const double error = wrap(turn_target_ - yaw);
        w = std::copysign(std::min(2.5, 0.4 + 3.0 * std::abs(error)), error);
        if (std::abs(error) < 0.08 || t_ - mode_start_ > 4.0) enter(turn_next_);
        break;
      }
    }
    api.motors.sendV(v);
    api.motors.sendW(w);
  }

 private:
  enum class Mode { Spiral, Cross, Wall, Backoff, Turn };

  static double sectorMin(const component::LaserData& laser, double from_rad, double to_rad) {
    double m = laser.maxRange;
    for (int i = 0; i < laser.numLaser; ++i) {
      const double a = laser.angle(i);
      if (a >= from_rad && a <= to_rad) m = std::min<double>(m, laser.values_m[i]);
    }
    return m;
  }

  void enter(Mode m) {
    mode_ = m;
    mode_start_ = t_;
    if (m == Mode::Spiral) spiral_radius_ = 0.2;
  }

  // Turn by a random angle (left, 100-260 degrees), widened when trapped; or, for the wall
  // follower, a quarter turn left so the wall ends up on the right.
  void startTurn(double yaw, Mode next, double extra = 0.0) {
    std::uniform_real_distribution<double> angle(1.75, 4.5);
    double delta = next == Mode::Wall ? M_PI / 2 : angle(rng_) + extra;
    if (next != Mode::Wall && std::uniform_int_distribution<int>(0, 1)(rng_) == 0) delta = -delta;
    turn_target_ = wrap(yaw + delta);
    turn_next_ = next;
    enter(Mode::Turn);
  }

  std::mt19937_64 rng_;
  Mode mode_ = Mode::Spiral;
  Mode turn_next_ = Mode::Cross;
  Mode after_spiral_ = Mode::Cross;
  double t_ = 0, mode_start_ = 0, last_bump_t_ = -100, wall_end_t_ = 0;
  double spiral_radius_ = 0.2, turn_target_ = 0;
  double max_v_ = 0.5, wall_time_s_ = 45.0;
  int runs_ = 0, bumps_recent_ = 0;
  bool first_contact_ = true;
};

// The baseline: straight ahead at full speed until the bumper fires, back off, random turn.
class RandomBounce : public VacuumAlgorithm {
 public:
  explicit RandomBounce(uint64_t seed) : rng_(seed * 2654435761ull + 99) {}
  void execute(VacuumApi& api) override {
    t_ += api.period_s;
    const double yaw = api.pose3d.getYaw();
    if (api.bumper.getBumperData().state == 1 && phase_ == 0) {
      phase_ = 1;
      phase_start_ = t_;
    }
    double v = 0.5, w = 0;
    if (phase_ == 1) {  // back off
      v = -0.15;
      if (t_ - phase_start_ > 0.35) {
        phase_ = 2;
        phase_start_ = t_;
        std::uniform_real_distribution<double> angle(-M_PI, M_PI);
        target_ = wrap(yaw + angle(rng_));
      }
    } else if (phase_ == 2) {  // turn
      v = 0;
      const double error = wrap(target_ - yaw);
      w = std::copysign(std::min(2.5, 0.4 + 3.0 * std::abs(error)), error);
      if (std::abs(error) < 0.08 || t_ - phase_start_ > 4.0) phase_ = 0;
    }
    api.motors.sendV(v);
    api.motors.sendW(w);
  }

 private:
  std::mt19937_64 rng_;
  double t_ = 0, phase_start_ = 0, target_ = 0;
  int phase_ = 0;
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeReferenceAlgorithm(uint64_t seed) { return std::make_unique<RoombaReference>(seed); }
std::unique_ptr<VacuumAlgorithm> makeRandomBounceAlgorithm(uint64_t seed) { return std::make_unique<RandomBounce>(seed); }

}  // namespace aula::vacuum
