// Autopark's slot detector on synthetic scans: the three lasers of a car driving along the
// street, ray-cast against the worlds' own geometry at the lasers' height (0.5 m, above the curb:
// beyond the parked cars a beam has no echo, as on RoboticsAcademy's street), or at 0.1 m, where
// the curb shows.
#include <aula/autopark/slot_detector.hpp>
#include <aula/autopark/street_end.hpp>
#include <aula/geometry/raycaster2d.hpp>
#include <aula/world/obstacle_slice.hpp>
#include <aula/world/world_spec.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace aula::autopark;

namespace {

struct Street {
  aula::geometry::Raycaster2D caster;
  explicit Street(const std::string& world, double height_m = kLaserHeightM)
      : caster(aula::world::sliceAtHeight(aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/" + world), height_m)) {}
  static constexpr double kLaserHeightM = 0.5;  // the car model's lasers

  aula::component::LaserData scan(double x, double y, double yaw, const LaserMount& m, double max_range_m) const {
    aula::component::LaserData d;
    d.numLaser = 180;
    d.minAngle = -M_PI / 2;
    d.maxAngle = M_PI / 2;
    d.angleIncrement = M_PI / 179;
    d.minRange = 0.08;
    d.maxRange = max_range_m;
    d.values_m.resize(180);
    aula::geometry::ScanRequest r;
    r.origin_m = Eigen::Vector2d(x + std::cos(yaw) * m.x_m - std::sin(yaw) * m.y_m, y + std::sin(yaw) * m.x_m + std::cos(yaw) * m.y_m);
    r.yaw_rad = yaw + m.yaw_rad;
    r.min_angle_rad = d.minAngle;
    r.angle_increment_rad = d.angleIncrement;
    r.num_beams = 180;
    r.min_range_m = d.minRange;
    r.max_range_m = d.maxRange;
    caster.scan(r, d.values_m.data());
    return d;
  }
};

// The car model's lasers (RoboticsAcademy's): mounts and max ranges, m.
const LaserMount kFront{2.4, 0, 0}, kRear{-2.4, 0, M_PI}, kRight{0.5, -1.25, -M_PI / 2};
constexpr double kFrontRearRangeM = 11.0, kRightRangeM = 9.5;

void drive(const Street& street, SlotDetector& detector, double from_x, double to_x, double y) {
  const double step = from_x < to_x ? 0.1 : -0.1;
  for (double x = from_x; step > 0 ? x <= to_x : x >= to_x; x += step) {
    detector.addScan(x, y, 0, kFront, street.scan(x, y, 0, kFront, kFrontRearRangeM));
    detector.addScan(x, y, 0, kRear, street.scan(x, y, 0, kRear, kFrontRearRangeM));
    detector.addScan(x, y, 0, kRight, street.scan(x, y, 0, kRight, kRightRangeM));
  }
}

}  // namespace

TEST(SlotDetector, FindsTheDefaultSlotDrivingPastIt) {
  const Street street("autopark.world");
  SlotDetector detector(4.8);
  drive(street, detector, -7, -1, 2.5);
  EXPECT_FALSE(detector.slot(0).has_value()) << "the slot is not bounded yet";
  drive(street, detector, -1, 14, 2.5);
  const auto slot = detector.slot(7);
  ASSERT_TRUE(slot.has_value());
  EXPECT_NEAR(slot->rear_x_m, 2.95, 0.15);
  EXPECT_NEAR(slot->front_x_m, 11.55, 0.15);
  // No beam sees the curb: the line is the parked cars' far side, seen on their end faces.
  EXPECT_NEAR(slot->curb_y_m, -4.1, 0.1);
  EXPECT_FALSE(slot->curb_seen);
  EXPECT_NEAR(slot->edge_y_m, -1.9, 0.05);
}

TEST(SlotDetector, TheCurbWhereTheLasersSeeIt) {
  const Street street("autopark.world", 0.1);  // below the curb's top
  SlotDetector detector(4.8);
  drive(street, detector, -7, 14, 2.5);
  const auto slot = detector.slot(7);
  ASSERT_TRUE(slot.has_value());
  EXPECT_NEAR(slot->centreXM(), 7.25, 0.15);
  EXPECT_NEAR(slot->curb_y_m, -4.25, 0.05);
  EXPECT_TRUE(slot->curb_seen);
}

TEST(SlotDetector, BeamsWithNoEchoFindTheSlotOnceAnEndFacesBottomIsSeen) {
  // Cars' side at -1.9 either side of a gap the beams cross with no echo, deep down. Where to
  // park in it is the cars' far side: no slot while their end faces are seen only in part (out
  // of range, or hidden), whatever the cars' width might be; then the deepest bottom seen.
  SlotDetector detector(4.0);
  for (double x = 0; x < 3; x += 0.05) detector.addPoint(x, -1.9);
  for (double x = 9; x < 12; x += 0.05) detector.addPoint(x, -1.9);
  for (double x = 3.02; x < 9; x += 0.05) detector.addFreePoint(x, -6.0);
  EXPECT_FALSE(detector.slot(6).has_value()) << "no end face seen";
  for (double y = -1.9; y > -3.05; y -= 0.1) {
    detector.addPoint(2.99, y);
    detector.addPoint(9.0, y);
  }
  EXPECT_FALSE(detector.slot(6).has_value()) << "the faces seen down to -3 only";
  detector.addPassBelowAFace(2.99, -3.58);
  EXPECT_FALSE(detector.slot(6).has_value()) << "a beam passed 0.58 m below the deepest echo: the bottom is not known";
  for (double y = -3.0; y > -3.55; y -= 0.1) detector.addPoint(2.99, y);  // down to -3.5: a narrow car behind
  auto slot = detector.slot(6);
  ASSERT_TRUE(slot.has_value());
  EXPECT_NEAR(slot->rear_x_m, 3.0, 0.06);
  EXPECT_NEAR(slot->front_x_m, 9.0, 0.06);
  EXPECT_NEAR(slot->curb_y_m, -3.5, 1e-9);
  for (double y = -3.0; y > -4.15; y -= 0.1) detector.addPoint(9.0, y);  // the car ahead reaches deeper
  detector.addPassBelowAFace(9.0, -4.15);
  slot = detector.slot(6);
  ASSERT_TRUE(slot.has_value());
  EXPECT_NEAR(slot->curb_y_m, -4.1, 1e-9);
}

TEST(SlotDetector, TheLineIsNeverAnEndFaceSeenInPart) {
  // Driving up to the default slot, the lasers first see the end face of the car ahead of it
  // down to where it leaves their range: that is no bottom; nor is an echo the next beam down
  // passed far below. Whenever a slot is reported, its line is the cars' far side (-4.1) within
  // 0.1 m, and never below it.
  const Street street("autopark.world");
  SlotDetector detector(4.8);
  bool reported = false;
  for (double x = -7; x <= 8; x += 0.1) {
    drive(street, detector, x, x, 2.5);
    if (const auto slot = detector.slot(7)) {
      reported = true;
      EXPECT_NEAR(slot->curb_y_m, -4.05, 0.05) << "car at x " << x;
    }
  }
  EXPECT_TRUE(reported);
}

TEST(SlotDetector, TightSlotAndTooShortAGap) {
  const Street street("autopark_ackermann_1.3L.world");
  SlotDetector detector(4.8);
  drive(street, detector, -7, 12, 1.0);
  const auto slot = detector.slot(5);
  ASSERT_TRUE(slot.has_value());
  EXPECT_NEAR(slot->lengthM(), 5.2, 0.25);
  EXPECT_NEAR(slot->centreXM(), 2.95 + 2.6, 0.1);
  // The same street with a 6 m minimum: no slot at all (the 2.6 m gaps between the other cars
  // are shorter still).
  SlotDetector picky(6.0);
  drive(street, picky, -7, 12, 1.0);
  EXPECT_FALSE(picky.slot(5).has_value());
}

TEST(SlotDetector, SeesTheSlotBehindWithTheRearLaser) {
  // Started alongside the car ahead of the slot, the car reverses down the street.
  const Street street("autopark.world");
  SlotDetector detector(4.8);
  drive(street, detector, 14, 9, 2.5);
  const auto slot = detector.slot(14);
  ASSERT_TRUE(slot.has_value());
  EXPECT_NEAR(slot->centreXM(), 7.25, 0.15);
}

TEST(SlotDetector, TheStreetsEndWallDoesNotMoveTheCarsEdge) {
  // Start alongside the car ahead of the slot, drive to the east end (its wall crosses the
  // parking side up to the lane) and back: the wall is a few bins only, the cars' side is most.
  const Street street("autopark.world");
  SlotDetector detector(4.8);
  drive(street, detector, 14, 31, 0.0);
  ASSERT_TRUE(detector.edgeY().has_value());
  EXPECT_NEAR(*detector.edgeY(), -1.9, 0.05);
  drive(street, detector, 31, 0, 0.0);
  const auto slot = detector.slot(7);
  ASSERT_TRUE(slot.has_value());
  EXPECT_NEAR(slot->centreXM(), 7.25, 0.15);
}

TEST(SlotDetector, NoEdgeUntilBothTheCurbAndTheCarsAreSeen) {
  SlotDetector detector(4.8);
  for (double x = 0; x < 5; x += 0.1) detector.addPoint(x, -2.1);  // cars only: or is it the curb?
  EXPECT_FALSE(detector.edgeY().has_value());
  for (double x = 5; x < 8; x += 0.1) detector.addPoint(x, -4.25);  // a gap shows the curb below
  ASSERT_TRUE(detector.edgeY().has_value());
  EXPECT_NEAR(*detector.edgeY(), -2.1, 1e-9);
}

TEST(SlotDetector, AGapBetweenTheLastCarAndTheEndWallIsNotASlot) {
  // In the 1.2 L street the last car ends at x = 27.65 and the wall at 35: 7 m of curb, bounded
  // by a wall, not by a car.
  const Street street("autopark_ackermann_1.2L.world");
  SlotDetector detector(4.6);
  drive(street, detector, 20, 31, 0.0);
  EXPECT_FALSE(detector.slot(31).has_value());
  drive(street, detector, 31, -1, 0.0);
  const auto slot = detector.slot(31);  // the nearest real slot, however far
  ASSERT_TRUE(slot.has_value());
  EXPECT_NEAR(slot->centreXM(), 5.35, 0.1);
  EXPECT_NEAR(slot->lengthM(), 4.8, 0.15);
}

namespace {
// One beam straight out of a laser at the car's centre, `range_m` long (0: no echo).
aula::component::LaserData oneBeam(double range_m) {
  aula::component::LaserData d;
  d.numLaser = 1;
  d.minRange = 0.1;
  d.maxRange = 20.0;
  d.values_m = {static_cast<float>(range_m > 0 ? range_m : 20.0)};
  return d;
}
}  // namespace

// The street's end is what blocks the lane, whatever the car's yaw: a parked car seen ahead by a
// car yawed towards the curb is not the end, a wall across the lane is; behind counts only when
// reversing.
TEST(LaneBlockedAhead, OnlyWhatStandsInTheLaneEndsTheStreet) {
  const LaserMount centre{0, 0, 0};
  // From (0, 2.5), the lane at 2.5 +- 1.3 m, 6 m ahead counts.
  EXPECT_TRUE(laneBlockedAhead(0, 2.5, 0.0, centre, oneBeam(3.0), +1, 2.5, 1.3, 6.0));
  EXPECT_FALSE(laneBlockedAhead(0, 2.5, 0.0, centre, oneBeam(7.0), +1, 2.5, 1.3, 6.0));  // too far yet
  EXPECT_FALSE(laneBlockedAhead(0, 2.5, 0.0, centre, oneBeam(0), +1, 2.5, 1.3, 6.0));    // no echo
  // Yawed 35 degrees towards the curb: the echo 4 m out lies 2.3 m below the lane, on a parked car.
  EXPECT_FALSE(laneBlockedAhead(0, 2.5, -0.61, centre, oneBeam(4.0), +1, 2.5, 1.3, 6.0));
  // Facing +x, something 3 m ahead is not ahead of a car reversing towards -x.
  EXPECT_FALSE(laneBlockedAhead(0, 2.5, 0.0, centre, oneBeam(3.0), -1, 2.5, 1.3, 6.0));
  const LaserMount rear{0, 0, M_PI};
  EXPECT_TRUE(laneBlockedAhead(0, 2.5, 0.0, rear, oneBeam(3.0), -1, 2.5, 1.3, 6.0));
}
