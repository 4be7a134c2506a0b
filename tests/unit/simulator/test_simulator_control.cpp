// SIM_CONTROL requests are range-checked before DART sees them: one packet must not crash the
// simulator (yaw 1e308 aborted DART's verifyTransform) or put a robot outside its world.
#include <aula/lcm/bus.hpp>
#include <aula/sim/simulator.hpp>
#include <aula/sim_clock_t.hpp>
#include <aula/sim_control_t.hpp>
#include <aula/world/world_spec.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

namespace {

aula::sim_control_t setPose(const std::string& robot, double x, double y, double yaw) {
  aula::sim_control_t msg{};
  msg.command = aula::sim_control_t::SET_POSE;
  msg.robot = robot;
  msg.x = x;
  msg.y = y;
  msg.yaw = yaw;
  return msg;
}

}  // namespace

TEST(SimulatorControl, PosesOutsideTheWorldOrWithAWildYawAreRejectedAndCounted) {
  aula::lcmbus::Bus bus("memq://");
  aula::sim::Simulator sim(aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world"), {}, bus);
  const int roomba = sim.physics().robotIndex("roomba");
  ASSERT_GE(roomba, 0);
  const Eigen::Vector3d start = sim.physics().robotState(roomba).position_m;
  auto send = [&](const aula::sim_control_t& msg) {
    bus.publish(aula::lcmbus::kControlChannel, &msg);
    while (bus.handleTimeout(0) > 0) {
    }
  };
  const double inf = std::numeric_limits<double>::infinity();
  send(setPose("roomba", start.x(), start.y(), 1e308));  // finite, yet DART aborts on it
  send(setPose("roomba", 1e308, start.y(), 0.0));
  send(setPose("roomba", start.x(), -500.0, 0.0));
  send(setPose("roomba", inf, start.y(), 0.0));
  send(setPose("nobody", start.x(), start.y(), 0.0));
  aula::sim_control_t unknown{};
  unknown.command = 99;
  send(unknown);
  EXPECT_EQ(sim.rejectedControls(), 6);
  EXPECT_NEAR((sim.physics().robotState(roomba).position_m - start).norm(), 0.0, 1e-9);
  ASSERT_TRUE(sim.poseProblem(start.x(), start.y(), 4.0).has_value());
  EXPECT_NE(sim.poseProblem(start.x(), start.y(), 4.0)->find("not in [-pi, pi]"), std::string::npos);

  send(setPose("roomba", start.x() + 0.5, start.y(), M_PI));  // inside the house: done
  EXPECT_EQ(sim.rejectedControls(), 6);
  EXPECT_NEAR(sim.physics().robotState(roomba).position_m.x(), start.x() + 0.5, 1e-6);
  sim.advanceToNextTick();  // and the world steps on without complaint
}

namespace {

aula::sim_control_t command(int8_t what, double real_time_factor = 0) {
  aula::sim_control_t msg{};
  msg.command = what;
  msg.real_time_factor = real_time_factor;
  return msg;
}

// Sim seconds gained in `wall` of running.
double simSecondsIn(aula::sim::Simulator& sim, std::chrono::milliseconds wall) {
  const int64_t before = sim.timeUs();
  const auto until = std::chrono::steady_clock::now() + wall;
  sim.run([&] { return std::chrono::steady_clock::now() >= until; });
  return (sim.timeUs() - before) / 1e6;
}

}  // namespace

TEST(SimulatorControl, TheWindowsSpeedControlChangesThePaceAndStepAdvancesOneTick) {
  aula::lcmbus::Bus bus("memq://");
  aula::sim::SimulatorOptions options;
  options.real_time_factor = 1.0;
  aula::sim::Simulator sim(aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world"), options, bus);
  const double at_1x = simSecondsIn(sim, std::chrono::milliseconds(400));
  const auto fast = command(aula::sim_control_t::SET_RTF, 20.0);
  bus.publish(aula::lcmbus::kControlChannel, &fast);
  const double at_20x = simSecondsIn(sim, std::chrono::milliseconds(400));
  // 0.4 s and 8 s of sim time when the machine keeps up; a loaded machine slows both alike.
  EXPECT_GT(at_20x, 5 * at_1x) << "1x: " << at_1x << " s, 20x: " << at_20x << " s";
  EXPECT_LT(at_1x, 0.6);

  const auto wrong = command(aula::sim_control_t::SET_RTF, -3.0);
  bus.publish(aula::lcmbus::kControlChannel, &wrong);
  const auto pause = command(aula::sim_control_t::PAUSE);
  bus.publish(aula::lcmbus::kControlChannel, &pause);
  simSecondsIn(sim, std::chrono::milliseconds(100));
  EXPECT_EQ(sim.rejectedControls(), 1);
  EXPECT_DOUBLE_EQ(simSecondsIn(sim, std::chrono::milliseconds(200)), 0.0) << "paused";
  const auto step = command(aula::sim_control_t::STEP);
  bus.publish(aula::lcmbus::kControlChannel, &step);
  EXPECT_NEAR(simSecondsIn(sim, std::chrono::milliseconds(200)), options.clock_period_us / 1e6, 1e-9) << "one tick";
}

// A graded run (the simulator has the run's key): only SIM_CONTROL signed with it is obeyed,
// each signed request once; the rest is refused, counted, and said in the signed clock.
TEST(SimulatorControl, AGradedSimulatorObeysOnlySignedControlOnce) {
  aula::lcmbus::Bus bus("memq://");
  const aula::auth::Key key = aula::auth::randomKey();
  aula::sim::Simulator sim(aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world"), {}, bus, key);
  const int roomba = sim.physics().robotIndex("roomba");
  const Eigen::Vector3d start = sim.physics().robotState(roomba).position_m;
  std::vector<aula::sim_clock_t> ticks;
  struct Ticks {
    std::vector<aula::sim_clock_t>* out;
    void on(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t* t) { out->push_back(*t); }
  } listener{&ticks};
  bus.subscribe(aula::lcmbus::kClockChannel, &Ticks::on, &listener);
  auto send = [&](const aula::sim_control_t& msg) {
    bus.publish(aula::lcmbus::kControlChannel, &msg);
    while (bus.handleTimeout(0) > 0) {
    }
  };
  aula::sim_control_t teleport = setPose("roomba", start.x() + 0.5, start.y(), 0.0);
  teleport.auth_seq = 1;
  send(teleport);  // unsigned
  aula::sim_control_t other_key = teleport;
  aula::auth::sign(aula::auth::Signer(aula::auth::randomKey()), aula::lcmbus::kControlChannel, other_key);
  send(other_key);
  EXPECT_EQ(sim.rejectedControls(), 2);
  EXPECT_NEAR((sim.physics().robotState(roomba).position_m - start).norm(), 0.0, 1e-9);

  aula::auth::sign(aula::auth::Signer(key), aula::lcmbus::kControlChannel, teleport);
  send(teleport);
  EXPECT_EQ(sim.rejectedControls(), 2);
  EXPECT_NEAR(sim.physics().robotState(roomba).position_m.x(), start.x() + 0.5, 1e-6);
  send(teleport);  // the same signed request again: a replay
  EXPECT_EQ(sim.rejectedControls(), 3);

  sim.advanceToNextTick();
  while (bus.handleTimeout(0) > 0) {
  }
  ASSERT_FALSE(ticks.empty());
  EXPECT_EQ(ticks.back().rejected_controls, 3);
  EXPECT_TRUE(aula::auth::verify(aula::auth::Signer(key), aula::lcmbus::kClockChannel, ticks.back())) << "the clock is signed";
}

TEST(SimulatorControl, WithoutAKeyTheWindowsControlsWorkAsBefore) {
  aula::lcmbus::Bus bus("memq://");
  aula::sim::Simulator sim(aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world"), {}, bus);
  const int roomba = sim.physics().robotIndex("roomba");
  const Eigen::Vector3d start = sim.physics().robotState(roomba).position_m;
  const aula::sim_control_t teleport = setPose("roomba", start.x() + 0.5, start.y(), 0.0);
  bus.publish(aula::lcmbus::kControlChannel, &teleport);
  while (bus.handleTimeout(0) > 0) {
  }
  EXPECT_EQ(sim.rejectedControls(), 0);
  EXPECT_NEAR(sim.physics().robotState(roomba).position_m.x(), start.x() + 0.5, 1e-6);
}
