#pragma once
// The coverage planner's two searches on plain data (coverage_planner.hpp uses them on its blocks
// of cells): the nearest goal on a grid, and a chain of waypoints cut short. Templates on the
// predicates, so that each is tested on a plain grid and inlined in the planner's hot loop.

#include "scan_map.hpp"

#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace aula::vacuum::mapping {

// Dijkstra on a width x height grid (index y * width + x), 8-connected (a straight step costs 10,
// a diagonal 14), from `start` to the nearest cell that is_goal(index) accepts (start itself never
// is), through cells that passable(index) accepts (start is not asked). Returns the goal (-1:
// none); parent[c] is the cell before c on the way there (-1 for the start and cells not reached).
// Why a search to the nearest of many goals: the unswept floor is everywhere, the robot in one place.
template <class Passable, class IsGoal>
int nearestGoal(int width, int height, int start, Passable&& passable, IsGoal&& is_goal, std::vector<int>& parent) {
  const size_t cells = static_cast<size_t>(width) * height;
  std::vector<int> cost(cells, std::numeric_limits<int>::max());
  parent.assign(cells, -1);
  using Item = std::pair<int, int>;  // (cost, cell): ties go to the lower index, so plans are reproducible
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  cost[start] = 0;
  open.push({0, start});
  while (!open.empty()) {
    const auto [c_cost, c] = open.top();
    open.pop();
    if (c_cost > cost[c]) continue;
    if (c != start && is_goal(c)) return c;
    const int cx = c % width, cy = c / width;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = cx + dx, ny = cy + dy;
        if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
        const int n = ny * width + nx;
        if (!passable(n)) continue;
        const int next = c_cost + (dx != 0 && dy != 0 ? 14 : 10);
        if (next < cost[n]) {
          cost[n] = next;
          parent[n] = c;
          open.push({next, n});
        }
      }
    }
  }
  return -1;
}

// A chain of waypoints from `from`, cut short: from each waypoint straight on to the farthest later
// one that clear(a, b, first) says is in a clear line (first: the segment from `from`, where the
// robot may stand close to a wall). Why: the grid's chain zigzags cell by cell; the robot drives lines.
template <class Clear>
std::vector<Point2> shortcut(Point2 from, const std::vector<Point2>& chain, Clear&& clear) {
  std::vector<Point2> out;
  Point2 at = from;
  size_t next = 0;
  while (next < chain.size()) {
    size_t far = next;
    for (size_t m = chain.size(); m-- > next + 1;) {
      if (clear(at, chain[m], out.empty())) {
        far = m;
        break;
      }
    }
    out.push_back(chain[far]);
    at = chain[far];
    next = far + 1;
  }
  return out;
}

}  // namespace aula::vacuum::mapping
