// Autopark reference solution, reactive (the thesis's manoeuvre, made robust and general):
//   TURN      a start facing the wrong way: turn round before searching (on the spot for a car
//             that turns in place; a three-point turn for a car-like one, each leg until
//             something is near ahead or behind).
//   SEARCH    drive along the lane, keeping a safe distance from the parked cars, while the
//             SlotDetector builds a profile of the parking side from the three lasers; at the
//             street's end (something close ahead or behind) search the other way.
//   (a slot)  plan for what the lasers measured (planTwoArcPark: the slot's length, the parked
//             cars' line, the curb): two equal arcs of the point the car turns about, swept
//             against the parked cars and the curb for every end point in the slot; none clear:
//   (too short for the arcs, a car that turns in place) a multi-move park, as parking assistants
//             do: APPROACH to the slot's centre, then
//   ZIGZAG    turn in place to -a, drive forward (down and ahead), turn to +a, reverse (down and
//             back), ... each move within the slot's measured ends, each turn high enough above
//             the curb for the body's corners, the angle a smaller as the car gets lower; on the
//             slot's line, turn straight and CENTRE.
//   DECLINED  stop and say why ("slot too short for a reactive park: 5.0 m, need 5.9 m"; for the
//             car that turns in place, shorter than the multi-move park needs).
//   APPROACH  drive along the lane to where the arcs start; arrived there off the lane (a start
//             beside or past the slot), back off along the lane and come again.
//   ARC1      reverse steering right (the rear swings towards the curb) until the remaining
//             lateral offset is what the second arc removes: R (1 - cos yaw);
//   ARC2      reverse steering left until the car is parallel to the curb;
//   CENTRE    forward or back, straight, until the front and rear lasers see equal gaps;
//   PARKED    stop: only when the car is in the slot, parallel; anywhere else it is
//   FAILED    stop and say where it ended; or, in any phase that runs longer than it ever should
//             (a car that cannot move), "stalled", with the phase, how long and where.
#include <aula/autopark/autopark_algorithm.hpp>
#include <aula/autopark/references.hpp>
#include <aula/autopark/car_geometry.hpp>
#include <aula/autopark/reference_steps.hpp>
#include <aula/autopark/street_search.hpp>
#include <aula/autopark/two_arc_park.hpp>
#include <aula/geometry/angles.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aula::autopark {
namespace {

class ReactiveParker : public AutoparkAlgorithm {
 public:
  // One control period: read the pose, run the present phase, say when the phase changes, drive.
  void execute(AutoparkApi& api) override {
    t_ += api.period_s;
    if (!sensorsReady(api)) return;
    const double x = api.pose3d.getX(), y = api.pose3d.getY(), yaw = api.pose3d.getYaw();
    if (!search_) start(api, yaw);
    Command command;
    if (overTime()) {
      stalled(api, x, y);
    } else {
      step(api, x, y, yaw, command);
    }
    logPhase(api, x, y, yaw);
    api.motors.sendV(command.v_mps);
    api.motors.sendW(command.w_radps);
  }

