// The vacuum's referee: the coverage grid and the coverage referee's mark, bumps and time stuck.
#include <aula/scoring/coverage_grid.hpp>
#include <aula/vacuum/coverage_referee.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace aula::vacuum;

namespace {

// A 1 m x 1 m room at 0.02 m/px (50 x 50 px) with a 0.2 m obstacle column on the right.
cv::Mat tinyMap() {
  cv::Mat map(50, 50, CV_8UC1, cv::Scalar(255));
  map(cv::Rect(40, 0, 10, 50)).setTo(0);
  return map;
}

aula::geometry::MapTransform tinyTransform() {
  aula::geometry::MapTransform t;
  t.resolution_m = 0.02;
  t.origin_x_m = 0;
  t.origin_y_m = 1;
  t.width_px = t.height_px = 50;
  return t;
}

// The robot's true pose at 50 Hz over [from_s, to_s) of sim time, with the referee's 1 s ticks:
// circling (0.15 m radius, 20 s a turn: 9 cm in each 2 s window), or still where the circle
// starts (a turn ends there, so the two join without a jump).
void drive(CoverageReferee& r, int64_t from_s, int64_t to_s, bool moving) {
  for (int64_t t = from_s * 1'000'000; t < to_s * 1'000'000; t += 20'000) {
    const double a = moving ? 2 * M_PI * (t / 20e6) : 0.0;
    r.onPose(t, 0.3 + 0.15 * std::cos(a), 0.5 + 0.15 * std::sin(a));
    if (t % 1'000'000 == 0) r.onTick(t);
  }
}

// A 300 s episode: a fifth is 60 s.
CoverageReferee shortEpisode() {
  CoverageSettings s;
  s.duration_s = 300;
  s.robot_radius_m = 0.1;
  return CoverageReferee(CoverageGrid(tinyMap(), tinyTransform(), 0.3, 0.5), s);
}

void endEpisode(CoverageReferee& r, bool moving) {
  drive(r, 299, 300, moving);
  r.onTick(300'000'000);
  ASSERT_TRUE(r.finished());
}

}  // namespace


TEST(CoverageGrid, CountsTheDiscFootprintOnFreePixelsOnly) {
  CoverageGrid grid(tinyMap(), tinyTransform(), 0.3, 0.5);
  EXPECT_EQ(grid.floorPixels(), 40 * 50);
  // A 0.1 m disc (5 px radius) in the open: pixel centres within 5 px of (15.0, 25.0) px.
  grid.markDisc(0.3, 0.5, 0.1);
  int expected = 0;
  for (int row = 0; row < 50; ++row) {
    for (int col = 0; col < 40; ++col) {
      const double dx = col + 0.5 - 15.0, dy = row + 0.5 - 25.0;
      expected += dx * dx + dy * dy <= 25.0;
    }
  }
  EXPECT_EQ(grid.cleanedPixels(), expected);
  EXPECT_NEAR(grid.cleanedPixels(), M_PI * 25, 6);  // about pi r^2
  // Marking the same disc again adds nothing.
  grid.markDisc(0.3, 0.5, 0.1);
  EXPECT_EQ(grid.cleanedPixels(), expected);
  // A disc half over the obstacle column counts only the floor half.
  const int64_t before = grid.cleanedPixels();
  grid.markDisc(0.8, 0.2, 0.1);  // column starts at x = 0.8
  EXPECT_NEAR(grid.cleanedPixels() - before, expected / 2.0, 6);
  EXPECT_NEAR(grid.coveragePercent(), 100.0 * grid.cleanedPixels() / 2000.0, 1e-12);
}

TEST(CoverageGrid, FloorIsWhatIsReachableFromTheStart) {
  cv::Mat map = tinyMap();
  map(cv::Rect(0, 20, 40, 2)).setTo(0);  // a wall splits the room: the top part is sealed off
  CoverageGrid grid(map, tinyTransform(), 0.3, 0.2);  // start in the bottom part (y < 0.56 m)
  EXPECT_EQ(grid.floorPixels(), 40 * 28);
  EXPECT_THROW(CoverageGrid(map, tinyTransform(), 0.9, 0.5), std::invalid_argument);  // in the column
}

