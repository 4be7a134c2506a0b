#pragma once
// Driving down the street looking for a slot, shared by the reference solutions: feeds the three
// scans to a SlotDetector, keeps a lane a safe distance from the parked cars (car-like steering,
// |w| <= |v| / R) and turns back at the street's end, as a car reverses down a street.

#include <aula/autopark/autopark_algorithm.hpp>
#include <aula/autopark/slot_detector.hpp>

#include <optional>

namespace aula::autopark {

// The minimum range of a laser over the beams within +-half_width_rad of straight out.
double rangeAhead(const component::LaserData& scan, double half_width_rad);
// The nearest echo straight ahead of a laser within a band `half_width_m` either side of its
// axis (the car's width), metres; the laser's max range when nothing is there.
double clearanceAhead(const component::LaserData& scan, double half_width_m);

// A start facing the wrong way (the parked cars on the car's left): turn round to face +x before
// searching, on the spot for a car that turns in place, or in the legs of a three-point turn for a
// car-like one (forward steering one way, back steering the other, each leg until something is
// near ahead or behind).
class TurnRound {
 public:
  static bool needed(double yaw_rad);  // facing more than 90 degrees away from +x
  // One period: the command, and true once facing +x (the lane keeping straightens what is left).
  bool step(const AutoparkApi& api, double yaw_rad, double& v_mps, double& w_radps);

 private:
  static constexpr double kTurnMps = 0.8, kTurnRadps = 0.6;
  static constexpr double kClearanceM = 0.8;  // a leg ends this close to something
  bool forward_ = true;
};

class StreetSearch {
 public:
  struct Settings {
    double min_slot_length_m = 4.8;   // the shortest slot worth reporting
    double lane_clearance_m = 1.0;    // between the parked cars' side and the car's side
    double turn_radius_m = 5.0;       // steering never tighter than this
    double cruise_mps = 2.0, reverse_mps = 1.5;
    double street_end_m = 4.0;        // turn back when something across the lane is this close ahead of the car (street_end.hpp)
  };
  StreetSearch(const AutoparkApi& api, Settings settings);

  // The three scans at the car's pose (x, y, yaw) go into the detector.
  void addScans(const AutoparkApi& api, double x_m, double y_m, double yaw_rad);
  // One period of searching: the command that keeps the car going, and the slot once seen.
  struct Step {
    double v_mps = 0, w_radps = 0;
    std::optional<Slot> slot;
  };
  Step search(const AutoparkApi& api, double x_m, double y_m, double yaw_rad);
  // The search has driven the whole street both ways (turned back at both ends) and seen no slot:
  // driving on would only repeat it.
  bool exhausted() const { return reversals_ >= 2; }
  // Steering that brings the car to the lane line, for a given speed (either sign).
  double keepLane(double v_mps, double y_m, double yaw_rad) const;
  // Fix the lane line (once a manoeuvre has been planned from it).
  void holdLane(double lane_y_m) { lane_y_m_ = lane_y_m; lane_held_ = true; }
  double laneY() const { return lane_y_m_; }
  double laneYFor(double edge_y_m) const { return edge_y_m + settings_.lane_clearance_m + car_width_m_ / 2; }
  const SlotDetector& detector() const { return detector_; }
  int direction() const { return direction_; }

 private:
  Settings settings_;
  SlotDetector detector_;
  double car_width_m_;
  double lane_y_m_;
  bool lane_held_ = false;
  int direction_ = 1;
  int reversals_ = 0;  // turns back at a street's end
};

}  // namespace aula::autopark
