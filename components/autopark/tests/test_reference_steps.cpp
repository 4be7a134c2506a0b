// The references' decisions (reference_steps.hpp) on plain numbers: each step alone, with the
// values at which it must switch.
#include <aula/autopark/reference_steps.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace aula::autopark;

namespace {
Slot slotOf(double rear_x_m, double front_x_m) {
  Slot slot;
  slot.rear_x_m = rear_x_m;
  slot.front_x_m = front_x_m;
  slot.curb_y_m = -4.25;
  slot.edge_y_m = -2.1;
  return slot;
}
}  // namespace

TEST(ReactiveSteps, TheArcsStartOnlyOnTheSpotOnTheLaneAndStraight) {
  EXPECT_TRUE(atArcStart(0.04, 0.0, 0.1, 0.01));
  EXPECT_FALSE(atArcStart(0.06, 0.0, 0.1, 0.01));  // still short of the spot
  EXPECT_FALSE(atArcStart(0.0, 0.0, 0.35, 0.0));   // off the lane
  EXPECT_FALSE(atArcStart(0.0, 0.0, 0.0, 0.06));   // not straight
  EXPECT_TRUE(atArcStart(0.0, 0.0, 0.0, 2 * M_PI + 0.01));  // a whole turn is straight
}

TEST(ReactiveSteps, TheApproachSlowsAsItNearsButNeverCreeps) {
  EXPECT_DOUBLE_EQ(approachSpeed(10.0, 2.0, 1.5), 2.0);
  EXPECT_DOUBLE_EQ(approachSpeed(-10.0, 2.0, 1.5), -1.5);
  EXPECT_DOUBLE_EQ(approachSpeed(1.0, 2.0, 1.5), 0.8);
  EXPECT_DOUBLE_EQ(approachSpeed(0.01, 2.0, 1.5), 0.15);
  EXPECT_DOUBLE_EQ(approachSpeed(-0.01, 2.0, 1.5), -0.15);
}

TEST(ReactiveSteps, TheFirstArcEndsWhenTheSecondRemovesWhatIsLeft) {
  const double radius = 5.0, yaw = 0.5, second = radius * (1 - std::cos(yaw));
  EXPECT_TRUE(firstArcDone(second - 0.01, radius, yaw, 0.6));
  EXPECT_FALSE(firstArcDone(second + 0.01, radius, yaw, 0.6));
  EXPECT_TRUE(firstArcDone(10.0, radius, 0.71, 0.6));  // turned past the plan
}

TEST(ReactiveSteps, CentringMovesTowardsEqualGapsAndStraightens) {
  const Command forward = centringCommand(2.0, 1.0, 0.0, 5.0);
  EXPECT_DOUBLE_EQ(forward.v_mps, 0.4);
  EXPECT_DOUBLE_EQ(forward.w_radps, 0.0);
  const Command back = centringCommand(1.0, 1.02, 0.0, 5.0);
  EXPECT_DOUBLE_EQ(back.v_mps, -0.1);  // never slower than 0.1 m/s
  const Command turning = centringCommand(3.0, 1.0, 0.2, 5.0);
  EXPECT_DOUBLE_EQ(turning.v_mps, 0.5);
  EXPECT_LT(turning.w_radps, 0.0);  // yawed left, moving forward: steer right
  EXPECT_LE(std::abs(turning.w_radps), 0.5 / 5.0 + 1e-12);
  EXPECT_TRUE(centred(1.0, 1.1, 0.02));
  EXPECT_FALSE(centred(1.0, 1.3, 0.0));
  EXPECT_FALSE(centred(1.0, 1.0, 0.05));
}

TEST(ReactiveSteps, InTheSlotMeansWithinItsEndsOnItsLineAndParallel) {
  const Slot slot = slotOf(2.75, 8.75);  // 6 m
  EXPECT_TRUE(inSlot(slot, -2.8, 4.0, 5.75, -2.8, 0.0));
  EXPECT_FALSE(inSlot(slot, -2.8, 4.0, 7.0, -2.8, 0.0));   // front past the car ahead
  EXPECT_FALSE(inSlot(slot, -2.8, 4.0, 5.75, -2.3, 0.0));  // half a metre above the line
  EXPECT_FALSE(inSlot(slot, -2.8, 4.0, 5.75, -2.8, 0.2));  // across
}

TEST(PlannedSteps, PastTheSlotCountsInTheSearchDirection) {
  const Slot slot = slotOf(2.0, 8.0);
  EXPECT_DOUBLE_EQ(pastSlotM(slot, +1, 10.0), 2.0);
  EXPECT_DOUBLE_EQ(pastSlotM(slot, -1, 10.0), -8.0);
  EXPECT_DOUBLE_EQ(pastSlotM(slot, -1, 0.5), 1.5);
}

