// The coverage planner's searches on plain grids (plan_search.hpp): the nearest goal through
// passable cells, and a chain of waypoints cut short where a straight line is clear.
#include <plan_search.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

using aula::vacuum::mapping::nearestGoal;
using aula::vacuum::mapping::Point2;
using aula::vacuum::mapping::shortcut;

namespace {

// A grid drawn as text, row 0 first: '#' not passable, 'G' a goal, 'S' the start.
struct TextGrid {
  std::vector<std::string> rows;
  int width() const { return static_cast<int>(rows[0].size()); }
  int height() const { return static_cast<int>(rows.size()); }
  char at(int cell) const { return rows[cell / width()][cell % width()]; }
  int find(char c) const {
    for (int cell = 0; cell < width() * height(); ++cell) {
      if (at(cell) == c) return cell;
    }
    return -1;
  }
  int goal(std::vector<int>& parent) const {
    return nearestGoal(
        width(), height(), find('S'), [&](int c) { return at(c) != '#'; }, [&](int c) { return at(c) == 'G'; }, parent);
  }
};

int steps(const std::vector<int>& parent, int goal) {
  int n = 0;
  for (int c = goal; parent[c] != -1; c = parent[c]) ++n;
  return n;
}

}  // namespace

TEST(PlanSearch, FindsTheNearestGoalAroundAWall) {
  const TextGrid grid{{"S.#..G",  //
                       "..#...",  //
                       "......",  //
                       "G#####"}};
  std::vector<int> parent;
  const int goal = grid.goal(parent);
  EXPECT_EQ(goal, 3 * 6) << "the goal below (3 steps) before the one beyond the wall (6 or more)";
  EXPECT_EQ(steps(parent, goal), 3);
}

TEST(PlanSearch, GoesRoundWhatIsNotPassableAndFindsNothingWhenWalledIn) {
  const TextGrid open{{"S#G",  //
                       ".#.",  //
                       "..."}};
  std::vector<int> parent;
  const int goal = open.goal(parent);
  ASSERT_EQ(goal, 2);
  EXPECT_EQ(steps(parent, goal), 4) << "down, diagonally under the wall twice, and up";
  const TextGrid closed{{"S#G",  //
                         "##.",  //
                         "..."}};
  EXPECT_EQ(closed.goal(parent), -1);
}

TEST(PlanSearch, TheStartIsNeverItsOwnGoal) {
  std::vector<int> parent;
  const int goal = nearestGoal(
      3, 1, 0, [](int) { return true; }, [](int) { return true; }, parent);
  EXPECT_EQ(goal, 1);
}

TEST(PlanSearch, ShortcutKeepsOnlyTheCornersOfAClearWay) {
  // An L: along x to (3, 0), then up to (3, 3). Lines are clear unless they cut the corner.
  const std::vector<Point2> chain{{1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}};
  std::vector<bool> firsts;
  const auto clear = [&](Point2 a, Point2 b, bool first) {
    firsts.push_back(first);
    return a.x_m == b.x_m || a.y_m == b.y_m;
  };
  const auto out = shortcut({0, 0}, chain, clear);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].x_m, 3);
  EXPECT_EQ(out[0].y_m, 0);
  EXPECT_EQ(out[1].y_m, 3);
  EXPECT_TRUE(firsts.front()) << "the segment from the start is the first";
  EXPECT_FALSE(firsts.back());
}

TEST(PlanSearch, ShortcutKeepsEveryWaypointWhenNoLineIsClear) {
  const std::vector<Point2> chain{{1, 0}, {1, 1}, {2, 1}};
  const auto out = shortcut({0, 0}, chain, [](Point2, Point2, bool) { return false; });
  EXPECT_EQ(out.size(), chain.size());
}
