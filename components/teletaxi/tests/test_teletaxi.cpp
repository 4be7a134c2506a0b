#include <aula/teletaxi/gradient_field.hpp>
#include <aula/teletaxi/grid.hpp>
#include <aula/teletaxi/path_pilot.hpp>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <random>

using namespace aula::teletaxi;

namespace {
aula::geometry::MapTransform cityTransform() {
  aula::geometry::MapTransform t;
  t.resolution_m = 1.25;
  t.origin_x_m = -250;
  t.origin_y_m = 250;
  t.width_px = t.height_px = 400;
  return t;
}

FieldParams noPenalty() {
  FieldParams p;
  p.core_radius_cells = 0.5;  // only obstacle cells themselves are blocked
  p.penalty_radius_cells = 0.5;
  p.penalty_max = 0.0;
  return p;
}
}  // namespace

TEST(Grid, TransformsRoundTripThroughTheMapTransform) {
  Grid grid(cv::Mat(400, 400, CV_8UC1, cv::Scalar(255)), cityTransform());
  for (int x : {0, 17, 200, 399}) {
    for (int y : {0, 123, 399}) {
      const auto [wx, wy] = grid.gridToWorld(x, y);
      EXPECT_EQ(grid.worldToGrid(wx, wy), std::make_pair(x, y));
    }
  }
  EXPECT_EQ(grid.worldToGrid(0.1, 0.1), std::make_pair(200, 199));  // north is up
  EXPECT_EQ(grid.worldToGrid(-249.9, 249.9), std::make_pair(0, 0));
}

TEST(Grid, FieldAndPathUseTheSameIndexOrder) {
  cv::Mat map(3, 5, CV_8UC1, cv::Scalar(255));
  aula::geometry::MapTransform t;
  t.width_px = 5;
  t.height_px = 3;
  Grid grid(map, t);
  EXPECT_EQ(grid.getVal(4, 2), 0.0f);  // initialised
  grid.setVal(4, 2, 7.5f);             // x = column 4, y = row 2
  grid.setPathVal(4, 2, 1.0f);
  EXPECT_EQ(grid.getVal(4, 2), 7.5f);
  EXPECT_EQ(grid.getPathVal(4, 2), 1.0f);
  EXPECT_EQ(grid.field().at<float>(2, 4), 7.5f);
  EXPECT_EQ(grid.getPathVal(2, 4), 0.0f);  // out of the map, not transposed
  EXPECT_TRUE(std::isinf(grid.getVal(5, 0)));
}

TEST(GradientField, MatchesAHandComputedWavefront) {
  // 5 x 5, obstacle at (2, 1); goal at (2, 0). Without penalty, values are shortest 8-connected
  // distances (straight 1, diagonal 1.41).
  cv::Mat map(5, 5, CV_8UC1, cv::Scalar(255));
  map.at<uint8_t>(1, 2) = 0;
  GradientField field(map, noPenalty());
  ASSERT_TRUE(field.compute({2, 0}));
  EXPECT_FLOAT_EQ(field.value(2, 0), 0.0f);
  EXPECT_FLOAT_EQ(field.value(1, 0), 1.0f);
  EXPECT_FLOAT_EQ(field.value(1, 1), 1.41f);
  EXPECT_FLOAT_EQ(field.value(3, 1), 1.41f);
  EXPECT_FLOAT_EQ(field.value(2, 2), 2.82f);  // around the obstacle: two diagonals
  EXPECT_FLOAT_EQ(field.value(0, 0), 2.0f);
  EXPECT_FLOAT_EQ(field.value(0, 4), 1.41f * 2 + 2.0f);
  EXPECT_FLOAT_EQ(field.value(2, 4), 2.82f + 2.0f);
  EXPECT_TRUE(std::isinf(field.value(2, 1)));  // the obstacle
  const auto path = field.descend({2, 4});
  ASSERT_FALSE(path.empty());
  EXPECT_EQ(path.back(), (Cell{2, 0}));
  for (size_t i = 1; i < path.size(); ++i) EXPECT_LT(field.value(path[i].x, path[i].y), field.value(path[i - 1].x, path[i - 1].y));
}

