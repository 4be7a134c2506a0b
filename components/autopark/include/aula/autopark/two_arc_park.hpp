#pragma once
// The reactive reference's manoeuvre, planned for the slot the lasers measured (plain data, no
// LCM): from the lane, two equal arcs of radius R of the point the car turns about (its centre,
// or its rear axle for a car-like car) bring it parallel into the slot; it then drives straight to
// the slot's centre. The car's footprint is swept along the arcs against the parked cars and the
// curb as measured, for every end point in the slot and, for a car that turns in place, for
// radii from 5 m down to 2.5 m. A slot with no clear manoeuvre is declined, with the length the
// same street would need.

#include <aula/autopark/slot_detector.hpp>

#include <string>

namespace aula::autopark {

struct CarShape {
  double length_m = 4.0, width_m = 2.0;
  double turn_centre_x_m = 0.0;    // body-frame x of the point it turns about
  double min_turn_radius_m = 0.0;  // 0: it turns in place
};

struct TwoArcPlan {
  bool feasible = false;
  double radius_m = 0;   // of the arcs the turning point follows
  double arc_rad = 0;    // each arc turns the car by this much
  double lane_y_m = 0;   // the car's centre line before the arcs
  double goal_y_m = 0;   // and after them: the slot's line
  double start_x_m = 0;  // the car's centre where the arcs start (facing +x)
  double end_x_m = 0;    // and where they end, in the slot
  double needed_length_m = 0;  // not feasible: the shortest slot of this street it would take
  std::string why;             // not feasible: "slot too short for a reactive park: 5.0 m, need 5.9 m"
};

// Clearance kept between the swept footprint and the parked cars or the curb.
constexpr double kSweepMarginM = 0.15;
// The car's side ends up this far from the slot's line (the curb, or the parked cars' far side):
// in the second arc the rear corner dips below where the side ends, and must clear the line.
constexpr double kCurbClearanceM = 0.45;

// The plan for `slot`, starting from the lane line `lane_y_m`.
TwoArcPlan planTwoArcPark(const Slot& slot, double lane_y_m, const CarShape& car);

// Whether the footprint swept along the two arcs of radius `radius_m` from (start, lane_y) to
// (end_x, goal_y) stays `margin_m` clear of the slot's two cars and its curb.
bool twoArcSweepClear(const Slot& slot, double lane_y_m, double goal_y_m, double radius_m, double end_x_m,
                      const CarShape& car, double margin_m = kSweepMarginM);

}  // namespace aula::autopark
