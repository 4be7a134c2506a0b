#pragma once
// Finds a free parking slot beside the curb from laser scans, with no map given: every laser
// point to the right of the car goes into a profile along the street (x bins); a bin whose
// nearest point to the lane is well below the parked cars' side sees the curb, so it is free.
// Where no beam sees a curb (lasers above it, as on RoboticsAcademy's street), a bin that beams
// with no echo crossed well below the cars' side is free, and the slot's curb line is the parked
// cars' far side: the deeper of the bottoms of the end faces of the cars either side of it, each
// its deepest echo once a beam with no echo passed within 0.1 m below it. A slot is reported only
// once a bottom is known: a face seen in part (out of range, or hidden behind the car before the
// slot) would place the car too high, and a guessed car width too low.
// A slot is a run of free bins bounded by parked cars at both ends (not the wall at a street's end).
// Assumes the street runs along x with the parking side at -y, as in the Autopark worlds.

#include <aula/autopark/autopark_algorithm.hpp>
#include <aula/component/devices.hpp>

#include <optional>
#include <vector>

namespace aula::autopark {

struct Slot {
  double rear_x_m = 0;   // end of the parked car behind the slot (smaller x)
  double front_x_m = 0;  // start of the parked car ahead of it
  double curb_y_m = 0;   // the curb face seen inside the slot, else the parked cars' far side
  double edge_y_m = 0;   // the parked cars' side nearest the lane
  bool curb_seen = false;  // curb_y_m is a curb the lasers saw; false: the parked cars' far side
  double lengthM() const { return front_x_m - rear_x_m; }
  double centreXM() const { return (rear_x_m + front_x_m) / 2; }
};

class SlotDetector {
 public:
  // min_length_m: the shortest slot worth reporting (the car's length plus a margin).
  explicit SlotDetector(double min_length_m, double bin_m = 0.05, double from_x_m = -100, double to_x_m = 100);

  // One scan from a laser at `mount` on a car at (x, y, yaw).
  void addScan(double car_x_m, double car_y_m, double car_yaw_rad, const LaserMount& mount,
               const component::LaserData& scan);
  void addPoint(double x_m, double y_m);  // a point of the parking side (world frame)
  void addFreePoint(double x_m, double y_m);  // a point a beam with no echo passed (world frame)
  // A point a beam with no echo passed just below an echo at the same x (world frame): the upright
  // face there (a parked car's end) ends above it.
  void addPassBelowAFace(double x_m, double y_m);

  // The bounded slot nearest to near_x_m, if one has been seen.
  std::optional<Slot> slot(double near_x_m) const;
  std::optional<double> edgeY() const;  // the parked cars' side, once both it and the curb are seen
  double minLengthM() const { return min_length_m_; }

 private:
  int binOf(double x_m) const;
  // The line of the slot between occupied bins b and e (the curb, or the cars' far side) into
  // s.curb_y_m and s.curb_seen; false while neither is known.
  bool placeLine(Slot& s, int b, int e, double edge_y) const;
  // The bottom of the end face in the bins around `face`, once it is known within 0.1 m.
  std::optional<double> faceBottom(int face) const;
  double min_length_m_, bin_m_, from_x_m_;
  std::vector<double> nearest_y_;  // per bin: the highest y seen (nearest the lane); NaN = unseen
  std::vector<double> lowest_y_;   // per bin: the lowest echo's y (a car's end face reaches its far side)
  std::vector<double> passed_below_y_;  // per bin: the highest y a beam with no echo passed below a face's echo
  std::vector<double> free_y_;     // per bin: the lowest y a beam with no echo passed; NaN = none
};

}  // namespace aula::autopark
