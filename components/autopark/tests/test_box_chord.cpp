// The footprint checker's row-by-row reading of the car's box (BoxChord) on plain corners: an
// axis-aligned box and a diamond, whose spans at any height are known by hand.
#include <aula/autopark/footprint_checker.hpp>

#include <gtest/gtest.h>

using namespace aula::autopark;

namespace {
// A 4 x 2 m box from (0, 0) to (4, 2), corners counter-clockwise.
const std::array<Eigen::Vector2d, 4> kBox{Eigen::Vector2d{0, 0}, {4, 0}, {4, 2}, {0, 2}};
// A diamond: bottom (2, 0), right (4, 2), top (2, 4), left (0, 2).
const std::array<Eigen::Vector2d, 4> kDiamond{Eigen::Vector2d{2, 0}, {4, 2}, {2, 4}, {0, 2}};
}  // namespace

TEST(BoxChord, AnAxisAlignedBoxSpansItsWholeWidthAtEveryHeight) {
  const BoxChord chord(kBox);
  const BoxChord::Span bottom = chord.bottom(0.0);
  EXPECT_DOUBLE_EQ(bottom.lo_x, 0.0);
  EXPECT_DOUBLE_EQ(bottom.hi_x, 4.0);
  const BoxChord::Span top = chord.top(2.0, 2.0);
  EXPECT_DOUBLE_EQ(top.lo_x, 0.0);
  EXPECT_DOUBLE_EQ(top.hi_x, 4.0);
  const BoxChord::Span band = chord.band(bottom, chord.top(0.5, 2.0), 0.0, 0.5);
  EXPECT_DOUBLE_EQ(band.lo_x, 0.0);
  EXPECT_DOUBLE_EQ(band.hi_x, 4.0);
}

TEST(BoxChord, ADiamondsBandHoldsTheCornerInsideIt) {
  const BoxChord chord(kDiamond);
  const BoxChord::Span bottom = chord.bottom(0.0);  // the bottom vertex only
  EXPECT_DOUBLE_EQ(bottom.lo_x, 2.0);
  EXPECT_DOUBLE_EQ(bottom.hi_x, 2.0);
  const BoxChord::Span at_one = chord.top(1.0, 4.0);  // halfway up the lower edges
  EXPECT_DOUBLE_EQ(at_one.lo_x, 1.0);
  EXPECT_DOUBLE_EQ(at_one.hi_x, 3.0);
  // The band [1.5, 2.5] holds the left and right corners: the span is the diamond's full width,
  // wider than the chords at either bound.
  const BoxChord::Span band = chord.band(chord.top(1.5, 4.0), chord.top(2.5, 4.0), 1.5, 2.5);
  EXPECT_DOUBLE_EQ(band.lo_x, 0.0);
  EXPECT_DOUBLE_EQ(band.hi_x, 4.0);
  const BoxChord::Span apex = chord.top(4.0, 4.0);
  EXPECT_DOUBLE_EQ(apex.lo_x, 2.0);
  EXPECT_DOUBLE_EQ(apex.hi_x, 2.0);
}

TEST(BoxChord, AnUntouchedSpanIsEmpty) {
  const BoxChord::Span span;
  EXPECT_FALSE(span.lo_x <= span.hi_x);
}
