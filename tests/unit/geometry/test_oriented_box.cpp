#include <aula/geometry/oriented_box.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

using aula::geometry::MapTransform;
using aula::geometry::OrientedBox;

TEST(OrientedBox, CornersCounterClockwiseFromTheRearRight) {
  const OrientedBox car{{1, 2, 0}, 4, 2};
  const auto c = car.corners();
  EXPECT_TRUE(c[0].isApprox(Eigen::Vector2d(-1, 1)));
  EXPECT_TRUE(c[1].isApprox(Eigen::Vector2d(3, 1)));
  EXPECT_TRUE(c[2].isApprox(Eigen::Vector2d(3, 3)));
  EXPECT_TRUE(c[3].isApprox(Eigen::Vector2d(-1, 3)));
}

TEST(OrientedBox, CornersTurnAboutTheBoxCentre) {
  // A car at (7.25, -3) rotated 90 degrees: 4 m tall, 2 m wide, centred on itself (the parking
  // referee's original rotated corners about the world origin, which moved the car across the street).
  const OrientedBox car{{7.25, -3, M_PI / 2}, 4, 2};
  double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
  for (const auto& c : car.corners()) {
    min_x = std::min(min_x, c.x());
    max_x = std::max(max_x, c.x());
    min_y = std::min(min_y, c.y());
    max_y = std::max(max_y, c.y());
  }
  EXPECT_NEAR(min_x, 6.25, 1e-9);
  EXPECT_NEAR(max_x, 8.25, 1e-9);
  EXPECT_NEAR(min_y, -5.0, 1e-9);
  EXPECT_NEAR(max_y, -1.0, 1e-9);
  EXPECT_TRUE(car.boundingHalfExtents().isApprox(Eigen::Vector2d(1, 2)));
}

TEST(OrientedBox, ContainsAndInflated) {
  const OrientedBox b{{0, 0, M_PI / 4}, 2, 2};  // a diamond: |x| + |y| <= sqrt(2)
  EXPECT_TRUE(b.contains(0, 1.4));
  EXPECT_FALSE(b.contains(1, 1));
  EXPECT_TRUE(b.inflated(0.5).contains(1, 1));  // |x| + |y| <= 1.5 sqrt(2)
  EXPECT_DOUBLE_EQ(b.inflated(0.5).length_m, 3.0);
}

TEST(OrientedBox, OverlapTrueAndFalse) {
  const OrientedBox a{{0, 0, 0}, 4, 2};
  EXPECT_TRUE(overlap(a, OrientedBox{{0, 0, 0.3}, 1, 1}));    // one inside the other
  EXPECT_TRUE(overlap(a, OrientedBox{{3.9, 0, 0}, 4, 2}));    // sharing a strip
  EXPECT_TRUE(overlap(a, OrientedBox{{4, 0, 0}, 4, 2}));      // touching counts
  EXPECT_TRUE(overlap(a, OrientedBox{{3.3, 0, M_PI / 4}, 2, 2}));   // diamond's corner at x = 1.886
  EXPECT_FALSE(overlap(a, OrientedBox{{3.5, 0, M_PI / 4}, 2, 2}));  // ... at x = 2.086
  EXPECT_FALSE(overlap(a, OrientedBox{{5, 0, 0}, 4, 2}));
  // Bounding boxes overlap, the boxes do not: only a rotated axis separates them.
  EXPECT_FALSE(overlap(a, OrientedBox{{3.2, 2.2, M_PI / 4}, 2, 2}));
}

TEST(OrientedBox, DistanceBetweenBoxesByHand) {
  const OrientedBox a{{0, 0, 0}, 4, 2};
  EXPECT_NEAR(distance(a, OrientedBox{{5, 0, 0}, 4, 2}), 1.0, 1e-12);  // 5 - 2 - 2
  EXPECT_NEAR(distance(a, OrientedBox{{0, 3, 0}, 4, 2}), 1.0, 1e-12);
  EXPECT_NEAR(distance(a, OrientedBox{{5, 3, 0}, 4, 2}), std::hypot(1.0, 1.0), 1e-12);  // corner to corner
  EXPECT_EQ(distance(a, OrientedBox{{3.9, 0, 0}, 4, 2}), 0.0);
  // A diamond's left corner (4 - sqrt 2, 0) to the face x = 2.
  EXPECT_NEAR(distance(a, OrientedBox{{4, 0, M_PI / 4}, 2, 2}), 2 - std::sqrt(2.0), 1e-12);
  // The corner (2, 1) to the diamond's edge x + y = 5.4 - sqrt 2.
  EXPECT_NEAR(distance(a, OrientedBox{{3.2, 2.2, M_PI / 4}, 2, 2}), 2.4 / std::sqrt(2.0) - 1, 1e-12);
}

TEST(OrientedBox, PenetrationIsTheLeastMoveThatSeparates) {
  const OrientedBox a{{0, 0, 0}, 4, 2};
  EXPECT_NEAR(penetration(a, OrientedBox{{3.9, 0, 0}, 4, 2}), 0.1, 1e-12);  // a 0.1 m strip
  EXPECT_NEAR(penetration(a, OrientedBox{{0, 1.5, 0}, 4, 2}), 0.5, 1e-12);  // across, the shorter way
  EXPECT_EQ(penetration(a, OrientedBox{{4, 0, 0}, 4, 2}), 0.0);             // touching
  EXPECT_EQ(penetration(a, OrientedBox{{5, 0, 0}, 4, 2}), 0.0);
  // A diamond's corner at x = 3.3 - sqrt 2 reaches 2 - (3.3 - sqrt 2) into a.
  EXPECT_NEAR(penetration(a, OrientedBox{{3.3, 0, M_PI / 4}, 2, 2}), 2 - (3.3 - std::sqrt(2.0)), 1e-12);
}

TEST(OrientedBox, RasterisesCellCentresInsideAndClipsToTheGrid) {
  MapTransform grid;  // 4 x 4 cells of 1 m over x [0, 4], y [0, 4]
  grid.resolution_m = 1;
  grid.origin_x_m = 0;
  grid.origin_y_m = 4;
  grid.width_px = grid.height_px = 4;
  auto cells = [&](const OrientedBox& box) {
    std::set<std::pair<int, int>> out;
    rasterise(box, grid, [&](int col, int row) { out.insert({col, row}); });
    return out;
  };
  const std::set<std::pair<int, int>> middle{{1, 1}, {2, 1}, {1, 2}, {2, 2}};
  EXPECT_EQ(cells(OrientedBox{{2, 2, 0}, 2, 2}), middle);
  EXPECT_EQ(cells(OrientedBox{{2, 2, M_PI / 4}, 2, 2}), middle);  // next cells: |dx| + |dy| = 2 > sqrt 2
  EXPECT_EQ(cells(OrientedBox{{0, 0, 0}, 2, 2}), (std::set<std::pair<int, int>>{{0, 3}}));  // bottom-left corner only
  EXPECT_TRUE(cells(OrientedBox{{10, 10, 0}, 2, 2}).empty());
}
