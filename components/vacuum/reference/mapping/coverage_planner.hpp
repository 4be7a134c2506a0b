#pragma once
// The mapping reference's coverage, on its own map (scan_map.hpp): which floor its disc has
// swept, straight lanes along the map's axes (boustrophedon), and the shortest way to the nearest
// floor not swept yet.
//
// A place is traversable when the map has seen it free and no wall is within clearance_m (the
// robot's radius and a margin). The nearest unswept place is found by Dijkstra on a coarser grid
// (plan_cell_m) from the robot outwards: a search to the nearest of many goals, which the
// TeleTaxi's gradient field (one goal, the whole field) is not; its path is then cut short
// wherever a straight segment stays traversable.

#include "scan_map.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace aula::vacuum::mapping {

struct CoverageSettings {
  // The centre keeps this far from walls (radius 0.165 + margin): 0.175 took the disc along
  // h2's 0.43 m corridor under a box with a centimetre to spare, where every glance on the box
  // pushed it along and the scans could not tell how far (lost in 3 runs of 10).
  double clearance_m = 0.185;
  double hug_clearance_m = 0.175; // ... but a lane along a wall, to sweep the strip beside it
  // Floor counted swept around the centre (the disc's is 0.165): at 0.15 every path left a
  // sliver along its sides that the plans went back for.
  double sweep_radius_m = 0.16;
  double plan_cell_m = 0.1;       // the nearest-unswept search's grid
  // Its relaxed search: through floor not seen yet, and nearer walls, but never a gap the disc
  // (0.33 m) barely fits: a robot that went in there was wedged between both sides (0.33 m; at
  // 0.17, h2's 0.34 m gap between two boxes).
  double relaxed_clearance_m = 0.18;
  // In the relaxed search, where the robot stands, the way out may pass its own bumps and walls
  // this near (the disc is there, so it fits): boxed in by its bumps in a gap beside a box, it
  // found no way anywhere and took the house for swept (d06-4x3 under realistic noise: all swept
  // at 416 s, 43 % covered). Only there: in every search it undid "never back there" of a wedge,
  // and h2 seed 10 went back into one for its last 494 s.
  double leave_m = 0.4;
  double leave_clearance_m = 0.15;
  // The nearest unswept floor worth a trip first: a frontier, or a block whose 3 x 3 blocks round
  // it hold this many unswept cells (0.02 m^2); slivers the lanes left (a sweep record a few
  // centimetres off under noise leaves many) only when there is nothing else. The first visit to a
  // room before a second pass over slivers (d09-3x2-large under noise: 57 % -> 75 %).
  int area_cells = 36;
};

// A block of the nearest-unswept search (CoveragePlanner::pathToUnswept): cells are indexed j * width + i.
struct PlanBlock {
  int rep = -2;   // its cell to go through, the farthest from walls; -1: not passable; -2: not looked at yet
  int goal = -1;  // its traversable cell farthest from walls, if any
  bool unswept = false, frontier = false;
  int unswept_cells = 0;  // its traversable cells not swept
};

struct Lane {
  Point2 end_m;           // the last unswept place along it
  double unswept_m = 0;   // how much of it is unswept
};

class CoveragePlanner {
 public:
  explicit CoveragePlanner(const ScanMap& map, const CoverageSettings& settings = {});

  const CoverageSettings& settings() const { return s_; }

