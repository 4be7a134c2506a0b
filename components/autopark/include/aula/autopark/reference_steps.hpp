#pragma once
// The references' decisions, each a small function on plain numbers (no API, no LCM), so a
// student can read one step at a time and a test can check it alone. ReactiveParker.cpp and
// PlannedParker.cpp call these at each control period.

#include <aula/autopark/parking_planner.hpp>
#include <aula/autopark/slot_detector.hpp>

namespace aula::autopark {

// All three lasers and the pose have come in: nothing is decided on half the picture (the one
// step that reads the API).
bool sensorsReady(const AutoparkApi& api);

// ---- the reactive reference (two arcs, or a multi-move park) --------------------------------

// Stopped at the arcs' start: on the spot along the street (5 cm), on the lane (0.3 m), straight (0.05 rad).
bool atArcStart(double to_go_m, double y_m, double lane_y_m, double yaw_rad);
// The approach's speed to a point `to_go_m` ahead (behind when negative): slowing as it nears,
// never so slow that friction stops it short.
double approachSpeed(double to_go_m, double cruise_mps, double reverse_mps);
// At the arcs' start but off the lane (0.3 m): a car steers no tighter than its radius, so it
// cannot close that offset on the spot; it must back off along the lane and come again.
bool arrivedOffLane(double to_go_m, double off_lane_m);
// How far behind the arcs' start to back off to close an offset of `off_lane_m` on the way back:
// the lane keeping needs about four metres of street per metre of offset, plus a car's length.
double runUpM(double off_lane_m);
// The first arc ends once what is left of the lateral offset is what the second arc removes,
// R (1 - cos yaw), or once it has turned a little more than planned.
bool firstArcDone(double remaining_m, double radius_m, double yaw_rad, double arc_rad);
// The centring command: forward or back towards equal gaps front and rear, straightening on the way
// (the yaw follows the sign of the motion); `radius_m` is the steering limit.
struct Command {
  double v_mps = 0, w_radps = 0;
};
Command centringCommand(double gap_front_m, double gap_rear_m, double yaw_rad, double radius_m);
// Reversing into the slot, how far the body's rearmost corner below the parked cars' side line
// is from the slot's measured rear end (the car behind), at (x, y, yaw); infinity when no corner
// is that low. The rear laser cannot say it: on RoboticsAcademy's car it sits 0.4 m behind the
// body, so it sees nothing nearer the body than that.
double rearClearanceM(const Slot& slot, double length_m, double width_m, double x_m, double y_m, double yaw_rad);
// Centred: equal gaps within 0.1 m, parallel within 0.03 rad.
bool centred(double gap_front_m, double gap_rear_m, double yaw_rad);
// In the slot and parallel to it: the body within the slot's ends (10 cm grace), on its line
// within 0.4 m, within 0.1 rad.
bool inSlot(const Slot& slot, double goal_y_m, double car_length_m, double x_m, double y_m, double yaw_rad);

// ---- the planned reference (a map, OMPL, a tracker) ------------------------------------------

// How far the car is past the slot's far end in the direction of the search (+1: +x).
double pastSlotM(const Slot& slot, int direction, double x_m);
// The planning grid's extent: the street around the car and the slot, 12 m beyond either, never
// beyond what the lasers mapped; from the slot's line (the curb, or the parked cars' far side where
// the lasers do not see the curb: the plan never takes the body below it) to a few metres above the lane.
MappedStreet planningExtent(const MappedStreet& mapped, const Slot& slot, double x_m, double y_m, double lane_y_m,
                            double car_width_m);
// The planner's options for attempt `attempt` (0: the first): after a failure, finer escape moves
// and a lower clearance in the slot, since the lasers' map puts the cars' ends a cell nearer.
ParkingPlannerOptions planOptions(unsigned seed, int attempt);
// The box the car's body sweeps along `path` (for the log: the plan stays on the street).
MappedStreet bodyExtent(const PlannedPath& path, const CarGeometry& car, const MappedStreet& start);

}  // namespace aula::autopark
