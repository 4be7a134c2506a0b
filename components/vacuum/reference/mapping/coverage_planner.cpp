#include "coverage_planner.hpp"
#include "plan_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace aula::vacuum::mapping {
namespace {
constexpr int kMinUnsweptCells = 3;  // of a block's: fewer is a sliver, not worth a trip
constexpr int kWallReachCells = 8;   // a lane goes on to the wall if it is this near (0.2 m) beyond its unswept floor
}  // namespace

CoveragePlanner::CoveragePlanner(const ScanMap& map, const CoverageSettings& settings)
    : map_(map), s_(settings), swept_(static_cast<size_t>(map.width()) * map.width(), 0),
      bump_count_(swept_.size(), 0) {
  const auto disc = [&](double radius_m) {
    std::vector<std::pair<int, int>> out;
    const int reach = static_cast<int>(std::ceil(radius_m / map.cellM()));
    for (int dj = -reach; dj <= reach; ++dj) {
      for (int di = -reach; di <= reach; ++di) {
        if (std::hypot(di, dj) * map.cellM() <= radius_m) out.emplace_back(di, dj);
      }
    }
    return out;
  };
  disc_ = disc(s_.sweep_radius_m);
  bump_disc_ = disc(s_.clearance_m);
}

int CoveragePlanner::sweep(Point2 centre_m) {
  const int i = map_.col(centre_m.x_m), j = map_.row(centre_m.y_m);
  int fresh = 0;
  for (const auto& [di, dj] : disc_) {
    if (!map_.inside(i + di, j + dj)) continue;
    uint8_t& cell = swept_[static_cast<size_t>(j + dj) * map_.width() + i + di];
    fresh += cell == 0;
    cell = 1;
  }
  return fresh;
}

void CoveragePlanner::stampBump(const Bump& b, int delta) {
  for (const auto& [di, dj] : bump_disc_) {
    if (!map_.inside(b.i + di, b.j + dj)) continue;
    uint8_t& count = bump_count_[static_cast<size_t>(b.j + dj) * map_.width() + b.i + di];
    count = static_cast<uint8_t>(std::clamp(count + delta, 0, 255));
  }
}

void CoveragePlanner::addBump(Point2 p_m, double until_s) {
  constexpr size_t kMaxBumps = 200;  // the oldest goes first
  if (bumps_.size() >= kMaxBumps) {
    stampBump(bumps_.front(), -1);
    bumps_.erase(bumps_.begin());
  }
  bumps_.push_back({map_.col(p_m.x_m), map_.row(p_m.y_m), until_s});
  stampBump(bumps_.back(), +1);
}

void CoveragePlanner::expireBumps(double now_s) {
  for (size_t k = 0; k < bumps_.size();) {
    if (bumps_[k].until_s > now_s) {
      ++k;
      continue;
    }
    stampBump(bumps_[k], -1);
    bumps_.erase(bumps_.begin() + static_cast<std::ptrdiff_t>(k));
  }
}

Point2 CoveragePlanner::nearestTraversable(Point2 from_m, double radius_m) const {
  const int reach = static_cast<int>(std::ceil(radius_m / map_.cellM()));
  const int i0 = map_.col(from_m.x_m), j0 = map_.row(from_m.y_m);
  Point2 best = from_m;
  double best_m = radius_m;
  for (int j = j0 - reach; j <= j0 + reach; ++j) {
    for (int i = i0 - reach; i <= i0 + reach; ++i) {
      if (!traversable(i, j)) continue;
      const Point2 c = map_.centre(i, j);
      const double d_m = std::hypot(c.x_m - from_m.x_m, c.y_m - from_m.y_m);
      if (d_m < best_m) {
        best_m = d_m;
        best = c;
      }
    }
  }
  return best;
}

void CoveragePlanner::forget(Point2 p_m) { sweep(p_m); }

void CoveragePlanner::resetSwept(double near_walls_m) {
  for (int j = map_.minRow(); j <= map_.maxRow(); ++j) {
    for (int i = map_.minCol(); i <= map_.maxCol(); ++i) {
      if (map_.clearanceM(i, j) < near_walls_m) swept_[static_cast<size_t>(j) * map_.width() + i] = 0;
    }
  }
}

