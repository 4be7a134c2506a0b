#pragma once
// The vacuum's reference, the mapping cleaner (--algorithm=reference; the thesis's spiral, walls
// and bounces is --algorithm=classic): it maps the house from its own laser and plans its
// coverage, with the student API alone (yaw, laser, bumper, motors; no x, y):
//   localize  predict from its own speed commands along the measured yaw, then match each scan
//             against the map so far (ScanMap::match) within a gate that grows with the way
//             driven since the last fix, and draw it in (ScanMap::insert);
//   cover     lanes along the map's axes, a sidestep of lane_spacing_m at each end and back
//             (boustrophedon), the first and last of a run along walls, and a lane along a wall
//             goes on round the corner along the next; where no lane is left, the way to the
//             nearest unswept floor worth a trip (CoveragePlanner), slivers only when none is
//             left; when all is swept, a second pass over
//             the floor near walls, along them;
//   recover   a bump backs off (forward if backing off bumps) and keeps the plans away from the
//             spot for a while; a poor match keeps the prediction and widens the next search,
//             where only a clearly better fit, driving straight and not pressed on anything,
//             may move the estimate beyond the gate;
//             nothing new swept for no_fresh_s: out by the laser; bumped wedge_bumps times in
//             one spot (wedged in a gap): back out along its own trail, and never back there;
//             wedged there again: a move on an arc or a turn per bump, each way in turn (wiggle).

#include "coverage_planner.hpp"
#include "scan_map.hpp"

#include <aula/vacuum/vacuum_algorithm.hpp>

#include <deque>
#include <memory>
#include <random>
#include <vector>