 private:
  enum class Mode { Turn, Search, Approach, Arc1, Arc2, Zigzag, Centre, Parked, Declined, Failed };
  static const char* name(Mode m) {
    static const char* const names[] = {"TURN",   "SEARCH", "APPROACH", "ARC1",     "ARC2",
                                        "ZIGZAG", "CENTRE", "PARKED",   "DECLINED", "FAILED"};
    return names[static_cast<int>(m)];
  }
  static constexpr double kArcRadiusM = 5.0;       // the search's steering limit
  static constexpr double kCruiseMps = 2.0, kReverseMps = 1.5, kManoeuvreMps = 0.8;
  // The multi-move park of a car that turns in place.
  static constexpr double kZigzagMaxRad = 0.6, kZigzagMinRad = 0.1, kZigzagStepRad = 0.05;
  static constexpr double kZigzagEndMarginM = 0.2;   // the body's ends from the slot's measured ends
  static constexpr double kZigzagCurbMarginM = 0.1;  // its lowest corner above the curb face
  static constexpr double kZigzagMinTravelM = 0.4;   // the shortest useful move
  static constexpr double kZigzagDoneM = 0.12;       // this near the slot's line: straighten up
  // The multi-move park's side from the parked cars' far side, where no curb was seen: each move
  // keeps the corners clear of that line, so it can end in line with the neighbours (the
  // referee's ideal pose is on their centre line) where the two arcs need more room.
  static constexpr double kZigzagFarSideClearanceM = 0.2;
  static constexpr double kZigzagMps = 0.5, kZigzagTurnRadps = 0.6;
  static constexpr int kZigzagMaxMoves = 40;
  // The longest each phase may take, sim seconds: longer, it is stuck and says so (never a silent
  // stall until the run's time is up). A search drives a long street both ways; a turn is short.
  static constexpr double kSearchLimitS = 240, kTurnLimitS = 60, kManoeuvreLimitS = 150;
  static constexpr double kArcRearClearM = 0.2;  // the second arc stops this near the slot's rear end
  static constexpr double kBackOffClearM = 1.0;  // backing off for a run-up stops this near something behind

  // The present phase's command for this period (and the next phase, when it ends).
  void step(AutoparkApi& api, double x, double y, double yaw, Command& c) {
    switch (mode_) {
      case Mode::Turn:
        if (turn_.step(api, yaw, c.v_mps, c.w_radps)) mode_ = Mode::Search;
        break;
      case Mode::Search:
        searchStep(api, x, y, yaw, c);
        break;
      case Mode::Approach:
        approachStep(api, x, y, yaw, c);
        break;
      case Mode::Arc1:
        arc1Step(api, y, yaw, c);
        break;
      case Mode::Arc2:
        arc2Step(api, x, y, yaw, c);
        break;
      case Mode::Zigzag:
        zigzag(api, x, y, yaw, c.v_mps, c.w_radps);
        break;
      case Mode::Centre:
        centre(api, x, y, yaw, c.v_mps, c.w_radps);
        break;
      case Mode::Parked:
      case Mode::Declined:
      case Mode::Failed:
        break;
    }
  }

  // SEARCH: drive down the street until the detector reports a slot, then plan for it.
  void searchStep(AutoparkApi& api, double x, double y, double yaw, Command& c) {
    if (search_->exhausted()) {
      api.status = "no free slot on the street";
      mode_ = Mode::Declined;
      return;
    }
    const StreetSearch::Step found = search_->search(api, x, y, yaw);
    if (found.slot) {
      planFor(api, *found.slot);
      return;
    }
    c.v_mps = found.v_mps;
    c.w_radps = found.w_radps;
  }

  // APPROACH: along the lane to where the arcs (or the multi-move park) start.
  void approachStep(const AutoparkApi& api, double x, double y, double yaw, Command& c) {
    const double to_go = plan_.start_x_m - x, off_lane = y - search_->laneY();
    if (atArcStart(to_go, y, search_->laneY(), yaw)) {
      mode_ = zigzag_ ? Mode::Zigzag : Mode::Arc1;
      if (zigzag_) zig_angle_ = zigzagAngle(api, y);
      return;
    }
    if (back_off_m_ <= 0 && arrivedOffLane(to_go, off_lane)) back_off_m_ = runUpM(off_lane);
    if (back_off_m_ > 0 && (to_go >= back_off_m_ || bodyGapBehind(api, 0.3) < kBackOffClearM)) {
      back_off_m_ = 0;  // far enough behind the start (or something close behind): come again
    }
    c.v_mps = back_off_m_ > 0 ? -kReverseMps : approachSpeed(to_go, kCruiseMps, kReverseMps);
    c.w_radps = search_->keepLane(c.v_mps, y, yaw);
  }