TEST(GradientField, PenaltyGrowsTowardsObstacles) {
  cv::Mat map(40, 40, CV_8UC1, cv::Scalar(255));
  cv::rectangle(map, cv::Rect(0, 0, 40, 3), cv::Scalar(0), cv::FILLED);  // a wall on top
  GradientField field(map);
  float previous = std::numeric_limits<float>::infinity();
  for (int y = 3; y < 20; ++y) {
    const float p = field.penalty(20, y);
    if (!std::isinf(p)) {
      EXPECT_LE(p, previous) << "row " << y;
      previous = p;
    }
  }
  EXPECT_TRUE(std::isinf(field.penalty(20, 3))) << "the core next to the wall is forbidden";
  EXPECT_EQ(field.penalty(20, 30), 0.0f);
}

TEST(GradientField, PathsNeverEnterObstaclesOrTheCoreAndTheFieldIsComplete) {
  std::mt19937 rng(7);
  for (int map_id = 0; map_id < 10; ++map_id) {
    cv::Mat map(120, 120, CV_8UC1, cv::Scalar(255));
    std::uniform_int_distribution<int> pos(0, 110), size(3, 20);
    for (int k = 0; k < 25; ++k) cv::rectangle(map, cv::Rect(pos(rng), pos(rng), size(rng), size(rng)), cv::Scalar(0), cv::FILLED);
    GradientField field(map);
    std::uniform_int_distribution<int> cell(0, 119);
    Cell goal;
    do goal = {cell(rng), cell(rng)};
    while (!field.traversable(goal.x, goal.y));
    ASSERT_TRUE(field.compute(goal));
    // Complete: every traversable cell 8-connected to a reached cell is reached too.
    for (int y = 0; y < 120; ++y) {
      for (int x = 0; x < 120; ++x) {
        if (!field.traversable(x, y) || std::isinf(field.value(x, y))) continue;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            if (field.traversable(x + dx, y + dy)) {
              EXPECT_FALSE(std::isinf(field.value(x + dx, y + dy)));
            }
          }
        }
      }
    }
    for (int k = 0; k < 20; ++k) {
      const Cell start{cell(rng), cell(rng)};
      const auto path = field.descend(start);
      if (!field.traversable(start.x, start.y) || std::isinf(field.value(start.x, start.y))) {
        EXPECT_TRUE(path.empty());
        continue;
      }
      ASSERT_FALSE(path.empty());
      EXPECT_EQ(path.back(), goal);
      for (const Cell& c : path) {
        EXPECT_NE(map.at<uint8_t>(c.y, c.x), 0);
        EXPECT_TRUE(field.traversable(c.x, c.y));
      }
    }
  }
}

TEST(GradientField, GoalInsideAnObstacleIsRefused) {
  cv::Mat map(10, 10, CV_8UC1, cv::Scalar(255));
  map.at<uint8_t>(5, 5) = 0;
  GradientField field(map);
  EXPECT_FALSE(field.compute({5, 5}));
  EXPECT_TRUE(field.descend({1, 1}).empty());
}

TEST(PathPilot, StraightAheadFullSpeedBehindTurnInPlaceAndStopsAtTheGoal) {
  std::vector<Point2> line;
  for (int i = 0; i <= 200; ++i) line.push_back({i * 1.0, 0.0});
  PathPilot pilot;
  pilot.setPath(line);
  auto cmd = pilot.command(0, 0, 0, 0);
  EXPECT_NEAR(cmd.w_radps, 0.0, 1e-9);
  EXPECT_NEAR(cmd.v_mps, 20.0, 1e-9);
  PathPilot behind;
  behind.setPath(line);
  cmd = behind.command(0, 0, M_PI, 0);
  EXPECT_EQ(cmd.v_mps, 0.0);
  EXPECT_GT(std::abs(cmd.w_radps), 1.0);
  PathPilot end;
  end.setPath(line);
  cmd = end.command(199.6, 0, 0, 0);
  EXPECT_TRUE(cmd.arrived);
  EXPECT_EQ(cmd.v_mps, 0.0);
}

TEST(PathPilot, SlowsDownBeforeABend) {
  std::vector<Point2> straight, bend;
  for (int i = 0; i <= 60; ++i) straight.push_back({i * 1.0, 0.0});
  for (int i = 0; i <= 20; ++i) bend.push_back({i * 1.0, 0.0});
  for (int i = 1; i <= 40; ++i) bend.push_back({20.0, i * 1.0});
  PathPilot a, b;
  a.setPath(straight);
  b.setPath(bend);
  const double v_straight = a.command(0, 0, 0, 15).v_mps;
  const double v_bend = b.command(0, 0, 0, 15).v_mps;
  EXPECT_LT(v_bend, v_straight - 3.0);
}
