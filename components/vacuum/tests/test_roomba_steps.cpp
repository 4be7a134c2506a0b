// The classic vacuum reference's steps on plain numbers (roomba_steps.hpp): its laser sectors,
// its spiral, its wall following and its turns on the spot.
#include "support/synthetic_scan.hpp"

#include <roomba_steps.hpp>

#include <gtest/gtest.h>

#include <cmath>

using aula::vacuum::roomba::Settings;

TEST(RoombaSteps, ASectorsNearestEchoIsWithinItsAngles) {
  // 1 m everywhere but 0.4 m from 30 degrees left on.
  const auto scan = aula::test::syntheticScan(181, -M_PI / 2, M_PI / 2, [](double a) { return a > 0.5 ? 0.4 : 1.0; });
  EXPECT_FLOAT_EQ(aula::vacuum::roomba::sectorMin(scan, -0.45, 0.45), 1.0);
  EXPECT_FLOAT_EQ(aula::vacuum::roomba::sectorMin(scan, -1.0, 1.0), 0.4);
  EXPECT_FLOAT_EQ(aula::vacuum::roomba::sectorMin(scan, 2.0, 3.0), 10.0) << "no beam there: the laser's max range";
}

TEST(RoombaSteps, TheSpiralWidensSlowerAsItGrows) {
  const Settings s;
  const double small = aula::vacuum::roomba::spiralRadiusAfter(s, 0.2, 1.0) - 0.2;
  const double large = aula::vacuum::roomba::spiralRadiusAfter(s, 1.0, 1.0) - 1.0;
  EXPECT_NEAR(small, s.spiral_growth_m2ps / 0.2, 1e-12);
  EXPECT_NEAR(large, s.spiral_growth_m2ps / 1.0, 1e-12);
  EXPECT_NEAR(aula::vacuum::roomba::spiralRadiusAfter(s, 0.0, 1.0), s.spiral_growth_m2ps / s.spiral_min_radius_m, 1e-12)
      << "never divided by less than the minimum radius";
}

TEST(RoombaSteps, WallFollowingTurnsAtCornersSearchesALostWallAndSteersToItsDistance) {
  const Settings s;
  const auto corner = aula::vacuum::roomba::wallFollow(s, 0.2, 1.0, 0.24);
  EXPECT_EQ(corner.v_mps, 0.0);
  EXPECT_GT(corner.w_radps, 0.0) << "left on the spot";
  const auto lost = aula::vacuum::roomba::wallFollow(s, 2.0, 2.0, 1.5);
  EXPECT_GT(lost.v_mps, 0.0);
  EXPECT_LT(lost.w_radps, 0.0) << "curving right to find the wall";
  EXPECT_EQ(aula::vacuum::roomba::wallFollow(s, 2.0, 2.0, s.wall_follow_distance_m).w_radps, 0.0);
  EXPECT_LT(aula::vacuum::roomba::wallFollow(s, 2.0, 2.0, 0.4).w_radps, 0.0) << "too far: towards the wall";
  EXPECT_GT(aula::vacuum::roomba::wallFollow(s, 2.0, 2.0, 0.1).w_radps, 0.0) << "too near: away from it";
  EXPECT_EQ(aula::vacuum::roomba::wallFollow(s, 2.0, 2.0, 0.6).w_radps, -s.wall_max_turn_radps) << "within its limit";
}

TEST(RoombaSteps, TurnsFasterTheFartherOffWithinItsLimit) {
  const Settings s;
  EXPECT_NEAR(aula::vacuum::roomba::turnRate(s, 0.1), s.turn_min_radps + s.turn_gain_per_s * 0.1, 1e-12);
  EXPECT_NEAR(aula::vacuum::roomba::turnRate(s, -0.1), -(s.turn_min_radps + s.turn_gain_per_s * 0.1), 1e-12);
  EXPECT_EQ(aula::vacuum::roomba::turnRate(s, 3.0), s.turn_max_radps);
}