bool CoveragePlanner::segmentClear(Point2 a_m, Point2 b_m, double skip_m, double clearance_m) const {
  if (clearance_m < 0) clearance_m = s_.clearance_m;
  const double length_m = std::hypot(b_m.x_m - a_m.x_m, b_m.y_m - a_m.y_m);
  const double step_m = 0.5 * map_.cellM();
  const int steps = static_cast<int>(std::ceil(length_m / step_m));
  for (int k = 0; k <= steps; ++k) {
    const double f = steps == 0 ? 1.0 : static_cast<double>(k) / steps;
    if (f * length_m < skip_m) continue;
    if (!passable(Point2{a_m.x_m + f * (b_m.x_m - a_m.x_m), a_m.y_m + f * (b_m.y_m - a_m.y_m)}, clearance_m)) return false;
  }
  return true;
}

Lane CoveragePlanner::lane(Point2 from_m, int dx, int dy) const { return wallLane(from_m, dx, dy, 0, 0, s_.clearance_m, 0); }

Lane CoveragePlanner::wallLane(Point2 from_m, int dx, int dy, int wall_dx, int wall_dy, double clearance_m,
                               double strip_m) const {
  const int strip = static_cast<int>(std::lround(strip_m / map_.cellM()));
  Lane out;
  out.end_m = from_m;
  int i = map_.col(from_m.x_m), j = map_.row(from_m.y_m);
  const double cell_m = map_.cellM();
  int last = 0, unswept_last = 0;
  for (int k = 1;; ++k) {
    i += dx;
    j += dy;
    if (!map_.knownFree(i, j) || map_.clearanceM(i, j) < clearance_m || bumped(i, j)) break;
    // Nearer a wall than the plans go, the other side must leave room: a cell away from the
    // wall is traversable (else the lane enters a gap the disc barely fits, h2's 0.35 m between
    // a box and a wall, and is wedged there).
    const bool beside_wall = wall_dx != 0 || wall_dy != 0;
    if (beside_wall && clearance_m < s_.clearance_m && !traversable(i - wall_dx, j - wall_dy)) break;
    last = k;
    if (!swept(i + wall_dx * strip, j + wall_dy * strip)) {
      out.unswept_m += cell_m;
      unswept_last = k;
    }
  }
  // Up to the wall when it is near the last unswept place: the disc then sweeps the floor
  // along the wall ahead too, which no lane across it does (it stops clearance_m short).
  const int end = last - unswept_last <= kWallReachCells ? last : unswept_last;
  // Along the lane's own line (not snapped to the cells' centres).
  out.end_m = {from_m.x_m + dx * end * cell_m, from_m.y_m + dy * end * cell_m};
  return out;
}

std::pair<Point2, Lane> CoveragePlanner::besideWall(Point2 from_m, int wall_dx, int wall_dy, int dx, int dy,
                                                    double max_m, double min_m, double strip_m, bool wall_beyond) const {
  const double cell_m = map_.cellM();
  for (double d_m = max_m; d_m >= min_m; d_m -= cell_m) {
    const Point2 q{from_m.x_m + wall_dx * d_m, from_m.y_m + wall_dy * d_m};
    if (!passable(q, s_.hug_clearance_m)) continue;
    const Point2 beyond{q.x_m + wall_dx * cell_m, q.y_m + wall_dy * cell_m};
    if ((wall_beyond && passable(beyond, s_.hug_clearance_m)) || !segmentClear(from_m, q, 0.05, s_.hug_clearance_m)) break;
    return {q, wallLane(q, dx, dy, wall_dx, wall_dy, s_.hug_clearance_m, strip_m)};
  }
  return {from_m, Lane{}};
}

// A block of k x k cells (corner bi, bj) for the nearest-unswept search. Why blocks: a search
// over every 2.5 cm cell of a house at each decision cost more than the run could spend.
PlanBlock CoveragePlanner::planBlock(int bi, int bj, int k, bool relaxed, bool leaving) const {
  PlanBlock out;
  out.rep = -1;
  double best_m = -1, best_goal_m = -1;
  int unswept = 0;
  for (int j = bj; j < bj + k; ++j) {
    for (int i = bi; i < bi + k; ++i) {
      if (!planPassable(i, j, relaxed, leaving)) continue;
      const double c_m = map_.clearanceM(i, j);
      if (c_m > best_m) {
        best_m = c_m;
        out.rep = j * map_.width() + i;
      }
      if (!traversable(i, j)) continue;
      unswept += !swept(i, j);
      if (c_m > best_goal_m) {
        best_goal_m = c_m;
        out.goal = j * map_.width() + i;
      }
      if (!out.frontier && !swept(i, j)) out.frontier = nextToUnknown(i, j, k);
    }
  }
  out.unswept = unswept >= kMinUnsweptCells;
  out.unswept_cells = unswept;
  return out;
}

