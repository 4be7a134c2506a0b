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
#include <aula/vacuum/references.hpp>

#include "roomba_steps.hpp"

#include <aula/geometry/angles.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace aula::vacuum {
namespace {

using geometry::wrapAngle;

using roomba::Command;
using roomba::sectorMin;
using roomba::Settings;

class RoombaReference : public VacuumAlgorithm {
 public:
  explicit RoombaReference(uint64_t seed, Settings settings = {})
      : s_(settings), rng_(seed * 2654435761ull + 17) {}

  void execute(VacuumApi& api) override {
    const double dt = api.period_s;
    t_ += dt;
    const auto& laser = api.laser.getLaserData();
    if (laser.numLaser == 0) return;  // no scan yet
    const Ranges ranges{sectorMin(laser, -s_.front_half_rad, s_.front_half_rad),
                        sectorMin(laser, -s_.front_wide_half_rad, s_.front_wide_half_rad),
                        sectorMin(laser, s_.right_from_rad, s_.right_to_rad)};
    const double yaw = api.pose3d.getYaw();
    const bool bumped = api.bumper.getBumperData().state == 1;
    deadReckon(yaw, bumped || ranges.front_m < s_.blocked_front_m, dt);
    onBumper(bumped);
    const Command command = step(laser, ranges, yaw, dt);
    leaveLongSpins(command.v_mps, dt);
    api.motors.sendV(command.v_mps);
    api.motors.sendW(command.w_radps);
    commanded_v_ = std::clamp(command.v_mps, -max_v_, max_v_);
  }

 private:
  enum class Mode { Spiral, Cross, Wall, Backoff, Turn };

  // The laser's nearest echo ahead, ahead and to the sides, and on the right.
  struct Ranges {
    double front_m, front_wide_m, right_m;
  };

  // A bump ends a forward move. While backing off or turning (a disc can always turn on the
  // spot) a held bumper is ignored, or a robot wedged in a nook would back off forever.
  void onBumper(bool bumped) {
    const bool moving_forward = mode_ == Mode::Cross || mode_ == Mode::Wall || mode_ == Mode::Spiral;
    if (bumped && moving_forward && (!was_bumped_ || t_ - mode_start_ > s_.bump_debounce_s)) {
      bumps_recent_ = t_ - last_bump_t_ < s_.bump_window_s ? bumps_recent_ + 1 : 1;
      last_bump_t_ = t_;
      enter(Mode::Backoff);
    }
    was_bumped_ = bumped;
  }

  // This period's command by the mode; each mode's step may choose the next mode.
  Command step(const component::LaserData& laser, const Ranges& r, double yaw, double dt) {
    switch (mode_) {
      case Mode::Spiral:
        return spiralStep(laser, r, yaw, dt);
      case Mode::Cross:
        return crossStep(laser, r, yaw);
      case Mode::Wall:
        return wallStep(laser, r, yaw);
      case Mode::Backoff: {
        const bool trapped = bumps_recent_ >= s_.bumps_to_trapped;
        if (t_ - mode_start_ > (trapped ? s_.backoff_trapped_s : s_.backoff_s)) chooseHeading(laser, yaw, trapped);
        return {-s_.backoff_speed_mps, 0.0};
      }
      case Mode::Turn: {
        const double error = wrapAngle(turn_target_ - yaw);
        if (std::abs(error) < s_.turn_tolerance_rad || t_ - mode_start_ > s_.turn_timeout_s) enter(turn_next_);
        return {0.0, roomba::turnRate(s_, error)};
      }
    }
    return {};
  }

  // An outward spiral until something is ahead or it has spiralled long enough.
  Command spiralStep(const component::LaserData& laser, const Ranges& r, double yaw, double dt) {
    spiral_radius_ = roomba::spiralRadiusAfter(s_, spiral_radius_, dt);
    const Command command{max_v_, max_v_ / spiral_radius_};
    if (r.front_m < s_.spiral_stop_front_m || r.front_wide_m < s_.spiral_stop_wide_m || t_ - mode_start_ > s_.spiral_max_s) {
      chooseHeading(laser, yaw, false);
    }
    return command;
  }

  // A straight run, slower near what is ahead; blocked, a new heading; a wall on the right now
  // and then, followed for a while.
  Command crossStep(const component::LaserData& laser, const Ranges& r, double yaw) {
    const double v = r.front_m < s_.cross_slow_front_m ? s_.cross_slow_speed_mps : max_v_;
    if (t_ - mode_start_ > s_.quick_fail_reset_s) quick_fails_ = 0;  // a real run: not boxed in
    if (r.front_m < s_.cross_stop_front_m || r.front_wide_m < s_.cross_stop_wide_m) {
      // Blocked again right after turning, several times: boxed in without touching
      // anything. Back out and turn round.
      if (t_ - mode_start_ < s_.quick_fail_window_s && ++quick_fails_ >= s_.quick_fails_to_escape) {
        quick_fails_ = 0;
        bumps_recent_ = s_.bumps_to_trapped;
        enter(Mode::Backoff);
      } else {
        chooseHeading(laser, yaw, false);
      }
    } else if (t_ - wall_end_t_ > s_.wall_every_s && r.right_m < s_.wall_trigger_right_m) {
      enter(Mode::Wall);  // a wall on the right: follow it for a while
    }
    return {v, 0.0};
  }