  // The robot's centre is here: its disc sweeps around it. Returns the cells newly swept.
  int sweep(Point2 centre_m);
  void forget(Point2 p_m);      // give up on this place (unreachable): counted swept
  // Start a new pass over the floor nearer a wall than near_walls_m: the strips along walls that
  // lanes across the rooms leave, and the centres that sweep them.
  void resetSwept(double near_walls_m);
  bool swept(int i, int j) const { return map_.inside(i, j) && swept_[static_cast<size_t>(j) * map_.width() + i] != 0; }
  bool traversable(int i, int j) const {
    return map_.knownFree(i, j) && map_.clearanceM(i, j) >= s_.clearance_m && !bumped(i, j);
  }
  bool traversable(Point2 p_m) const { return traversable(map_.col(p_m.x_m), map_.row(p_m.y_m)); }
  // traversable() with another clearance.
  bool passable(Point2 p_m, double clearance_m) const {
    const int i = map_.col(p_m.x_m), j = map_.row(p_m.y_m);
    return map_.knownFree(i, j) && map_.clearanceM(i, j) >= clearance_m && !bumped(i, j);
  }
  // Every cell along a -> b traversable (passable at clearance_m if given), except within skip_m
  // of a (the robot may start close to a wall).
  bool segmentClear(Point2 a_m, Point2 b_m, double skip_m = 0, double clearance_m = -1) const;

  // Something the laser does not see was bumped at p_m: no plan goes within clearance_m of it
  // until until_s. Not a wall on the map: a bump placed wrong (a side contact, a pose a little
  // off) would close a passage for good, and the scans would be matched against it.
  void addBump(Point2 p_m, double until_s);
  void expireBumps(double now_s);
  bool bumped(int i, int j) const { return map_.inside(i, j) && bump_count_[static_cast<size_t>(j) * map_.width() + i] != 0; }

  // Straight from `from` along the axis (dx, dy) (one of +-x, +-y) while traversable.
  Lane lane(Point2 from_m, int dx, int dy) const;
  // The same along a wall on the side (wall_dx, wall_dy), passable at clearance_m: what counts
  // is the floor strip_m towards the wall, which the disc sweeps and the robot's centre never
  // crosses.
  Lane wallLane(Point2 from_m, int dx, int dy, int wall_dx, int wall_dy, double clearance_m, double strip_m) const;
  // A lane along (dx, dy) beside a wall on the side (wall_dx, wall_dy) of from_m: its start is
  // the farthest place that way, max_m to min_m off, passable at hug_clearance_m and in a clear
  // line from from_m (and with the wall right beyond it if wall_beyond); the lane is wallLane()'s
  // from there. Lane::unswept_m 0: none.
  std::pair<Point2, Lane> besideWall(Point2 from_m, int wall_dx, int wall_dy, int dx, int dy, double max_m,
                                     double min_m, double strip_m, bool wall_beyond) const;
  // Waypoints to the nearest traversable place that is unswept or next to floor not seen yet (a
  // frontier), through traversable places (relaxed: see CoverageSettings); empty if there is none.
  // worth_a_trip: only a frontier or an area (CoverageSettings::area_cells), no sliver.
  std::vector<Point2> pathToUnswept(Point2 from_m, bool relaxed = false, bool worth_a_trip = false) const;
  // A block of k x k cells from corner (bi, bj), for the nearest-unswept search; leaving: it is
  // where the robot stands or next to it, in the relaxed search (CoverageSettings::leave_m).
  PlanBlock planBlock(int bi, int bj, int k, bool relaxed, bool leaving = false) const;
  // The traversable place nearest to `from` within radius_m (the robot pushed too close to a wall
  // gets out that way); `from` itself if there is none.
  Point2 nearestTraversable(Point2 from_m, double radius_m) const;

 private:
  const ScanMap& map_;
  CoverageSettings s_;
  std::vector<uint8_t> swept_;
  std::vector<std::pair<int, int>> disc_;  // cell offsets within sweep_radius_m
  struct Bump {
    int i, j;
    double until_s;
  };
  void stampBump(const Bump& b, int delta);
  bool planPassable(int i, int j, bool relaxed, bool leaving) const;
  bool nextToUnknown(int i, int j, int k) const;
  std::vector<Bump> bumps_;
  std::vector<uint8_t> bump_count_;        // how many bumps' discs cover each cell
  std::vector<std::pair<int, int>> bump_disc_;  // cell offsets within clearance_m
};

}  // namespace aula::vacuum::mapping