  // Whether the present phase has run longer than it ever should.
  bool overTime() const {
    if (mode_ == Mode::Parked || mode_ == Mode::Declined || mode_ == Mode::Failed) return false;
    const double limit = mode_ == Mode::Search ? kSearchLimitS : mode_ == Mode::Turn ? kTurnLimitS : kManoeuvreLimitS;
    return t_ - phase_start_s_ > limit;
  }

  // Stuck: stop and say in which phase, for how long, and where (and where the slot is, if one).
  void stalled(AutoparkApi& api, double x, double y) {
    char line[200];
    const int n = std::snprintf(line, sizeof line, "stalled: %.0f s in %s, stopped at x %.2f y %.2f", t_ - phase_start_s_,
                                name(mode_), x, y);
    if (mode_ != Mode::Search && mode_ != Mode::Turn && n > 0 && n < static_cast<int>(sizeof line)) {
      std::snprintf(line + n, sizeof line - n, " (the slot: x %.2f to %.2f)", slot_.rear_x_m, slot_.front_x_m);
    }
    api.status = line;
    mode_ = Mode::Failed;
  }

  // ARC1: reversing, yaw grows, the rear swings right towards the curb.
  void arc1Step(const AutoparkApi& api, double y, double yaw, Command& c) {
    c.v_mps = -kManoeuvreMps;
    c.w_radps = kManoeuvreMps / plan_.radius_m;
    // The point the car turns about: it moves on arcs of radius |v / w|.
    const double pivot_y = y + api.turn_centre_x_m * std::sin(yaw);
    if (firstArcDone(pivot_y - plan_.goal_y_m, plan_.radius_m, yaw, plan_.arc_rad)) mode_ = Mode::Arc2;
  }

  // ARC2: reversing, steering the other way until parallel to the curb.
  void arc2Step(const AutoparkApi& api, double x, double y, double yaw, Command& c) {
    c.v_mps = -kManoeuvreMps;
    c.w_radps = -kManoeuvreMps / plan_.radius_m;
    // Parallel to the curb, or the car behind is close (by its laser, or by the slot's measured
    // rear end: the arcs run a little long when they start off straight): straighten up later, forwards.
    if (yaw <= 0.0 || bodyGapBehind(api, 0.35) < 0.35 ||
        rearClearanceM(slot_, api.car_length_m, api.car_width_m, x, y, yaw) < kArcRearClearM) {
      mode_ = Mode::Centre;
    }
  }

  // One line per phase, so a student can follow the manoeuvre in the terminal.
  void logPhase(const AutoparkApi& api, double x, double y, double yaw) {
    if (mode_ == logged_mode_) return;
    phase_start_s_ = t_;
    std::fprintf(stderr, "reactive [%.2f s]: %s at x %.2f y %.2f yaw %.1f deg%s%s\n", t_, name(mode_), x, y,
                 geometry::headingDeg(yaw), api.status.empty() ? "" : ": ", api.status.c_str());
    logged_mode_ = mode_;
  }

  void start(const AutoparkApi& api, double yaw) {
    car_ = {api.car_length_m, api.car_width_m, api.turn_centre_x_m, api.min_turn_radius_m};
    StreetSearch::Settings settings;
    settings.min_slot_length_m = api.car_length_m;  // shorter is no slot; longer ones the plan judges
    settings.turn_radius_m = std::max(kArcRadiusM, api.min_turn_radius_m);
    search_.emplace(api, settings);
    // Facing the other way (the parked cars on its left): turn round first.
    if (TurnRound::needed(yaw)) mode_ = Mode::Turn;
  }

