#pragma once
// Follows a PlannedPath segment by segment (a segment = poses between cusps, driven forward or in
// reverse), stopping at every cusp. Control: rear-wheel-feedback law on the rear axle
// (feed-forward curvature + heading and lateral error feedback), |w| <= |v| / R.
// Kinematic model assumed: rear-axle bicycle -- the rear axle moves along the heading at v and the
// body turns at w about a point on the rear-axle line (see docs/planner.md, "Integration").

#include <aula/autopark/car_geometry.hpp>
#include <aula/autopark/parking_planner.hpp>

#include <cstddef>
#include <vector>

namespace aula::autopark {

struct PathTrackerOptions {
  double forward_speed_mps = 1.0;
  double reverse_speed_mps = 0.7;   // magnitude
  double min_speed_mps = 0.1;       // crawl speed at the end of a segment
  double decel_mps2 = 0.5;          // v <= sqrt(2 a d) with d the distance left in the segment
  double k_lateral = 1.0;           // 1/m^2
  double k_heading = 2.0;           // 1/m
  double segment_end_tolerance_m = 0.01;
  int search_window = 40;           // poses looked ahead for the nearest one
};

class PathTracker {
 public:
  using Options = PathTrackerOptions;
  struct Command {
    double v_mps = 0.0;    // longitudinal speed, negative = reverse
    double w_radps = 0.0;  // yaw rate, |w| <= |v| / min_turn_radius_m
    bool done = false;     // end of the path reached (v = w = 0)
  };

  PathTracker(const PlannedPath& path, CarGeometry car = {}, Options options = {});

  // current_centre: the car's true centre pose. Call at a fixed rate (e.g. every 0.05 s).
  Command update(const Pose2D& current_centre);

  bool done() const { return done_; }
  int segment() const { return segment_; }          // index of the segment being driven
  int segmentCount() const { return static_cast<int>(segments_.size()); }
  double lateralError_m() const { return last_lateral_error_m_; }

 private:
  struct Segment {
    int begin, end;  // inclusive pose indices
    int dir;
  };
  CarGeometry car_;
  Options opt_;
  std::vector<Pose2D> rear_;      // rear-axle poses
  std::vector<double> s_;         // cumulative rear-axle arc length
  std::vector<double> kappa_;
  std::vector<Segment> segments_;
  int segment_ = 0;
  int index_ = 0;
  bool done_ = false;
  double last_lateral_error_m_ = 0.0;
};

}  // namespace aula::autopark