TEST(CoverageReferee, MarkPerHundredSecondsAndTheEnd) {
  EXPECT_DOUBLE_EQ(coverageMark(15.0, 15.0, 30.0), 5.0);
  EXPECT_DOUBLE_EQ(coverageMark(45.0, 15.0, 30.0), 10.0);
  EXPECT_DOUBLE_EQ(coverageMark(20.0, 40.0, 60.0), 2.5);  // 0 to 5 up to the half mark's coverage
  EXPECT_DOUBLE_EQ(coverageMark(50.0, 40.0, 60.0), 7.5);  // 5 to 10 from there to the full mark's
  EXPECT_DOUBLE_EQ(coverageMark(NAN, 15.0, 30.0), 0.0);
  EXPECT_DOUBLE_EQ(coverageMark(10.0, 0.0, 0.0), 0.0);    // no division by zero
  EXPECT_DOUBLE_EQ(coverageMark(10.0, 20.0, 20.0), 0.0);
  CoverageSettings s;
  s.duration_s = 300;
  s.robot_radius_m = 0.1;
  CoverageReferee r(CoverageGrid(tinyMap(), tinyTransform(), 0.3, 0.5), s);
  for (int64_t t = 0; t <= 300'000'000; t += 20'000) {
    const double x = 0.12 + 0.6 * (t / 300e6);  // a slow sweep to the right
    r.onPose(t, x, 0.5);
    if (t % 1'000'000 == 0) r.onTick(t);
  }
  ASSERT_TRUE(r.finished());
  ASSERT_EQ(r.coveragePer100s().size(), 3u);
  double total = 0;
  for (double gain : r.coveragePer100s()) {
    EXPECT_GT(gain, 0);
    total += gain;
  }
  EXPECT_NEAR(total, r.coveragePercent(), 1e-9);
  EXPECT_DOUBLE_EQ(r.elapsedS(), 300.0);
  r.onPose(301'000'000, 0.12, 0.9);  // after the end: ignored
  EXPECT_NEAR(total, r.coveragePercent(), 1e-9);
}

TEST(CoverageReferee, ANewEpisodeCountsFromItsOrigin) {
  // A hot reload at 500 s: the referee's 300 s run from there, and truth before it is ignored.
  CoverageSettings s;
  s.duration_s = 300;
  s.robot_radius_m = 0.1;
  const int64_t origin = 500'000'000;
  CoverageReferee r(CoverageGrid(tinyMap(), tinyTransform(), 0.3, 0.5), s, origin);
  r.onPose(origin - 20'000, 0.7, 0.5);  // the last episode's
  r.onTick(origin - 1'000'000);
  EXPECT_DOUBLE_EQ(r.coveragePercent(), 0.0);
  EXPECT_DOUBLE_EQ(r.elapsedS(), 0.0);
  r.onPose(origin, 0.3, 0.5);
  const double start_footprint = r.coveragePercent();
  EXPECT_GT(start_footprint, 0.0);
  r.onTick(origin + 299'000'000);
  EXPECT_FALSE(r.finished());
  EXPECT_DOUBLE_EQ(r.elapsedS(), 299.0);
  EXPECT_EQ(r.coveragePer100s().size(), 2u);
  r.onTick(origin + 300'000'000);
  EXPECT_TRUE(r.finished());
  EXPECT_DOUBLE_EQ(r.elapsedS(), 300.0);
}

TEST(CoverageReferee, CountsBumpsAndTimeStuck) {
  CoverageSettings s;
  CoverageReferee r(CoverageGrid(tinyMap(), tinyTransform(), 0.3, 0.5), s);
  r.onBump(0, true);
  r.onBump(20'000, true);  // held: still one bump
  r.onBump(40'000, false);
  r.onBump(60'000, true);
  EXPECT_EQ(r.bumps(), 2);
  for (int64_t t = 0; t <= 10'000'000; t += 20'000) r.onPose(t, 0.3, 0.5);  // 10 s without moving
  EXPECT_NEAR(r.stuckS(), 10.0, 0.1);
}

TEST(CoverageReferee, ARunThatEndsStuckForAFifthOfItsEpisodeEndedWedged) {
  CoverageReferee r = shortEpisode();
  drive(r, 0, 200, true);
  EXPECT_DOUBLE_EQ(r.stuckS(), 0.0);  // the circle is never stuck
  drive(r, 200, 299, false);          // pressed in a corner for the last 100 s
  endEpisode(r, false);
  EXPECT_NEAR(r.stuckAtEndS(), 100.0, 2.1);  // to within a window
  EXPECT_DOUBLE_EQ(r.stuckAtEndS(), r.stuckS());
  EXPECT_TRUE(r.wedged());
}

TEST(CoverageReferee, ARunStuckInTheMiddleOrBrieflyAtTheEndIsNotWedged) {
  // 100 s stuck in the middle, then cleaning again to the end: stuck, not wedged.
  CoverageReferee middle = shortEpisode();
  drive(middle, 0, 100, true);
  drive(middle, 100, 200, false);
  drive(middle, 200, 299, true);
  endEpisode(middle, true);
  EXPECT_NEAR(middle.stuckS(), 100.0, 2.1);
  EXPECT_DOUBLE_EQ(middle.stuckAtEndS(), 0.0);
  EXPECT_FALSE(middle.wedged());
  // Stuck for the last 40 s, under a fifth of 300 s: said, not wedged.
  CoverageReferee brief = shortEpisode();
  drive(brief, 0, 260, true);
  drive(brief, 260, 299, false);
  endEpisode(brief, false);
  EXPECT_NEAR(brief.stuckAtEndS(), 40.0, 2.1);
  EXPECT_FALSE(brief.wedged());
}
