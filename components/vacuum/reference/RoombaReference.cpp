// Vacuum cleaner reference solution, Roomba style and reactive (no localization: only yaw,
// laser, bumper and its own commands):
//   SPIRAL  an outward spiral in open space, until something is ahead;
//   WALL    right-hand wall following with the laser for a while after the first contact;
//   CROSS   straight runs across the room, each ended by a seeded random turn;
//   escape  after a bump: back off, then turn; repeated bumps in a short time widen the turn.
// It returns to the spiral when a run ends in open space, and to the wall now and then.
// New headings favour floor it has not been over yet, by dead reckoning: it integrates its own
// speed commands along the measured yaw into a coarse memory of where it has been. That drifts
// (wheels slip, pushes against furniture), so it only biases the random choice.
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <aula/geometry/angles.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace aula::vacuum {
namespace {

using geometry::wrapAngle;

class RoombaReference : public VacuumAlgorithm {
 public:
  explicit RoombaReference(uint64_t seed) : rng_(seed * 2654435761ull + 17) {}

  void execute(VacuumApi& api) override {
    const double dt = api.period_s;
    t_ += dt;
    const auto& laser = api.laser.getLaserData();
    if (laser.numLaser == 0) return;  // no scan yet
    const double front = sectorMin(laser, -0.45, 0.45);
    const double front_wide = sectorMin(laser, -1.0, 1.0);
    const double right = sectorMin(laser, -1.58, -1.25);
    const double yaw = api.pose3d.getYaw();
    const bool bumped = api.bumper.getBumperData().state == 1;
    deadReckon(yaw, bumped || front < 0.12, dt);

    // A bump ends a forward move. While backing off or turning (a disc can always turn on the
    // spot) a held bumper is ignored, or a robot wedged in a nook would back off forever.
    const bool moving_forward = mode_ == Mode::Cross || mode_ == Mode::Wall || mode_ == Mode::Spiral;
    if (bumped && moving_forward && (!was_bumped_ || t_ - mode_start_ > 0.3)) {
      bumps_recent_ = t_ - last_bump_t_ < 5.0 ? bumps_recent_ + 1 : 1;
      last_bump_t_ = t_;
      enter(Mode::Backoff);
    }
    was_bumped_ = bumped;
    double v = 0, w = 0;
    switch (mode_) {
      case Mode::Spiral: {
        spiral_radius_ += 0.05 * dt / std::max(spiral_radius_, 0.1);  // rings ~0.3 m apart
        v = max_v_;
        w = v / spiral_radius_;
        if (front < 0.3 || front_wide < 0.2 || t_ - mode_start_ > 40.0) chooseHeading(laser, yaw, false);
        break;
      }
      case Mode::Cross: {
        v = front < 0.5 ? 0.3 : max_v_;
        if (t_ - mode_start_ > 1.0) quick_fails_ = 0;  // a real run: not boxed in
        if (front < 0.22 || front_wide < 0.17) {
          // Blocked again right after turning, several times: boxed in without touching
          // anything. Back out and turn round.
          if (t_ - mode_start_ < 0.5 && ++quick_fails_ >= 3) {
            quick_fails_ = 0;
            bumps_recent_ = 3;
            enter(Mode::Backoff);
          } else {
            chooseHeading(laser, yaw, false);
          }
        } else if (t_ - wall_end_t_ > wall_every_s_ && right < 0.5) {
          enter(Mode::Wall);  // a wall on the right: follow it for a while
        }
        break;
      }
      case Mode::Wall: {
        if (front < 0.3 || front_wide < 0.18) {
          v = 0.0;
          w = 1.8;  // corner ahead: turn left on the spot
        } else if (right > 0.7) {
          v = 0.3;
          w = -1.3;  // lost the wall: curve right to find it
        } else {
          v = 0.45;
          w = std::clamp(-5.0 * (right - 0.24), -1.5, 1.5);
        }
        if (t_ - mode_start_ > wall_time_s_) {
          wall_end_t_ = t_;
          chooseHeading(laser, yaw, false);
        }
        break;
      }
      case Mode::Backoff: {
        v = -0.15;
        if (t_ - mode_start_ > (bumps_recent_ >= 3 ? 0.8 : 0.3)) chooseHeading(laser, yaw, bumps_recent_ >= 3);
        break;
      }
      case Mode::Turn: {
        const double error = wrapAngle(turn_target_ - yaw);
        w = std::copysign(std::min(2.8, 0.5 + 3.0 * std::abs(error)), error);
        if (std::abs(error) < 0.1 || t_ - mode_start_ > 3.0) enter(turn_next_);
        break;
      }
    }
    // Spinning on the spot for long (a corner the wall follower cannot leave, a nook where every
    // turn faces an obstacle): back out and turn round.
    spin_s_ = std::abs(v) < 0.05 ? spin_s_ + dt : 0.0;
    if (spin_s_ > 4.0) {
      spin_s_ = 0;
      bumps_recent_ = 3;
      wall_end_t_ = t_;
      enter(Mode::Backoff);
    }
    api.motors.sendV(v);
    api.motors.sendW(w);
    commanded_v_ = std::clamp(v, -max_v_, max_v_);
  }

 private:
  enum class Mode { Spiral, Cross, Wall, Backoff, Turn };

  // Dead-reckoned memory: cells of kCellM around the start, marked where the robot has been.
  static constexpr double kCellM = 0.25;
  static constexpr int kCells = 200;  // 50 x 50 m

  void deadReckon(double yaw, bool blocked, double dt) {
    // Last period's command; a pressed bumper or a wall at the nose means it did not move.
    if (!(blocked && commanded_v_ > 0)) {
      x_m_ += commanded_v_ * dt * std::cos(yaw);
      y_m_ += commanded_v_ * dt * std::sin(yaw);
    }
    const int c = cellOf(x_m_), r = cellOf(y_m_);
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        if (dr != 0 && dc != 0) continue;  // a plus: about the 0.33 m disc
        if (inside(c + dc, r + dr)) visited_[(r + dr) * kCells + c + dc] = 1;
      }
  }
  static int cellOf(double v_m) { return static_cast<int>(std::floor(v_m / kCellM)) + kCells / 2; }
  static bool inside(int c, int r) { return c >= 0 && r >= 0 && c < kCells && r < kCells; }

  // Fraction of the not-yet-visited cells along a heading, up to range_m.
  double novelty(double heading_rad, double range_m) const {
    int fresh = 0, total = 0;
    for (double d = 0.5; d <= range_m; d += kCellM) {
      const int c = cellOf(x_m_ + d * std::cos(heading_rad)), r = cellOf(y_m_ + d * std::sin(heading_rad));
      ++total;
      if (inside(c, r) && !visited_[r * kCells + c]) ++fresh;
    }
    return total == 0 ? 0.0 : static_cast<double>(fresh) / total;
  }

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
    if (m == Mode::Spiral) spiral_radius_ = 0.15;
  }

  // A new heading: a random open direction the laser sees (a corridor at least as wide as the
  // robot and 0.8 m deep), favouring long ones; if there is none, or the robot is trapped,
  // turn back (the way it came in is free).
  void chooseHeading(const component::LaserData& laser, double yaw, bool trapped) {
    std::vector<std::pair<double, double>> options;  // (angle, weight)
    const int half_width = 8;  // beams on each side: ~8 degrees, the robot's width at ~1 m
    for (int i = half_width; i + half_width < laser.numLaser; i += 2) {
      const double a = laser.angle(i);
      if (std::abs(a) < 0.35) continue;  // straight ahead is what just got blocked
      double clear = laser.maxRange;
      for (int k = i - half_width; k <= i + half_width; ++k) clear = std::min<double>(clear, laser.values_m[k]);
      if (clear < 0.8) continue;
      const double reach = std::min(clear, 4.0);
      const double fresh = novelty(yaw + a, reach);
      options.emplace_back(a, reach * (novelty_floor_ + fresh) * (novelty_floor_ + fresh));
    }
    double delta;
    if (trapped || options.empty()) {
      delta = M_PI + std::uniform_real_distribution<double>(-0.7, 0.7)(rng_);
      bumps_recent_ = 0;
    } else {
      double total = 0;
      for (const auto& o : options) total += o.second;
      double pick = std::uniform_real_distribution<double>(0, total)(rng_);
      delta = options.back().first;
      for (const auto& o : options) {
        if ((pick -= o.second) <= 0) {
          delta = o.first;
          break;
        }
      }
    }
    // Open space all around: spiral there now and then.
    const bool open = sectorMin(laser, -1.57, 1.57) > 0.9;
    const Mode next = open && std::uniform_real_distribution<double>(0, 1)(rng_) < 0.35 ? Mode::Spiral : Mode::Cross;
    turn_target_ = wrapAngle(yaw + delta);
    turn_next_ = next;
    enter(Mode::Turn);
  }

  std::mt19937_64 rng_;
  Mode mode_ = Mode::Spiral;
  Mode turn_next_ = Mode::Cross;
  double t_ = 0, mode_start_ = 0, last_bump_t_ = -100, wall_end_t_ = 0;
  double spiral_radius_ = 0.15, turn_target_ = 0;
  double max_v_ = 0.5, wall_time_s_ = 45.0, wall_every_s_ = 60.0;
  int bumps_recent_ = 0;
  int quick_fails_ = 0;
  double spin_s_ = 0;
  bool was_bumped_ = false;
  double commanded_v_ = 0, x_m_ = 0, y_m_ = 0;
  double novelty_floor_ = 0.05;
  std::vector<uint8_t> visited_ = std::vector<uint8_t>(kCells * kCells, 0);
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
        target_ = wrapAngle(yaw + angle(rng_));
      }
    } else if (phase_ == 2) {  // turn
      v = 0;
      const double error = wrapAngle(target_ - yaw);
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