namespace aula::vacuum::mapping {

struct MappingSettings {
  double max_speed_mps = 0.5;
  double laser_forward_m = 0.139;     // the roomba's laser, ahead of its centre (worlds/models/roomba)
  double footprint_m = 0.15;          // the floor under the robot, drawn free (a bit inside its 0.165 m)
  // Localization.
  double match_range_m = 9.0;         // beams beyond this are not matched
  int match_stride = 3;               // every third beam
  double track_window_m = 0.05;       // the least gate (how far a fit may move the estimate)...
  double gate_sigmas = 2.5;           // ... or this many times the estimate's uncertainty, per axis:
  double slip_per_m = 0.03;           // ... growing this much a metre driven along that axis...
  double pressed_sigma_m = 0.001;     // ... and this much a period pressed on something,
  double fixed_sigma_m = 0.01;        // ... and this after a fit that sharpens the axis
  double lost_window_m = 0.3;         // the widest search (after a poor match) and the widest gate
  double good_match = 0.75;           // mean match field a scan needs to correct the pose
  double map_good_match = 0.85;       // ... and to be drawn into the map, where an axis the scan
  double insert_sigma_m = 0.02;       // ... does not sharpen is known this well (one sigma)
  double min_sharpness = 0.03;        // a match this much better than 5 cm off, along x (y), fixes x (y)
  // Turning, a scan's yaw is known only as well as its timing: a few hundredths of a radian
  // turn it about the laser, and a turned scan fits a wall nearby better shifted.
  double match_max_w_radps = 0.25;    // turning faster than this: prediction only
  double map_max_w_radps = 0.15;      // ... and drawn into the map only below this
  double jump_margin = 0.08;          // a correction beyond the gate only when its fit beats the best within by this...
  double jump_max_w_radps = 0.05;     // ... driving this straight
  double jump_min_explained = 0.6;    // ... and a share of the scan's points on walls the map has seen...
  double jump_agree_m = 0.03;         // ... and the same offset from the prediction (this close)...
  int jump_confirm_scans = 3;         // ... in this many scans in a row
  double map_every_m = 0.1;           // draw a scan after moving this far...
  double map_every_rad = 0.3;         // ... or turning this much
  // Coverage.
  double lane_spacing_m = 0.28;       // the disc is 0.33 m: lanes overlap by 5 cm
  double min_hug_m = 0.075;           // a lane along a wall only this far beside the last lane, or more
  double max_slide_m = 0.5;           // a new run of lanes starts at a wall this near beside it
  double hug_strip_m = 0.1;           // ... and its floor this far towards the wall still unswept
  double corner_reach_m = 0.05;       // a wall ahead this near at a lane's end: round the inner corner
  double corner_past_m = 0.25;        // the side's wall ended: this far on, and round its end
  double min_lane_m = 0.3;            // a shorter unswept run is not worth a lane
  double lane_choice = 0.7;           // a new lane: any way with this share of the longest's unswept floor
  double arrive_m = 0.015;            // a lane's end is the wall's: every centimetre short is floor left
  double beside_m = 0.05;             // ... or this near with the waypoint behind
  double turn_in_place_rad = 0.25;    // heading errors above this turn on the spot
  double turn_gain_per_s = 5.0;       // turning on the spot was a quarter of the time at 3 and 2.5 rad/s
  double turn_min_radps = 0.6;
  double turn_max_radps = 3.0;
  double steer_max_radps = 1.0;
  double approach_gain_per_s = 3.0;  // slowing down from 0.13 m off: the motors stop it within 3 cm
  double approach_min_mps = 0.1;
  double follow_min_mps = 0.2;        // the deadline assumes at least this speed, plus...
  double follow_slack_s = 6.0;        // ... this long
  // Recovery.
  double backoff_mps = 0.12;
  double backoff_s = 0.5;
  double bump_ahead_m = 0.2;          // a bump straight ahead blocks the plans this far ahead of the centre...
  double side_bump_rad = 0.8;         // ... or this far round to the bumper's side...
  double bump_known_m = 0.1;          // ... unless the map has a wall this close to that point...
  double bump_memory_s = 60;          // ... for this long
  int goal_bumps = 2;                 // bumps on the way to one goal before it is given up...
  double same_goal_m = 0.1;           // ... a goal this close to the last one being the same
  double stuck_s = 3.0;               // no progress this long while following: give up the goal
  double stuck_m = 0.05;
  double escape_radius_m = 0.5;       // too close to a wall: the nearest traversable place within this
  int escape_half_beams = 8;          // no way out on the map: the laser's most open +-8 beams...
  double escape_run_m = 0.8;          // ... this far at most...
  double escape_margin_m = 0.4;       // ... stopping this short of what it sees there;
  double escape_min_m = 0.1;          // shorter than this: it backs out instead
  double second_pass_m = 0.3;         // the second pass: floor this near walls only
  int wedge_bumps = 8;                // this many bumps within wedge_window_s...
  double wedge_window_s = 30;         // ...
  double wedge_m = 0.3;               // ... all this near one another: wedged. Out along its own trail
  double unwedge_m = 1.0;             // this far, and the plans never go back there
  double wiggle_s = 1.0;              // wedged there again: moves on arcs and turns this long...
  double wiggle_radps = 1.5;          // ... turning this fast
  double trail_step_m = 0.1;          // the trail: where it has been, a point this far apart
  int fresh_cells = 4;                // an execute() sweeping this many new cells (2.5 cm) is progress...
  double no_fresh_s = 40;             // ... and none for this long, while following plans, is not
};

class MappingReference : public VacuumAlgorithm {
 public:
  // seed: draws the lanes' directions where several are about as long (aula run --seed).
  explicit MappingReference(uint64_t seed = 1, const MappingSettings& settings = {});
  void execute(VacuumApi& api) override;

  // For the window and the tests: the map, what is swept, and where it thinks it is (the map's
  // frame: the start is the origin, axes the world's).
  const ScanMap& map() const { return map_; }
  const CoveragePlanner& coverage() const { return coverage_; }
  Point2 estimate() const { return est_; }
  const std::vector<Point2>& waypoints() const { return waypoints_; }
  int passes() const { return passes_; }

