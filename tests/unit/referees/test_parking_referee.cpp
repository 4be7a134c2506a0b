// Autopark referee: the parking measures (minimum distances about the car's own centre), the
// slot read from the worlds, the sub-scores and the episode on sim time.
#include <aula/scoring/parking_geometry.hpp>
#include <aula/autopark/parking_referee.hpp>
#include <aula/world/world_spec.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace aula::autopark;

namespace {

// The default street, by hand: cars 4.5 x 1.8 at y = -3, x = 0.5 and 14; curb face y = -4.25.
ParkingScene handScene() {
  ParkingScene s;
  s.rear_car = {{0.5, -3, 0}, 4.5, 1.8};
  s.front_car = {{14, -3, 0}, 4.5, 1.8};
  s.curb_y_m = -4.25;
  s.ideal_x_m = 7.25;
  s.ideal_y_m = -3;
  s.car_length_m = 4;
  s.car_width_m = 2;
  return s;
}

constexpr double kDeg = M_PI / 180.0;

}  // namespace

TEST(ParkingGeometry, IdealPoseMeasures) {
  const ParkingMeasures m = measureParking(handScene(), 7.25, -3, 0);
  EXPECT_NEAR(m.front_gap_m, 14 - 2.25 - 9.25, 1e-9);  // 2.5
  EXPECT_NEAR(m.rear_gap_m, 5.25 - 2.75, 1e-9);        // 2.5
  EXPECT_NEAR(m.curb_gap_m, -4.0 + 4.25, 1e-9);        // 0.25
  EXPECT_NEAR(m.yaw_error_deg, 0, 1e-9);
  EXPECT_NEAR(m.position_error_m, 0, 1e-9);
  EXPECT_TRUE(m.inside_slot);
}

TEST(ParkingGeometry, TiltedCarUsesMinimumDistances) {
  // 10 degrees nose-left, 1 m forward: the front-right corner is the one nearest the front
  // car, the rear-right corner the one nearest the curb.
  const double yaw = 10 * kDeg, c = std::cos(yaw), s = std::sin(yaw);
  const ParkingMeasures m = measureParking(handScene(), 8.25, -3, yaw);
  const double front_right_x = 8.25 + c * 2 - s * -1;
  const double rear_right_y = -3 + s * -2 + c * -1;
  EXPECT_NEAR(m.front_gap_m, 11.75 - front_right_x, 1e-9);
  EXPECT_NEAR(m.curb_gap_m, rear_right_y + 4.25, 1e-9);
  EXPECT_NEAR(m.yaw_error_deg, 10, 1e-9);
  // Backwards is as parallel as forwards; the bands are symmetric.
  EXPECT_NEAR(measureParking(handScene(), 7.25, -3, M_PI - 5 * kDeg).yaw_error_deg, -5, 1e-9);
  EXPECT_NEAR(measureParking(handScene(), 7.25, -3, -10 * kDeg).yaw_error_deg, -10, 1e-9);
}

TEST(ParkingGeometry, OutsideTheSlot) {
  EXPECT_FALSE(measureParking(handScene(), 7.25, 1.5, 0).inside_slot);   // still in the lane
  EXPECT_FALSE(measureParking(handScene(), 0.5, -3, 0).inside_slot);     // on the rear car
  EXPECT_FALSE(measureParking(handScene(), 7.25, -3, 60 * kDeg).inside_slot);
}