  void planFor(AutoparkApi& api, const Slot& slot) {
    slot_ = slot;
    search_->holdLane(search_->laneYFor(slot.edge_y_m));
    plan_ = planTwoArcPark(slot, search_->laneY(), car_);
    if (!plan_.feasible && api.min_turn_radius_m <= 0) {
      // It turns in place: forward and back within the slot instead, if the slot holds the body
      // turned by the smallest angle with a margin at both ends.
      const double need = 2 * (halfExtentX(api, kZigzagMinRad) + kZigzagEndMarginM) + kZigzagMinTravelM;
      char line[160];
      if (slot.lengthM() < need) {
        std::snprintf(line, sizeof line, "slot too short for a multi-move park: %.1f m, need %.1f m", slot.lengthM(), need);
        api.status = line;
        mode_ = Mode::Declined;
        return;
      }
      zigzag_ = true;
      plan_.feasible = true;
      plan_.radius_m = kArcRadiusM;  // the centring's steering limit
      plan_.start_x_m = slot.centreXM();
      plan_.goal_y_m = slot.curb_y_m + (slot.curb_seen ? kCurbClearanceM : kZigzagFarSideClearanceM) + api.car_width_m / 2;
      std::snprintf(line, sizeof line, "slot %.1f m: a multi-move park, forward and back within it", slot.lengthM());
      api.status = line;
      mode_ = Mode::Approach;
      return;
    }
    if (!plan_.feasible) {
      api.status = plan_.why;
      mode_ = Mode::Declined;
      return;
    }
    char line[160];
    std::snprintf(line, sizeof line, "slot %.1f m: two arcs of R %.2f m from x %.2f", slot.lengthM(), plan_.radius_m,
                  plan_.start_x_m);
    api.status = line;
    mode_ = Mode::Approach;
  }

  // CENTRE: forward or back until the front and rear lasers see equal gaps, then say where it is.
  void centre(AutoparkApi& api, double x, double y, double yaw, double& v, double& w) {
    const double gap_front = bodyGapAhead(api, 0.15);
    const double gap_rear = bodyGapBehind(api, 0.15);
    if (centred(gap_front, gap_rear, yaw) || ++centre_moves_ > 2000) {  // never oscillate forever
      finish(api, x, y, yaw);
      return;
    }
    const Command c = centringCommand(gap_front, gap_rear, yaw, std::max(plan_.radius_m, api.min_turn_radius_m));
    v = c.v_mps;
    w = c.w_radps;
  }

  // The body's gap to what is ahead of (behind) it: the front (rear) laser's range within
  // half_width_rad of straight out, plus how far the laser sits beyond the body's end (0.4 m on
  // RoboticsAcademy's car: its lasers at +-2.4 m on a 4 m body; negative when inside it).
  static double bodyGapAhead(const AutoparkApi& api, double half_width_rad) {
    return rangeAhead(api.laser1.getLaserData(), half_width_rad) + std::abs(api.mount1.x_m) - api.car_length_m / 2;
  }
  static double bodyGapBehind(const AutoparkApi& api, double half_width_rad) {
    return rangeAhead(api.laser2.getLaserData(), half_width_rad) + std::abs(api.mount2.x_m) - api.car_length_m / 2;
  }

  // Half the body's extent along the street, and how far its lowest corner is below its centre,
  // turned by a (either way).
  static double halfExtentX(const AutoparkApi& api, double a) {
    return api.car_length_m / 2 * std::cos(a) + api.car_width_m / 2 * std::abs(std::sin(a));
  }
  static double lowestCornerBelow(const AutoparkApi& api, double a) {
    return api.car_length_m / 2 * std::abs(std::sin(a)) + api.car_width_m / 2 * std::cos(a);
  }
  // The steepest angle (of kZigzagMaxRad, in kZigzagStepRad steps down to kZigzagMinRad) that the
  // car may turn to at height y and still turn back at its next stop; 0 when none.
  double zigzagAngle(const AutoparkApi& api, double y) const {
    for (double a = kZigzagMaxRad; a >= kZigzagMinRad - 1e-9; a -= kZigzagStepRad) {
      const double travel = slot_.lengthM() - 2 * (halfExtentX(api, a) + kZigzagEndMarginM);
      if (travel >= kZigzagMinTravelM && y - lowestCornerBelow(api, a) >= slot_.curb_y_m + kZigzagCurbMarginM + 0.02) return a;
    }
    return 0.0;
  }

