// Autopark's street search and both reference parkers on plain data: the street's parked cars,
// curbs and walls at the lasers' height, the car's three lasers ray-cast, the car moving on its
// own kinematics (turning in place, or car-like about its rear axle with |w| <= |v| / R) and
// stopped by any overlap (tests/unit/support/plain_robot.hpp). No LCM, no DART, no process.
#include "support/plain_robot.hpp"
#include <aula/autopark/references.hpp>

#include <aula/autopark/autopark_algorithm.hpp>
#include <aula/autopark/street_search.hpp>
#include <aula/scoring/parking_geometry.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>

using namespace aula::autopark;
using aula::scoring::ParkingScene;

namespace {

constexpr double kPeriodS = 0.05;  // Autopark.Period

LaserMount mountOf(const aula::world::RobotSpec& car, const std::string& name) {
  const Eigen::Isometry3d pose = car.findPluginNamed(name)->getPose("pose");
  return {pose.translation().x(), pose.translation().y(), aula::world::yawOf(pose)};
}

// The car of a shipped street and the API the component would give its algorithm.
struct Street {
  explicit Street(const std::string& world_file)
      : world(aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/" + world_file)),
        car(world_file, "car", 3, 1),  // Autopark.MaxV, MaxW
        api{car.pose,
            car.laser("laser_front"),
            car.laser("laser_rear"),
            car.laser("laser_right"),
            car.motors,
            kPeriodS,
            mountOf(car.spec(), "laser_front"),
            mountOf(car.spec(), "laser_rear"),
            mountOf(car.spec(), "laser_right")},
        scene(ParkingScene::fromWorld(world, "car")) {
    api.car_length_m = car.spec().shape.box_size_m.x();
    api.car_width_m = car.spec().shape.box_size_m.y();
    api.min_turn_radius_m = car.kinematics().min_turn_radius_m;
    api.turn_centre_x_m = car.kinematics().rear_axle_x_m;
    api.wheelbase_m = car.kinematics().wheelbase_m;
  }
  // Runs `step` every period for at most `seconds`, or until it returns false.
  void run(double seconds, const std::function<bool()>& step) {
    const int periods = static_cast<int>(seconds / kPeriodS);
    for (int i = 1; i <= periods && step(); ++i) car.step(kPeriodS, static_cast<int64_t>(i * kPeriodS * 1e6));
  }
  double positionErrorM() const { return std::hypot(car.x() - scene.ideal_x_m, car.y() - scene.ideal_y_m); }
  double yawErrorDeg() const {
    return std::abs(std::remainder(car.yaw() - scene.ideal_yaw_rad, 2 * M_PI)) * 180 / M_PI;
  }

  aula::world::WorldSpec world;
  aula::test::PlainRobot car;
  AutoparkApi api;
  ParkingScene scene;
};

}  // namespace

TEST(StreetSearch, FindsTheSlotKeepingItsLaneAndTouchingNothing) {
  for (const char* world : {"autopark.world", "autopark_ackermann.world"}) {
    SCOPED_TRACE(world);
    Street street(world);
    StreetSearch search(street.api, StreetSearch::Settings{});
    std::optional<Slot> slot;
    street.run(60, [&] {
      const StreetSearch::Step s = search.search(street.api, street.car.x(), street.car.y(), street.car.yaw());
      street.car.motors.sendV(s.v_mps);
      street.car.motors.sendW(s.w_radps);
      slot = s.slot;
      return !slot.has_value();
    });
    ASSERT_TRUE(slot.has_value()) << "no slot after 60 s";
    EXPECT_NEAR(slot->lengthM(), street.scene.slotLengthM(), 0.3);
    EXPECT_NEAR(slot->centreXM(), street.scene.ideal_x_m, 0.3);
    EXPECT_EQ(street.car.contacts(), 0);
  }
}

struct ParkerCase {
  const char* world;
  const char* algorithm;
};

class ReferenceParker : public ::testing::TestWithParam<ParkerCase> {};

TEST_P(ReferenceParker, ParksNearTheIdealPoseWithoutTouchingAnything) {
  Street street(GetParam().world);
  const std::string name = GetParam().algorithm;
  std::unique_ptr<AutoparkAlgorithm> parker = name == "reactive" ? makeReactiveAlgorithm(1) : makePlannedAlgorithm(1);
  double still_s = 0;
  street.run(120, [&] {
    parker->execute(street.api);
    // Parked: at rest for two seconds inside the slot.
    still_s = street.car.motors.getV() == 0 && street.car.motors.getW() == 0 ? still_s + kPeriodS : 0;
    return !(still_s > 2 && street.positionErrorM() < 1.0);
  });
  std::printf("%s on %s: %.2f m and %.1f deg from the ideal pose, %d contacts\n", name.c_str(), GetParam().world,
              street.positionErrorM(), street.yawErrorDeg(), street.car.contacts());
  EXPECT_LT(street.positionErrorM(), 0.5);
  EXPECT_LT(street.yawErrorDeg(), 10);
  EXPECT_EQ(street.car.contacts(), 0);
}

INSTANTIATE_TEST_SUITE_P(Streets, ReferenceParker,
                         ::testing::Values(ParkerCase{"autopark.world", "reactive"},
                                           ParkerCase{"autopark_ackermann.world", "reactive"},
                                           ParkerCase{"autopark.world", "planner"},
                                           ParkerCase{"autopark_ackermann_1.3L.world", "planner"}),
                         [](const ::testing::TestParamInfo<ParkerCase>& info) {
                           std::string name = std::string(info.param.algorithm) + "_" + info.param.world;
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

// Wheels that never turn: the reactive reference does not wait out the run in silence. Its search
// ends, after its longest search, "stalled" with the phase, how long, and where the car stands.
TEST(ReactiveParker, ACarThatCannotMoveSaysItIsStalledAndWhere) {
  Street street("autopark.world");
  std::unique_ptr<AutoparkAlgorithm> parker = makeReactiveAlgorithm(1);
  double said_at_s = 0;
  street.run(260, [&] {
    parker->execute(street.api);
    street.car.motors.sendV(0);  // blocked
    street.car.motors.sendW(0);
    said_at_s += kPeriodS;
    return street.api.status.empty();
  });
  const std::string& status = street.api.status;
  EXPECT_EQ(status.rfind("stalled: ", 0), 0u) << status;
  EXPECT_NE(status.find(" in SEARCH, stopped at x -7.00 y 2.50"), std::string::npos) << status;
  EXPECT_GT(said_at_s, 200.0);
  EXPECT_LT(said_at_s, 250.0);
}
