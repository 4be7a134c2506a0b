#pragma once
// Parallel-parking planner: OMPL Reeds-Shepp planning (RRTConnect) from the start to an "escape"
// pose, plus the reversed deterministic escape (un-parking) manoeuvre from the goal pose in the
// slot. See docs/planner.md for the method and measurements.

#include <aula/autopark/car_geometry.hpp>
#include <aula/autopark/occupancy_grid.hpp>

#include <string>
#include <vector>

namespace aula::autopark {

struct PlannedPath {
  bool solved = false;
  std::vector<Pose2D> poses;            // car CENTRE poses, start .. goal, <= Options::output_step_m apart (rear axle)
  std::vector<int> direction;           // per pose: +1 forward, -1 reverse (motion arriving at the pose;
                                        // pose 0 takes the first motion's); a change marks a cusp
  std::vector<double> curvature_per_m;  // per pose: signed rear-axle curvature dyaw/ds of that motion
                                        // (|k| <= 1 / min_turn_radius_m)
  int cusps = 0;                        // direction changes
  double length_m = 0.0;                // rear-axle path length
  double planning_time_s = 0.0;
  double escape_time_s = 0.0;           // of planning_time_s: the escape search
  double escape_clearance_m = 0.0;      // clearance the escape (in-slot) part was planned with
  int escape_moves = 0;                 // moves of the (reversed) escape manoeuvre at the end of the path
  std::string message;                  // why not solved (empty when solved)
};

struct ParkingPlannerOptions {
  double time_limit_s = 1.0;  // whole plan() call, escape + OMPL
  unsigned seed = 1;          // same seed + same inputs -> same path (see docs/planner.md)
  double clearance_m = 0.15;  // footprint inflation against occupied cells
  bool use_escape = true;     // false: plain RRTConnect from start to goal (comparison only)
  // Escape search (hybrid A* from the goal pose out of the slot):
  double min_slot_clearance_m = 0.05;   // the escape may lower the clearance down to this in the slot
  double slot_clearance_step_m = 0.05;  // ... in these steps (0: never lower it)
  double escape_step_m = 0.04;          // rear-axle step of the escape moves (collision checked at each)
  double escape_move_m = 0.5;           // longest single search move
  double escape_cell_m = 0.05;          // duplicate-detection cell, x and y
  double escape_cell_yaw_rad = 0.0175;  // ... and yaw (1 degree)
  double escape_cusp_cost_m = 1.0;      // cost of a direction change, metres of driving
  double escape_steer_change_cost_m = 0.1;
  double escape_heuristic_weight = 10.0;
  int escape_max_expansions = 20000;
  double exit_lateral_m = 2.0;      // escape ends once the centre is this far sideways from the goal
  double exit_margin_m = 0.3;       // ... and the footprint is this much beyond clearance_m from obstacles
  double motion_check_step_m = 0.03;  // OMPL state-validity resolution along motions, metres
  double range_m = 0.0;             // RRTConnect range; 0 = OMPL default
  bool deterministic_nn = true;     // NearestNeighborsLinear (repeatable); false: OMPL default (GNAT, unseeded)
  double output_step_m = 0.05;      // spacing of PlannedPath::poses
  bool quiet = true;                // lower OMPL's log level to warnings (process-wide)
  // true: the budgets are counts only (escape_max_expansions, rrt_max_checks), never the wall clock,
  // so the same inputs give the same path however loaded the machine is (the references: sim time
  // is their only clock); time_limit_s is then not applied.
  bool repeatable = false;
  int rrt_max_checks = 20000;       // repeatable: RRTConnect gives up once it has asked this often whether to stop
};

// The part of the street the lasers have mapped (axis-aligned, the street along x).
struct MappedStreet {
  double min_x_m = 0, max_x_m = 0, min_y_m = 0, max_y_m = 0;
  bool contains(const geometry::OrientedBox& box) const;
};
// Why `path` leaves `street` ("leaves the mapped street at x 31.20 y 2.10 (mapped x -20.00 to
// 30.00, y -4.30 to 5.00)": its first pose whose footprint is not inside it), or "" when it stays in.
std::string pathLeavesStreet(const PlannedPath& path, const CarGeometry& car, const MappedStreet& street);

class ParkingPlanner {
 public:
  using Options = ParkingPlannerOptions;


  explicit ParkingPlanner(CarGeometry car = {}, Options options = {});

  // start and goal are car CENTRE poses. Not thread-safe w.r.t. OMPL's global log level only.
  PlannedPath plan(const OccupancyGrid& grid, const Pose2D& start_centre, const Pose2D& goal_centre) const;

  const CarGeometry& car() const { return car_; }
  const Options& options() const { return options_; }

 private:
  CarGeometry car_;
  Options options_;
};

}  // namespace aula::autopark