TEST(PlannedSteps, ThePlanningGridNeverReachesBeyondTheMappedStreet) {
  const Slot slot = slotOf(2.0, 8.0);
  const MappedStreet wide{-100, 100, -10, 10};
  const MappedStreet e = planningExtent(wide, slot, 10.0, 0.0, -0.1, 2.0);
  EXPECT_DOUBLE_EQ(e.min_x_m, -10.0);  // 12 m behind the slot
  EXPECT_DOUBLE_EQ(e.max_x_m, 22.0);   // 12 m beyond the car
  EXPECT_DOUBLE_EQ(e.min_y_m, -4.25);  // the slot's line: nothing below it
  EXPECT_DOUBLE_EQ(e.max_y_m, 4.0);    // the car's side plus 3 m
  const MappedStreet narrow{0, 15, -5, 1};
  const MappedStreet n = planningExtent(narrow, slot, 10.0, 0.0, -0.1, 2.0);
  EXPECT_DOUBLE_EQ(n.min_x_m, 0.0);
  EXPECT_DOUBLE_EQ(n.max_x_m, 15.0);
  EXPECT_DOUBLE_EQ(n.max_y_m, 1.0);
}

TEST(PlannedSteps, ARetriedPlanSearchesFinerWithAnotherSeed) {
  const ParkingPlannerOptions first = planOptions(7, 0), second = planOptions(7, 1);
  EXPECT_EQ(first.seed, 7u);
  EXPECT_EQ(second.seed, 8u);
  EXPECT_TRUE(first.repeatable && second.repeatable);  // never the wall clock
  EXPECT_DOUBLE_EQ(first.escape_step_m, ParkingPlannerOptions{}.escape_step_m);
  EXPECT_LT(second.escape_step_m, first.escape_step_m);
  EXPECT_LT(second.min_slot_clearance_m, first.min_slot_clearance_m);
  EXPECT_GT(second.escape_max_expansions, first.escape_max_expansions);
}

TEST(PlannedSteps, TheBodysExtentHoldsEveryCornerOfThePath) {
  PlannedPath path;
  path.poses = {{0, 0, 0}, {10, 0, 0}};
  const CarGeometry car;  // 4 x 2 m by default
  const MappedStreet body = bodyExtent(path, car, {1e9, -1e9, 1e9, -1e9});
  EXPECT_NEAR(body.min_x_m, -car.length_m / 2, 1e-9);
  EXPECT_NEAR(body.max_x_m, 10 + car.length_m / 2, 1e-9);
  EXPECT_NEAR(body.min_y_m, -car.width_m / 2, 1e-9);
  EXPECT_NEAR(body.max_y_m, car.width_m / 2, 1e-9);
}

TEST(ReactiveSteps, ArrivedOffTheLaneItBacksOffFurtherTheFurtherOffItIs) {
  EXPECT_TRUE(arrivedOffLane(0.2, 2.6));
  EXPECT_TRUE(arrivedOffLane(-0.4, -0.5));
  EXPECT_FALSE(arrivedOffLane(0.2, 0.1));  // on the lane: the arcs start
  EXPECT_FALSE(arrivedOffLane(3.0, 2.6));  // still on its way: the lane keeping closes it
  EXPECT_GT(runUpM(2.6), runUpM(0.5));
  EXPECT_DOUBLE_EQ(runUpM(-1.0), runUpM(1.0));
  EXPECT_GE(runUpM(0.3), 4.0);
}

TEST(ReactiveSteps, TheRearClearanceIsTheLowRearCornerToTheSlotsRearEnd) {
  const Slot slot = slotOf(2.0, 9.0);  // the cars' side at -2.1
  // Straight, on the slot's line: the rear corners at x 5 - 2 = 3, 1 m from the car behind.
  EXPECT_NEAR(rearClearanceM(slot, 4.0, 2.0, 5.0, -3.2, 0.0), 1.0, 1e-9);
  // Turned 0.3 rad in the second arc: only the lower rear corner is below the side line.
  const double c = std::cos(0.3), s = std::sin(0.3);
  EXPECT_NEAR(rearClearanceM(slot, 4.0, 2.0, 5.0, -2.3, 0.3), 5.0 - 2.0 * c + 1.0 * s - 2.0, 1e-9);
  // Still above the cars' side line: nothing behind it to hit.
  EXPECT_TRUE(std::isinf(rearClearanceM(slot, 4.0, 2.0, 5.0, 1.5, 0.0)));
}