  // One period of the multi-move park (Mode::Zigzag): turning in place to the next move's angle,
  // or driving it (forward at -a goes down and ahead, reverse at +a down and back) until the body
  // is at the slot's end, or at the lowest height from which it can still turn back.
  void zigzag(AutoparkApi& api, double x, double y, double yaw, double& v, double& w) {
    const bool low_enough = y - plan_.goal_y_m < kZigzagDoneM;
    if (zig_turning_) {
      if (low_enough) zig_angle_ = 0;
      const double target = zig_forward_ ? -zig_angle_ : zig_angle_;
      const double error = geometry::wrapAngle(target - yaw);
      if (std::abs(error) > 0.01) {
        w = std::clamp(2.0 * error, -kZigzagTurnRadps, kZigzagTurnRadps);
        return;
      }
      if (low_enough) {
        mode_ = Mode::Centre;
        return;
      }
      zig_turning_ = false;
      return;
    }
    const double a = zig_angle_;
    const double reach = halfExtentX(api, a) + kZigzagEndMarginM;
    const double lowest_y = slot_.curb_y_m + kZigzagCurbMarginM + lowestCornerBelow(api, a);
    const bool at_end = zig_forward_ ? x >= slot_.front_x_m - reach : x <= slot_.rear_x_m + reach;
    const double ahead = zig_forward_ ? bodyGapAhead(api, 0.35) : bodyGapBehind(api, 0.35);
    if (at_end || y <= std::max(lowest_y, plan_.goal_y_m) || low_enough || ahead < 0.15) {
      ++zig_moves_;
      zig_forward_ = !zig_forward_;
      zig_turning_ = true;
      zig_angle_ = zig_moves_ > kZigzagMaxMoves ? 0.0 : zigzagAngle(api, y);
      if (zig_angle_ <= 0 && !low_enough) finish(api, x, y, yaw);  // no lower move left: say where it stands
      return;
    }
    v = zig_forward_ ? kZigzagMps : -kZigzagMps;
    w = std::clamp(2.0 * geometry::wrapAngle((zig_forward_ ? -a : a) - yaw), -0.3, 0.3);
  }

  // PARKED only in the slot and parallel to it; anything else is said as it is.
  void finish(AutoparkApi& api, double x, double y, double yaw) {
    char line[160];
    if (inSlot(slot_, plan_.goal_y_m, api.car_length_m, x, y, yaw)) {
      std::snprintf(line, sizeof line, "parked in the %.1f m slot", slot_.lengthM());
      mode_ = Mode::Parked;
    } else {
      std::snprintf(line, sizeof line, "not in the slot: ended at x %.2f y %.2f (the slot is x %.2f to %.2f, line y %.2f)",
                    x, y, slot_.rear_x_m, slot_.front_x_m, plan_.goal_y_m);
      mode_ = Mode::Failed;
    }
    api.status = line;
  }

  std::optional<StreetSearch> search_;
  CarShape car_;
  Slot slot_;
  TwoArcPlan plan_;
  Mode mode_ = Mode::Search, logged_mode_ = Mode::Parked;
  double t_ = 0;
  TurnRound turn_;
  bool zigzag_ = false, zig_turning_ = true, zig_forward_ = true;
  double zig_angle_ = kZigzagMaxRad;
  int zig_moves_ = 0;
  int centre_moves_ = 0;
  double phase_start_s_ = 0;  // sim time the present phase began
  double back_off_m_ = 0;     // > 0: backing off until this far behind the arcs' start
};

}  // namespace

std::unique_ptr<AutoparkAlgorithm> makeReactiveAlgorithm(uint64_t) { return std::make_unique<ReactiveParker>(); }

}  // namespace aula::autopark