TEST(ParkingGeometry, SceneFromTheWorlds) {
  const auto street = aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/autopark.world");
  const ParkingScene s = ParkingScene::fromWorld(street, "car");
  EXPECT_NEAR(s.rear_car.centre.x_m, 0.5, 1e-9);
  EXPECT_NEAR(s.front_car.centre.x_m, 14, 1e-9);
  EXPECT_NEAR(s.curb_y_m, -4.25, 1e-9);
  EXPECT_NEAR(s.ideal_x_m, 7.25, 1e-9);
  EXPECT_NEAR(s.ideal_y_m, -3, 1e-9);
  EXPECT_NEAR(s.slotLengthM(), 8.6, 1e-9);  // RoboticsAcademy's street: 4.9 m cars at x = 0.5 and 14
  EXPECT_NEAR(s.rear_car.length_m, 4.9, 1e-9);
  EXPECT_NEAR(s.rear_car.width_m, 2.2, 1e-9);
  EXPECT_NEAR(s.car_length_m, 4.0, 1e-9);
  // Found from the geometry, not the names: the curbs nearest below and above the car's start,
  // the seven parked cars between the parking-side curb and the car.
  EXPECT_NE(s.curb_name.find("curb_parking_side"), std::string::npos) << s.curb_name;
  EXPECT_NEAR(s.far_curb_y_m, 5.0, 1e-9);
  EXPECT_EQ(s.parked_cars.size(), 7u);
  EXPECT_NEAR(s.street_west_x_m, -25, 1e-9);
  // Settings that name parts the world does not have: said, with the setting.
  try {
    ParkingScene::fromWorld(street, "car", {"kerb", ""});
    ADD_FAILURE();
  } catch (const aula::world::WorldError& e) {
    EXPECT_NE(std::string(e.what()).find(": no box collision named 'kerb' (Autopark.Referee.Curb)"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(ParkingScene::fromWorld(street, "car", {"curb_parking_side", "parked_car"}).slotLengthM(), s.slotLengthM());
  // The variants' slots are what their names say, in car lengths.
  for (double k : {1.6, 1.4, 1.3, 1.2}) {
    char name[64];
    std::snprintf(name, sizeof name, "/worlds/autopark_ackermann_%gL.world", k);
    const auto w = aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + name);
    const ParkingScene v = ParkingScene::fromWorld(w, "car");
    EXPECT_NEAR(v.slotLengthM(), 4.0 * k, 1e-9) << name;
    EXPECT_NEAR(v.rear_car.centre.x_m, 0.5, 1e-9) << name;
    EXPECT_EQ(w.findRobot("car")->findPlugin("motors")->getString("kinematics", ""), "ackermann") << name;
  }
  EXPECT_THROW(ParkingScene::fromWorld(street, "nobody"), aula::world::WorldError);
}

TEST(ParkingScores, BandsAndMark) {
  ParkingRefereeSettings s;
  const ParkingContacts none, one{1, 0.0, 0.0};
  ParkingMeasures m = measureParking(handScene(), 7.25, -3, 0);
  ParkingScores best = scoreParking(m, ParkingCase::Parked, 60, none, s);
  EXPECT_DOUBLE_EQ(best.mark, 10.0);
  // Slow: T = 100 * 170 / t.
  EXPECT_DOUBLE_EQ(scoreParking(m, ParkingCase::Parked, 340, none, s).time, 50.0);
  // Not parked: no time score.
  EXPECT_DOUBLE_EQ(scoreParking(m, ParkingCase::GaveUp, 300, none, s).time, 0.0);
  // 20 degrees either way: angle 50.
  EXPECT_DOUBLE_EQ(scoreParking(measureParking(handScene(), 7.25, -3, 20 * kDeg), ParkingCase::Parked, 60, none, s).angle, 50.0);
  EXPECT_DOUBLE_EQ(scoreParking(measureParking(handScene(), 7.25, -3, -20 * kDeg), ParkingCase::Parked, 60, none, s).angle, 50.0);
  // The slot rule (the default): a centred car's gaps are 2.5 m here. 1.3 m from the rear car
  // (52 % of 2.5: full) and 3.7 m from the front one: D = 100.
  m = measureParking(handScene(), 6.05, -3, 0);
  EXPECT_NEAR(m.rear_gap_m, 1.3, 1e-9);
  EXPECT_NEAR(m.ideal_gap_m, 2.5, 1e-9);
  EXPECT_NEAR(scoreParking(m, ParkingCase::Parked, 60, none, s).distance, 100.0, 1e-9);
  // 1.0 m (40 %: half) and 0.5 m (20 %: nothing) from the rear car.
  EXPECT_DOUBLE_EQ(gapScore(1.0, 2.5, s), 50.0);
  EXPECT_DOUBLE_EQ(gapScore(0.5, 2.5, s), 0.0);
  EXPECT_DOUBLE_EQ(gapScore(0.1, -0.2, s), 0.0);  // a slot shorter than the car
  // The original's absolute bands: 1.3 m is 50, 3.7 m is 0: D = (0 + 50 + 100) / 3.
  s.gaps_relative_to_slot = false;
  EXPECT_NEAR(scoreParking(m, ParkingCase::Parked, 60, none, s).distance, 50.0, 1e-9);
  // The thesis's scale: a collision costs C, whatever it was.
  s.thesis_scale = true;
  EXPECT_DOUBLE_EQ(scoreParking(measureParking(handScene(), 7.25, -3, 0), ParkingCase::Parked, 60, one, s).mark, 7.5);
}

TEST(ParkingReferee, ParkedAfterStandingStillThreeSecondsClockStopsWhenItStopped) {
  ParkingReferee r(handScene(), ParkingRefereeSettings{});
  int64_t t = 0;
  r.onPose(t, -7, 2.5, 0);
  r.onTick(t);
  EXPECT_FALSE(r.started());
  r.start(1'000'000);
  // Drive for 20 s (not in the slot), then stand at the ideal pose.
  for (t = 1'000'000; t <= 21'000'000; t += 100'000) {
    r.onPose(t, -7 + (t - 1'000'000) / 1e6 * 0.5, 2.5, 0);
    r.onTick(t);
  }
  EXPECT_FALSE(r.finished());
  const int64_t stopped = t;
  for (; t <= stopped + 5'000'000 && !r.finished(); t += 100'000) {
    r.onPose(t, 7.25, -3, 0);
    r.onTick(t);
  }
  ASSERT_TRUE(r.finished());
  EXPECT_TRUE(r.parked());
  // The first still pose is one period after arriving (speed needs two poses in the slot).
  EXPECT_NEAR(r.elapsedS(), (stopped - 1'000'000) / 1e6 + 0.1, 1e-9);
  EXPECT_DOUBLE_EQ(r.scores().mark, 10.0);
  EXPECT_EQ(r.collisions(), 0);
}

TEST(ParkingReferee, ContactsCountedWithTheirDurationAndTimeout) {
  ParkingRefereeSettings settings;
  settings.timeout_s = 10;
  ParkingReferee r(handScene(), settings);
  r.onContact(500'000, true);  // before Run: not counted
  r.onContact(600'000, false);
  r.start(1'000'000);
  int64_t t = 1'000'000;
  for (; t <= 12'000'000 && !r.finished(); t += 100'000) {
    r.onPose(t, (t / 1e6), 2.5, 0);  // driving along the lane, 1 m/s
    if (t == 2'000'000) r.onContact(t, true);
    if (t == 2'500'000) r.onContact(t, false);
    if (t == 4'000'000) r.onContact(t, true);
    if (t == 4'200'000) r.onContact(t, false);
    r.onTick(t);
  }
  ASSERT_TRUE(r.finished());
  EXPECT_FALSE(r.parked());
  EXPECT_EQ(r.collisions(), 2);
  EXPECT_NEAR(r.contactS(), 0.7, 1e-9);
  EXPECT_NEAR(r.elapsedS(), 10.0, 1e-9);
  EXPECT_DOUBLE_EQ(r.scores().time, 0.0);
  // Driving along the lane all the while, on the street: it gave up. Two contacts, 0.7 s, no depth
  // (the hand-made scene has no obstacle there): 0.2 + 0.07 of the not-parked mark.
  EXPECT_EQ(r.parkingCase(), ParkingCase::GaveUp);
  EXPECT_NEAR(r.scores().mark, 1.0 * (1 - 0.27), 1e-9);
  EXPECT_NEAR(r.scores().collision, 73.0, 1e-9);
}

TEST(ParkingReferee, TurningOnTheSpotIsNotStandingStill) {
  ParkingReferee r(handScene(), ParkingRefereeSettings{});
  r.start(0);
  int64_t t = 0;
  for (; t <= 10'000'000; t += 100'000) {
    r.onPose(t, 7.25, -3, 0.2 * std::sin(t / 1e6));  // wiggling in place
    r.onTick(t);
  }
  EXPECT_FALSE(r.finished());
}

// The player's breakdown rows (parkingMarkTerms), read top to bottom, make scoreParking's mark in
// every case, on both scales, with and without contacts: the not-parked rule and the contacts'
// factor are rows of their own, so no page recomputes the rubric.
TEST(ParkingScores, TheBreakdownsTotalIsTheMark) {
  const ParkingContacts none, one{1, 0.4, 0.003}, many{4, 6.0, 0.02};
  for (const bool thesis : {false, true}) {
    ParkingRefereeSettings s;
    s.thesis_scale = thesis;
    for (const double x : {7.25, 6.05, 20.0}) {  // centred, off centre, outside the slot
      const ParkingMeasures m = measureParking(handScene(), x, -3, 10 * kDeg);
      for (const ParkingCase c : {ParkingCase::Parked, ParkingCase::ParkedElsewhere, ParkingCase::DroveOff,
                                  ParkingCase::StayedStill, ParkingCase::GaveUp}) {
        for (const ParkingContacts& contacts : {none, one, many}) {
          const double mark = scoreParking(m, c, 120, contacts, s).mark;
          const auto rows = parkingMarkTerms(m, c, 120, contacts, s);
          EXPECT_NEAR(aula::referee::breakdownTotal(rows), mark, 1e-9)
              << "thesis " << thesis << ", x " << x << ", case " << caseName(c) << ", contacts " << contacts.count;
        }
      }
    }
  }
  // Not parked on the default scale: the rule's row says so and carries the mark; the terms are 0.
  ParkingRefereeSettings s;
  const auto rows = parkingMarkTerms(measureParking(handScene(), 7.25, -3, 0), ParkingCase::StayedStill, 300, none, s);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[3].term, "parked");
  EXPECT_DOUBLE_EQ(rows[3].points, s.not_parked_mark);
  EXPECT_NE(rows[3].measure.find("NOT parked"), std::string::npos) << rows[3].measure;
  EXPECT_NE(rows[2].measure.find("not graded: not parked"), std::string::npos) << rows[2].measure;
  EXPECT_DOUBLE_EQ(rows[2].points, 0.0);
  EXPECT_DOUBLE_EQ(rows[4].factor, 1.0);
}

TEST(ParkingGeometry, AStreetWithNoCurbAndCarsTurnedAcrossTheirOwnAxes) {
  // RoboticsAcademy's street: cars whose own axes run across (2.2 m along their x, 4.9 m along
  // their y), turned 1.57 rad, at y = -3 and x = 0.5, 14 and 21.5; no curb.
  aula::world::WorldSpec w;
  w.name = "ra";
  for (const double x : {0.5, 14.0, 21.5}) {
    aula::world::StaticObject car;
    car.name = "car::l::c";
    car.shape.box_size_m = Eigen::Vector3d(2.2, 4.9, 1.6);
    car.pose = Eigen::Translation3d(x, -3, 0.8) * Eigen::AngleAxisd(1.57, Eigen::Vector3d::UnitZ());
    w.statics.push_back(car);
  }
  aula::world::RobotSpec taxi;
  taxi.name = "taxi";
  taxi.shape.box_size_m = Eigen::Vector3d(4, 2, 1.2);
  taxi.pose = Eigen::Isometry3d(Eigen::Translation3d(-7, 2.5, 0));
  w.robots.push_back(taxi);
  const ParkingScene s = ParkingScene::fromWorld(w, "taxi");
  EXPECT_NEAR(s.slotLengthM(), 13.5 - 4.9, 1e-2) << "the cars' length runs along the street";
  EXPECT_NEAR(s.rear_car.length_m, 4.9, 1e-9);
  EXPECT_NEAR(s.ideal_x_m, 7.25, 1e-9);
  EXPECT_NEAR(s.curb_y_m, -3 - 1.1, 1e-2) << "the parking line: the parked cars' far side";
  EXPECT_TRUE(s.curb_name.empty());
  EXPECT_NEAR(s.street_west_x_m, 0.5 - 10, 1e-9);
  EXPECT_NEAR(s.street_east_x_m, 21.5 + 10, 1e-9);
  // No curb to touch: a car over the parking line is in no contact, one in a parked car is.
  EXPECT_EQ(contactDepthM(s, 7.25, -4.0, 0), 0.0);
  EXPECT_GT(contactDepthM(s, 3.0, -3, 0), 0.0);
}
