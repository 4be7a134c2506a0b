#include <aula/geometry/angles.hpp>

#include <gtest/gtest.h>

#include <cmath>

using aula::geometry::wrapAngle;
using aula::geometry::wrapLineAngle;

TEST(WrapAngle, KeepsAnAngleInRange) {
  for (double a : {0.0, 0.1, -0.1, 1e-10, -3.0, 3.0, M_PI / 2}) EXPECT_NEAR(wrapAngle(a), a, 1e-15) << a;
}

TEST(WrapAngle, WrapsIntoTheHalfOpenTurn) {
  EXPECT_EQ(wrapAngle(M_PI), -M_PI);  // [-pi, pi): pi and -pi are one heading, reported once
  EXPECT_EQ(wrapAngle(-M_PI), -M_PI);
  EXPECT_NEAR(wrapAngle(3 * M_PI / 2), -M_PI / 2, 1e-15);
  EXPECT_NEAR(wrapAngle(-3 * M_PI / 2), M_PI / 2, 1e-15);
  EXPECT_NEAR(wrapAngle(0.5 + 20 * M_PI), 0.5, 1e-13);
  EXPECT_NEAR(wrapAngle(-0.5 - 20 * M_PI), -0.5, 1e-13);
}

TEST(WrapLineAngle, ABackwardsHeadingIsAlignedWithTheLine) {
  EXPECT_NEAR(wrapLineAngle(M_PI), 0.0, 1e-15);
  EXPECT_NEAR(wrapLineAngle(M_PI + 0.2), 0.2, 1e-15);
  EXPECT_NEAR(wrapLineAngle(-M_PI + 0.2), 0.2, 1e-15);
  EXPECT_NEAR(wrapLineAngle(0.3), 0.3, 1e-15);
  EXPECT_NEAR(wrapLineAngle(M_PI / 2 + 0.1), -M_PI / 2 + 0.1, 1e-15);
}

TEST(Angles, HeadingIsDegreesCounterClockwiseFromXInMinus180To180) {
  using aula::geometry::headingDeg;
  EXPECT_DOUBLE_EQ(headingDeg(0.0), 0.0);
  EXPECT_DOUBLE_EQ(headingDeg(M_PI / 2), 90.0);
  EXPECT_DOUBLE_EQ(headingDeg(-M_PI / 2), -90.0);           // facing -y: -90, never 270
  EXPECT_DOUBLE_EQ(headingDeg(3 * M_PI / 2), -90.0);
  EXPECT_DOUBLE_EQ(headingDeg(M_PI), 180.0);                // the half-open end is +180
  EXPECT_DOUBLE_EQ(headingDeg(-M_PI), 180.0);
  EXPECT_NEAR(headingDeg(-91.4 * M_PI / 180), -91.4, 1e-9);  // the Autopark case of the issue
  EXPECT_NEAR(headingDeg(10 * M_PI + 0.1), 0.1 * 180 / M_PI, 1e-9);
}