  // Right-hand wall following for wall_time_s, then a new heading.
  Command wallStep(const component::LaserData& laser, const Ranges& r, double yaw) {
    const Command command = roomba::wallFollow(s_, r.front_m, r.front_wide_m, r.right_m);
    if (t_ - mode_start_ > s_.wall_time_s) {
      wall_end_t_ = t_;
      chooseHeading(laser, yaw, false);
    }
    return command;
  }

  // Spinning on the spot for long (a corner the wall follower cannot leave, a nook where every
  // turn faces an obstacle): back out and turn round.
  void leaveLongSpins(double v, double dt) {
    spin_s_ = std::abs(v) < s_.spin_speed_mps ? spin_s_ + dt : 0.0;
    if (spin_s_ > s_.spin_limit_s) {
      spin_s_ = 0;
      bumps_recent_ = s_.bumps_to_trapped;
      wall_end_t_ = t_;
      enter(Mode::Backoff);
    }
  }


  // Dead-reckoned memory: cells of Settings::memory_cell_m around the start, marked where the
  // robot has been.
  static constexpr int kCells = 200;

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
  int cellOf(double v_m) const { return static_cast<int>(std::floor(v_m / s_.memory_cell_m)) + kCells / 2; }
  static bool inside(int c, int r) { return c >= 0 && r >= 0 && c < kCells && r < kCells; }

  // Fraction of the not-yet-visited cells along a heading, up to range_m.
  double novelty(double heading_rad, double range_m) const {
    int fresh = 0, total = 0;
    for (double d = s_.novelty_start_m; d <= range_m; d += s_.memory_cell_m) {
      const int c = cellOf(x_m_ + d * std::cos(heading_rad)), r = cellOf(y_m_ + d * std::sin(heading_rad));
      ++total;
      if (inside(c, r) && !visited_[r * kCells + c]) ++fresh;
    }
    return total == 0 ? 0.0 : static_cast<double>(fresh) / total;
  }

  void enter(Mode m) {
    mode_ = m;
    mode_start_ = t_;
    if (m == Mode::Spiral) spiral_radius_ = s_.spiral_start_radius_m;
  }

  // A new heading: a random open direction the laser sees (a corridor at least as wide as the
  // robot and 0.8 m deep), favouring long ones; if there is none, or the robot is trapped,
  // turn back (the way it came in is free).
  void chooseHeading(const component::LaserData& laser, double yaw, bool trapped) {
    std::vector<std::pair<double, double>> options;  // (angle, weight)
    const int half_width = s_.heading_half_width_beams;
    for (int i = half_width; i + half_width < laser.numLaser; i += 2) {
      const double a = laser.angle(i);
      if (std::abs(a) < s_.heading_skip_ahead_rad) continue;  // straight ahead is what just got blocked
      double clear = laser.maxRange;
      for (int k = i - half_width; k <= i + half_width; ++k) clear = std::min<double>(clear, laser.values_m[k]);
      if (clear < s_.heading_min_clear_m) continue;
      const double reach = std::min(clear, s_.heading_max_reach_m);
      const double fresh = novelty(yaw + a, reach);
      options.emplace_back(a, reach * (s_.novelty_floor + fresh) * (s_.novelty_floor + fresh));
    }
    double delta;
    if (trapped || options.empty()) {
      delta = M_PI + std::uniform_real_distribution<double>(-s_.trapped_turn_spread_rad, s_.trapped_turn_spread_rad)(rng_);
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
    const bool open = sectorMin(laser, -s_.open_half_rad, s_.open_half_rad) > s_.open_side_m;
    const Mode next = open && std::uniform_real_distribution<double>(0, 1)(rng_) < s_.spiral_chance ? Mode::Spiral : Mode::Cross;
    turn_target_ = wrapAngle(yaw + delta);
    turn_next_ = next;
    enter(Mode::Turn);
  }

  const Settings s_;
  const double max_v_ = s_.max_speed_mps;
  std::mt19937_64 rng_;
  Mode mode_ = Mode::Spiral;
  Mode turn_next_ = Mode::Cross;
  double t_ = 0, mode_start_ = 0, last_bump_t_ = -100, wall_end_t_ = 0;
  double spiral_radius_ = s_.spiral_start_radius_m, turn_target_ = 0;
  int bumps_recent_ = 0;
  int quick_fails_ = 0;
  double spin_s_ = 0;
  bool was_bumped_ = false;
  double commanded_v_ = 0, x_m_ = 0, y_m_ = 0;
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
