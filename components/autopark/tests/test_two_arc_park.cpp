// The reactive reference's manoeuvre planning on plain data: two equal arcs swept against the
// slot's cars and curb as measured, declined with the length it would need when nothing fits.
#include <aula/autopark/two_arc_park.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace aula::autopark;

namespace {

// The shipped street's slot as the lasers measure it: parked cars' side at y = -2.1, the curb at
// -4.25, the slot from x = 2.75, `length_m` long; the lane 2 m above the cars' side.
Slot streetSlot(double length_m) {
  Slot slot;
  slot.rear_x_m = 2.75;
  slot.front_x_m = 2.75 + length_m;
  slot.curb_y_m = -4.25;
  slot.edge_y_m = -2.1;
  return slot;
}
constexpr double kLaneY = -0.1;
const CarShape kTurnsInPlace{4.0, 2.0, 0.0, 0.0};
const CarShape kCarLike{4.0, 2.0, -1.3, 5.0};

}  // namespace

TEST(TwoArcPark, TheDefaultSlotFitsBothCarsWithAClearSweepEndingInTheSlot) {
  for (const CarShape& car : {kTurnsInPlace, kCarLike}) {
    const Slot slot = streetSlot(9.0);
    const TwoArcPlan plan = planTwoArcPark(slot, kLaneY, car);
    ASSERT_TRUE(plan.feasible) << plan.why;
    EXPECT_GE(plan.radius_m, car.min_turn_radius_m);
    EXPECT_NEAR(plan.goal_y_m, -4.25 + kCurbClearanceM + 1.0, 1e-9);
    EXPECT_GT(plan.end_x_m - 2.0, slot.rear_x_m);
    EXPECT_LT(plan.end_x_m + 2.0, slot.front_x_m);
    EXPECT_NEAR(plan.start_x_m - plan.end_x_m, 2 * plan.radius_m * std::sin(plan.arc_rad), 1e-9);
    EXPECT_TRUE(twoArcSweepClear(slot, kLaneY, plan.goal_y_m, plan.radius_m, plan.end_x_m, car));
  }
}

TEST(TwoArcPark, ASlotTooShortIsDeclinedWithTheLengthItWouldNeed) {
  const TwoArcPlan plan = planTwoArcPark(streetSlot(5.0), kLaneY, kCarLike);
  ASSERT_FALSE(plan.feasible);
  // A 5 m turning radius about the rear axle needs about 6.3 m plus the clearances.
  EXPECT_GT(plan.needed_length_m, 6.0);
  EXPECT_LT(plan.needed_length_m, 7.5);
  EXPECT_NE(plan.why.find("slot too short for a reactive park: 5.0 m, need "), std::string::npos) << plan.why;
  // And a slot that long does fit.
  EXPECT_TRUE(planTwoArcPark(streetSlot(plan.needed_length_m), kLaneY, kCarLike).feasible);
  EXPECT_FALSE(planTwoArcPark(streetSlot(plan.needed_length_m - 0.2), kLaneY, kCarLike).feasible);
}

TEST(TwoArcPark, TheSweepSeesACarTooCloseAheadOrBehindAndTheCurb) {
  const Slot slot = streetSlot(9.0);
  const TwoArcPlan plan = planTwoArcPark(slot, kLaneY, kCarLike);
  ASSERT_TRUE(plan.feasible);
  Slot ahead_closer = slot;
  ahead_closer.front_x_m = plan.end_x_m + 2.0;  // the car ahead right at the car's front at the end
  EXPECT_FALSE(twoArcSweepClear(ahead_closer, kLaneY, plan.goal_y_m, plan.radius_m, plan.end_x_m, kCarLike));
  Slot behind_closer = slot;
  behind_closer.rear_x_m = plan.end_x_m - 2.0;
  EXPECT_FALSE(twoArcSweepClear(behind_closer, kLaneY, plan.goal_y_m, plan.radius_m, plan.end_x_m, kCarLike));
  // Ending with the car's side on the curb.
  EXPECT_FALSE(twoArcSweepClear(slot, kLaneY, slot.curb_y_m + 0.9, plan.radius_m, plan.end_x_m, kCarLike));
}
