// Autopark reference solution, reactive (the thesis's manoeuvre, made robust):
//   SEARCH    drive along the lane, keeping a safe distance from the parked cars, while the
//             SlotDetector builds a profile of the parking side from the three lasers; at the
//             street's end (something close ahead or behind) search the other way.
//   APPROACH  drive to the manoeuvre's start: alongside the car ahead of the slot, where two
//             equal arcs of radius R bring the car into the slot, a little behind its centre
//             (reversing in close behind the car ahead is where a parallel park scrapes).
//   ARC1      reverse steering right (the rear swings towards the curb) until the remaining
//             lateral offset is what the second arc removes: R (1 - cos yaw);
//             the arcs are those of the point the car turns about (its centre for a car that
//             turns in place, its rear axle for a car-like one), so one plan suits both;
//   ARC2      reverse steering left until the car is parallel to the curb;
//   CENTRE    forward or back, straight, until the front and rear lasers see equal gaps;
//   PARKED    stop.
// Every arc has radius >= R = 5 m, so the same manoeuvre suits a car-like (Ackermann) car.
#include <aula/autopark/autopark_algorithm.hpp>
#include <aula/autopark/car_geometry.hpp>
#include <aula/autopark/street_search.hpp>
#include <aula/geometry/angles.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aula::autopark {
namespace {

class ReactiveParker : public AutoparkAlgorithm {
 public:
  void execute(AutoparkApi& api) override {
    t_ += api.period_s;
    const auto& front = api.laser1.getLaserData();
    const auto& rear = api.laser2.getLaserData();
    if (front.numLaser == 0 || rear.numLaser == 0 || api.laser3.getLaserData().numLaser == 0 || !api.pose3d.received()) return;
    const double x = api.pose3d.getX(), y = api.pose3d.getY(), yaw = api.pose3d.getYaw();
    // The point the car turns about: it moves on arcs of radius |v / w|.
    const double pivot_y = y + api.turn_centre_x_m * std::sin(yaw);
    if (!search_) {
      radius_m_ = std::max(kArcRadiusM, api.min_turn_radius_m);
      StreetSearch::Settings settings;
      settings.min_slot_length_m = api.car_length_m + kSlotMarginM;
      settings.turn_radius_m = radius_m_;
      search_.emplace(api, settings);
    }
    double v = 0, w = 0;
    switch (mode_) {
      case Mode::Search: {
        const StreetSearch::Step step = search_->search(api, x, y, yaw);
        if (step.slot) {
          slot_ = *step.slot;
          planManoeuvre(api);
          mode_ = Mode::Approach;
          break;
        }
        v = step.v_mps;
        w = step.w_radps;
        break;
      }
      case Mode::Approach: {
        const double to_go = start_x_m_ - x;
        if (std::abs(to_go) < 0.05 && std::abs(y - search_->laneY()) < 0.3 && std::abs(geometry::wrapAngle(yaw)) < 0.05) {
          mode_ = Mode::Arc1;
          break;
        }
        v = std::clamp(0.8 * to_go, -kReverseMps, kCruiseMps);
        if (std::abs(v) < 0.15) v = std::copysign(0.15, to_go);
        w = search_->keepLane(v, y, yaw);
        break;
      }
      case Mode::Arc1: {
        v = -kManoeuvreMps;
        w = kManoeuvreMps / radius_m_;  // reversing, yaw grows: the rear swings right
        const double remaining = pivot_y - goal_y_m_;
        if (remaining <= radius_m_ * (1 - std::cos(yaw)) || yaw > 1.2) mode_ = Mode::Arc2;
        break;
      }
      case Mode::Arc2: {
        v = -kManoeuvreMps;
        w = -kManoeuvreMps / radius_m_;
        // Parallel to the curb, or the car behind is close: straighten up later, forwards.
        if (yaw <= 0.0 || rangeAhead(rear, 0.35) < 0.35) mode_ = Mode::Centre;
        break;
      }
      case Mode::Centre: {
        const double gap_front = rangeAhead(front, 0.15), gap_rear = rangeAhead(rear, 0.15);
        const double error = (gap_front - gap_rear) / 2;  // > 0: move forward
        const double yaw_error = geometry::wrapAngle(yaw);
        if (std::abs(error) < 0.1 && std::abs(yaw_error) < 0.03) {
          mode_ = Mode::Parked;
          break;
        }
        v = std::clamp(0.8 * error, -0.5, 0.5);
        if (std::abs(v) < 0.1) v = std::copysign(0.1, error);
        // Straighten while moving: the yaw follows the sign of the motion.
        w = std::clamp(-2.0 * yaw_error * (v > 0 ? 1 : -1) * std::abs(v), -std::abs(v) / radius_m_, std::abs(v) / radius_m_);
        if (std::abs(yaw_error) < 0.03) w = 0;
        if (++centre_moves_ > 2000) mode_ = Mode::Parked;  // never oscillate forever
        break;
      }
      case Mode::Parked:
        break;
    }
    if (mode_ != logged_mode_) {
      // One line per phase, so a student can follow the manoeuvre in the terminal.
      std::fprintf(stderr, "reactive [%.2f s]: %s at x %.2f y %.2f yaw %.1f deg\n", t_, name(mode_), x, y, geometry::headingDeg(yaw));
      logged_mode_ = mode_;
    }
    api.motors.sendV(v);
    api.motors.sendW(w);
  }

 private:
  enum class Mode { Search, Approach, Arc1, Arc2, Centre, Parked };
  static const char* name(Mode m) {
    static const char* const names[] = {"SEARCH", "APPROACH", "ARC1", "ARC2", "CENTRE", "PARKED"};
    return names[static_cast<int>(m)];
  }
  static constexpr double kSlotMarginM = 0.8;      // shortest slot: the car plus this
  static constexpr double kArcRadiusM = 5.0;
  static constexpr double kCurbClearanceM = 0.45;  // where the parked car's side ends up
  static constexpr double kBehindCentreM = 1.0;    // the arcs end this far behind the slot's centre
  static constexpr double kCruiseMps = 2.0, kReverseMps = 1.5, kManoeuvreMps = 0.8;

  // Where the two arcs start: they bring the centre from the lane to the slot's centre line.
  void planManoeuvre(const AutoparkApi& api) {
    search_->holdLane(search_->laneYFor(slot_.edge_y_m));
    goal_y_m_ = slot_.curb_y_m + kCurbClearanceM + api.car_width_m / 2;
    const double offset = search_->laneY() - goal_y_m_;
    const double cos_arc = std::clamp(1.0 - offset / (2 * radius_m_), -1.0, 1.0);
    const double arc_length_x = 2 * radius_m_ * std::sqrt(1 - cos_arc * cos_arc);
    // Room behind: end no closer than 0.6 m to the car behind; CENTRE then drives forward.
    const double behind = std::clamp((slot_.lengthM() - api.car_length_m) / 2 - 0.6, 0.0, kBehindCentreM);
    // The pivot starts and ends at the same body offset, parallel to the street.
    start_x_m_ = slot_.centreXM() - behind + arc_length_x;
  }

  std::optional<StreetSearch> search_;
  Slot slot_;
  Mode mode_ = Mode::Search, logged_mode_ = Mode::Parked;
  double t_ = 0, radius_m_ = kArcRadiusM;
  double goal_y_m_ = 0, start_x_m_ = 0;
  int centre_moves_ = 0;
};

}  // namespace

std::unique_ptr<AutoparkAlgorithm> makeReactiveAlgorithm(uint64_t) { return std::make_unique<ReactiveParker>(); }

}  // namespace aula::autopark