// Relaxed: also through floor not seen yet and closer to walls, the way out of a pocket the
// map has closed (a passage seen too narrow, a wall drawn a little off); never through a bump
// (h2: a path along a corridor clipped a box's corner, bumped, and was planned again, 50 s),
// except where the robot stands (leaving).
bool CoveragePlanner::planPassable(int i, int j, bool relaxed, bool leaving) const {
  if (leaving && map_.knownFree(i, j) && map_.clearanceM(i, j) >= s_.leave_clearance_m) return true;
  if (!relaxed) return traversable(i, j);
  return (map_.knownFree(i, j) || !map_.known(i, j)) && map_.clearanceM(i, j) >= s_.relaxed_clearance_m && !bumped(i, j);
}

// A frontier: floor next to what the laser has not seen yet (a block's width away). Going there
// shows more, unless the robot has been there already: what it did not see then (under furniture,
// behind it where the laser does not look) it will not see by going back (the caller asks only
// of unswept floor).
bool CoveragePlanner::nextToUnknown(int i, int j, int k) const {
  for (int dj = -k; dj <= k; dj += k) {
    for (int di = -k; di <= k; di += k) {
      if (!map_.known(i + di, j + dj)) return true;
    }
  }
  return false;
}

std::vector<Point2> CoveragePlanner::pathToUnswept(Point2 from_m, bool relaxed, bool worth_a_trip) const {
  // Blocks of k x k cells over what the map has seen. A block is traversable when any of its
  // cells is (a narrow passage between furniture is narrower than a block), through the one
  // farthest from walls; unswept when enough of its traversable cells are (not a sliver).
  const int k = std::max(1, static_cast<int>(std::lround(s_.plan_cell_m / map_.cellM())));
  const int i0 = map_.minCol(), j0 = map_.minRow();
  const int w = (map_.maxCol() - i0) / k + 1, h = (map_.maxRow() - j0) / k + 1;
  if (map_.maxCol() < i0 || w <= 0 || h <= 0) return {};
  std::vector<PlanBlock> blocks(static_cast<size_t>(w) * h);  // each looked at once, when the search reaches it
  const auto block = [&](int b) -> const PlanBlock& {
    if (blocks[b].rep == -2) {
      const int bi = i0 + (b % w) * k, bj = j0 + (b / w) * k;
      const Point2 c = map_.centre(bi + k / 2, bj + k / 2);
      blocks[b] = planBlock(bi, bj, k, relaxed, relaxed && std::hypot(c.x_m - from_m.x_m, c.y_m - from_m.y_m) <= s_.leave_m);
    }
    return blocks[b];
  };
  // The unswept cells of block b and the 8 round it.
  const auto area = [&](int b) {
    int cells = 0;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = b % w + dx, y = b / w + dy;
        if (x >= 0 && y >= 0 && x < w && y < h) cells += block(y * w + x).unswept_cells;
      }
    }
    return cells;
  };
  const auto point = [&](int cell) { return map_.centre(cell % map_.width(), cell / map_.width()); };
  const int sx = std::clamp((map_.col(from_m.x_m) - i0) / k, 0, w - 1);
  const int sy = std::clamp((map_.row(from_m.y_m) - j0) / k, 0, h - 1);
  const int start = sy * w + sx;
  std::vector<int> parent;
  const int goal = nearestGoal(
      w, h, start, [&](int b) { return block(b).rep >= 0; },
      [&](int b) {
        const PlanBlock& g = block(b);
        if (g.goal < 0 || !(g.unswept || g.frontier)) return false;
        return !worth_a_trip || g.frontier || area(b) >= s_.area_cells;
      },
      parent);
  if (goal < 0) return {};
  std::vector<Point2> chain;
  chain.push_back(point(block(goal).goal));
  for (int c = parent[goal]; c != -1 && c != start; c = parent[c]) chain.push_back(point(block(c).rep));
  std::reverse(chain.begin(), chain.end());
  return shortcut(from_m, chain, [&](Point2 a, Point2 b, bool first) { return segmentClear(a, b, first ? 0.1 : 0.0); });
}

}  // namespace aula::vacuum::mapping