 private:
  enum class Mode { Spin, Follow, Backoff };
  void localize(const component::LaserData& scan, double yaw_rad, bool bumped);
  void correct(const component::LaserData& scan, double yaw_s, Point2 predicted, double w_max, bool pressed);
  bool confirmJump(const ScanMatch& m, Point2 predicted, size_t points, double w_max, bool pressed);
  void spin(double yaw, double& w);
  void onBump(int bumper, double yaw);
  void decide();
  void follow(double yaw_rad, double& v, double& w);
  void enterFollow(std::vector<Point2> waypoints);
  bool sidestep(Point2 p);
  void secondPass(Point2 p);
  bool newLane(Point2 p);
  bool hugWall(Point2 p);
  bool startAtWall(Point2 p);
  bool roundTheCorner(Point2 p);
  bool wedged(Point2 p);
  void backOff(double& v, double& w);
  void wiggle();
  bool unwedge();
  void escapeByLaser();
  void tellBelief(VacuumApi& api);

  MappingSettings s_;
  ScanMap map_;
  CoveragePlanner coverage_;
  Mode mode_ = Mode::Spin;
  // Localization.
  Point2 est_;               // the robot's centre now
  int64_t n_ = 0;            // execute() calls
  double period_s_ = 0;
  double clock_offset_s_ = 0, now_s_ = 0, last_now_s_ = 0;
  bool clock_started_ = false;
  int64_t last_stamp_ = -1;
  double last_yaw_ = 0, cmd_v_ = 0, cmd_w_ = 0, prev_cmd_w_ = 0;
  int poor_matches_ = 0;
  double sigma_x_m_ = 0, sigma_y_m_ = 0;  // how far off the estimate may be, per axis (one sigma)
  int jump_count_ = 0;       // scans in a row that found the same far correction...
  Point2 jump_offset_;       // ... this one (from the prediction)
  bool mapped_once_ = false;
  Point2 last_insert_;
  double last_insert_yaw_ = 0;
  // Coverage.
  std::vector<Point2> waypoints_;
  int lane_dx_ = 0, lane_dy_ = 0, side_ = 1;
  bool on_lane_ = false;
  bool hugging_ = false;     // on a lane along a wall (hug_clearance_m from it)...
  int wall_dx_ = 0, wall_dy_ = 0;  // ... on this side
  double mode_start_s_ = 0, deadline_s_ = 0;
  Point2 progress_at_;
  double progress_s_ = 0;
  int spin_quarters_ = 0, spin_hold_ = 0;
  double spin_target_ = 0;
  int passes_ = 1;
  const component::LaserData* scan_ = nullptr;  // this execute()'s
  double yaw_ = 0;
  bool escaping_ = false;
  double backoff_v_ = 0, backoff_end_s_ = -1e9;
  Point2 last_bump_m_{1e9, 1e9};  // where the last bump moving forward was
  int goal_bumps_ = 0;       // bumps on the way to...
  Point2 bumped_goal_;       // ... this goal
  std::deque<std::pair<double, Point2>> recent_bumps_;  // (when, where) within wedge_window_s
  bool unwedge_ = false;     // wedged: out along the trail at the next decision
  int wedge_repeats_ = 0;    // wedged this many times in a row at...
  Point2 last_wedge_m_{1e9, 1e9};  // ... this spot
  int wiggle_step_ = 0;      // the next of wiggle()'s moves
  double backoff_w_ = 0;     // a wiggle's turn while backing off
  std::deque<Point2> trail_;  // where it has been, the newest last
  double fresh_s_ = 0;  // when the last execute() swept new floor
  double last_reset_s_ = -1e9;
  // What it tells of its belief (api.belief): where it has been, and when its map goes next.
  Point2 visited_min_, visited_max_;
  double next_belief_map_s_ = 0;
  std::mt19937_64 rng_;
};

std::unique_ptr<VacuumAlgorithm> makeMappingReferenceAlgorithm(uint64_t seed);

}  // namespace aula::vacuum::mapping
