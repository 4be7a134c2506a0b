#include <aula/teletaxi/taxi_referee.hpp>

#include <gtest/gtest.h>

using aula::teletaxi::TaxiReferee;
using aula::teletaxi::TaxiRefereeSettings;

namespace {
// Feeds poses at 50 Hz from `from_s` to `to_s` along x at `speed` starting at x0; returns end x.
double drive(TaxiReferee& r, double from_s, double to_s, double x0, double speed) {
  double x = x0;
  for (int64_t t = static_cast<int64_t>(from_s * 1e6); t <= static_cast<int64_t>(to_s * 1e6); t += 20000) {
    x = x0 + speed * (t / 1e6 - from_s);
    r.onPose(t, x, 0.0, 0.0);
    if (t % 100000 == 0) r.onTick(t);
  }
  return x;
}
}  // namespace

TEST(TaxiReferee, ClockRunsFromGoToArrivalOnSimTime) {
  TaxiReferee r(TaxiRefereeSettings{});
  r.setGoal(100.0, 0.0);
  drive(r, 0.0, 5.0, 0.0, 0.0);  // waiting before GO!: no clock
  EXPECT_DOUBLE_EQ(r.elapsedS(), 0.0);
  r.start(5'000'000);
  EXPECT_NEAR(r.straightDistanceM(), 100.0, 1e-9);
  drive(r, 5.0, 55.0, 0.0, 2.0);    // 100 m in 50 s
  EXPECT_FALSE(r.finished());
  drive(r, 55.02, 60.0, 100.0, 0.0);  // at rest at the goal
  ASSERT_TRUE(r.finished());
  EXPECT_NEAR(r.elapsedS(), 50.02, 0.03);  // stopped when it came to rest
  EXPECT_NEAR(r.pathLengthM(), 100.0, 0.05);
  EXPECT_TRUE(r.grade().reached);
  EXPECT_NEAR(r.grade().average_speed_mps, 2.0, 0.01);
  EXPECT_NEAR(r.grade().mark, 8.0 + 0.2 * (10 * 2.0 / 2.6), 0.02);
  const double frozen = r.elapsedS();
  drive(r, 60.02, 70.0, 100.0, 0.0);
  EXPECT_DOUBLE_EQ(r.elapsedS(), frozen);
}

TEST(TaxiReferee, StoppingFarAwayIsNotArrivingAndTimesOut) {
  TaxiRefereeSettings s;
  s.timeout_s = 30.0;
  TaxiReferee r(s);
  r.setGoal(100.0, 0.0);
  r.start(0);
  drive(r, 0.0, 10.0, 0.0, 5.0);       // 50 m, then stops 50 m short
  drive(r, 10.02, 29.0, 50.0, 0.0);
  EXPECT_FALSE(r.finished());
  drive(r, 29.02, 31.0, 50.0, 0.0);
  ASSERT_TRUE(r.finished());
  EXPECT_FALSE(r.grade().reached);
  EXPECT_EQ(r.grade().mark, 0.0);
}

TEST(TaxiReferee, MirrorPositionsDoNotPass) {
  // The original compared |x| and |y| separately: (-100, 0) "arrived" at (100, 0).
  TaxiReferee r(TaxiRefereeSettings{});
  r.setGoal(100.0, 0.0);
  r.start(0);
  for (int64_t t = 0; t <= 3'000'000; t += 20000) {
    r.onPose(t, -100.0, 0.0, 0.0);
    r.onTick(t);
  }
  EXPECT_FALSE(r.finished());
  EXPECT_NEAR(r.distanceToGoalM(), 200.0, 1e-9);
}

TEST(TaxiReferee, TheGoalIsFixedOnceStarted) {
  TaxiReferee r(TaxiRefereeSettings{});
  r.setGoal(10.0, 0.0);
  r.onPose(0, 0.0, 0.0, 0.0);
  r.start(0);
  r.setGoal(500.0, 0.0);
  EXPECT_DOUBLE_EQ(r.goalX(), 10.0);
}
