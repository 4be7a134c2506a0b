// Drivers inside the real simulator core on the in-process memq:// bus.
#include <aula/bumper_t.hpp>
#include <aula/laser_t.hpp>
#include <aula/motors_t.hpp>
#include <aula/pose3d_t.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/sim/simulator.hpp>
#include <aula/sim_control_t.hpp>

#include "motors_driver.hpp"

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <cmath>
#include <limits>

namespace {

using aula::world::PluginSpec;
using aula::world::RobotSpec;
using aula::world::ShapeKind;
using aula::world::StaticObject;
using aula::world::WorldSpec;

StaticObject wallBox(const std::string& name, double cx, double cy, double sx, double sy) {
  StaticObject o;
  o.name = name;
  o.pose.translation() = Eigen::Vector3d(cx, cy, 1.0);
  o.shape.kind = ShapeKind::Box;
  o.shape.box_size_m = Eigen::Vector3d(sx, sy, 2.0);
  return o;
}

PluginSpec plugin(const std::string& type, std::map<std::string, std::string> params) {
  PluginSpec p;
  p.name = type;
  p.type = type;
  p.owner = "bot";
  p.params = std::move(params);
  return p;
}

// A 10 x 10 m room (inner faces at +-5 m) and a roomba-sized robot at (x, y, yaw).
WorldSpec room(double x, double y, double yaw, double max_v = 25.0, double noise = 0.0) {
  WorldSpec w;
  w.name = "room";
  w.statics.push_back(wallBox("east", 5.25, 0, 0.5, 11));
  w.statics.push_back(wallBox("west", -5.25, 0, 0.5, 11));
  w.statics.push_back(wallBox("north", 0, 5.25, 11, 0.5));
  w.statics.push_back(wallBox("south", 0, -5.25, 11, 0.5));
  RobotSpec r;
  r.name = "bot";
  r.mass_kg = 2.5;
  r.shape.kind = ShapeKind::Cylinder;
  r.shape.radius_m = 0.165;
  r.shape.length_m = 0.09;
  r.shape_offset.translation() = Eigen::Vector3d(0, 0, 0.045);
  r.pose = Eigen::Translation3d(x, y, 0) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
  r.plugins.push_back(plugin("pose3d", {{"channel", "POSE"}, {"rate_hz", "100"}}));
  r.plugins.push_back(plugin("motors", {{"channel", "MOTORS"},
                                        {"max_v", std::to_string(max_v)},
                                        {"max_w", "3"},
                                        {"watchdog_s", "0.5"}}));
  r.plugins.push_back(plugin("laser", {{"channel", "LASER"},
                                       {"pose", "0.1 0 0.075 0 0 0"},
                                       {"samples", "180"},
                                       {"min_angle", "-1.5707963267948966"},
                                       {"max_angle", "1.5707963267948966"},
                                       {"min_range", "0.08"},
                                       {"max_range", "10"},
                                       {"rate_hz", "20"},
                                       {"noise_stddev", std::to_string(noise)}}));
  r.plugins.push_back(plugin("bumper", {{"channel", "BUMPER"}}));
  w.robots.push_back(r);
  return w;
}

// Test-side view of the bus: the latest message of each kind.
struct Listener {
  explicit Listener(aula::lcmbus::Bus& bus) {
    bus.subscribe("POSE", &Listener::onPose, this);
    bus.subscribe("LASER", &Listener::onLaser, this);
    bus.subscribe("BUMPER", &Listener::onBumper, this);
  }
  void onPose(const lcm::ReceiveBuffer*, const std::string&, const aula::pose3d_t* m) {
    pose = *m;
    poses.push_back(*m);
  }
  void onLaser(const lcm::ReceiveBuffer*, const std::string&, const aula::laser_t* m) {
    laser = *m;
    ++scans;
  }
  void onBumper(const lcm::ReceiveBuffer*, const std::string&, const aula::bumper_t* m) {
    bumper = *m;
    if (m->state == aula::bumper_t::PRESSED) ever_pressed = true;
  }
  aula::pose3d_t pose{};
  std::vector<aula::pose3d_t> poses;
  aula::laser_t laser{};
  int scans = 0;
  aula::bumper_t bumper{};
  bool ever_pressed = false;
};

void drain(aula::lcmbus::Bus& bus) {
  while (bus.handleTimeout(0) > 0) {
  }
}

void send(aula::lcmbus::Bus& bus, double v, double w = 0.0) {
  aula::motors_t m{};
  m.v = v;
  m.w = w;
  bus.publish("MOTORS", &m);
}

aula::sim::SimulatorOptions fastOptions() {
  aula::sim::SimulatorOptions o;
  o.real_time_factor = 0;
  o.clock_period_us = 20000;
  return o;
}

// Runs the simulator for `seconds` of sim time, handling the bus at every tick.
void runFor(aula::sim::Simulator& sim, aula::lcmbus::Bus& bus, double seconds) {
  const int64_t end = sim.timeUs() + static_cast<int64_t>(seconds * 1e6);
  while (sim.timeUs() < end) {
    drain(bus);
    sim.advanceToNextTick();
  }
  drain(bus);
}

// Analytic range in the room from (x, y) along angle a (inner faces at +-5).
double roomRange(double x, double y, double a) {
  double best = std::numeric_limits<double>::infinity();
  const double c = std::cos(a), s = std::sin(a);
  if (c > 1e-12) best = std::min(best, (5 - x) / c);
  if (c < -1e-12) best = std::min(best, (-5 - x) / c);
  if (s > 1e-12) best = std::min(best, (5 - y) / s);
  if (s < -1e-12) best = std::min(best, (-5 - y) / s);
  return best;
}

}  // namespace

TEST(LaserDriver, RangesMatchAnalyticDistances) {
  aula::lcmbus::Bus bus("memq://");
  Listener listener(bus);
  const double x = 0.7, y = -1.2, yaw = 0.3;
  aula::sim::Simulator sim(room(x, y, yaw), fastOptions(), bus);
  runFor(sim, bus, 0.06);
  ASSERT_GE(listener.scans, 1);
  const auto& scan = listener.laser;
  ASSERT_EQ(scan.num_ranges, 180);
  EXPECT_NEAR(scan.angle_increment, M_PI / 179, 1e-6);
  const double sx = listener.pose.x + 0.1 * std::cos(listener.pose.yaw);
  const double sy = listener.pose.y + 0.1 * std::sin(listener.pose.yaw);
  for (int i = 0; i < scan.num_ranges; ++i) {
    const double a = listener.pose.yaw + scan.min_angle + i * static_cast<double>(scan.angle_increment);
    const double expected = std::min(10.0, roomRange(sx, sy, a));
    EXPECT_NEAR(scan.ranges[i], expected, 0.01) << "beam " << i;
  }
}

// The run's noise (Simulator.Noise.*): about the asked share of beams read max_range, the others
// stay near the truth; the wheels deliver another distance than commanded, the same for the same
// seed.
TEST(SensorNoise, DropoutsReadMaxRangeAndSlipChangesTheDistanceDriven) {
  aula::lcmbus::Bus bus("memq://");
  Listener listener(bus);
  aula::sim::SimulatorOptions noisy = fastOptions();
  noisy.noise.laser_dropout = 0.2;
  aula::sim::Simulator sim(room(0.7, -1.2, 0.3), noisy, bus);
  int lost = 0, beams = 0;
  for (int i = 0; i < 10; ++i) {
    runFor(sim, bus, 0.05);
    for (float r : listener.laser.ranges) {
      lost += r == listener.laser.max_range ? 1 : 0;  // the room is 10 m wide: no beam reaches 10 m
      ++beams;
    }
  }
  EXPECT_NEAR(static_cast<double>(lost) / beams, 0.2, 0.03) << lost << " of " << beams;

  auto driven = [](double slip, uint64_t seed) {
    aula::lcmbus::Bus slip_bus("memq://");
    Listener poses(slip_bus);
    aula::sim::SimulatorOptions o = fastOptions();
    o.noise.wheel_slip = slip;
    o.seed = static_cast<int64_t>(seed);
    aula::sim::Simulator slipping(room(-3, 0, 0), o, slip_bus);
    for (int i = 0; i < 50; ++i) {
      send(slip_bus, 1.0);
      runFor(slipping, slip_bus, 0.04);
    }
    return poses.pose.x;
  };
  const double exact = driven(0.0, 1), slipped = driven(0.2, 1);
  EXPECT_GT(std::abs(slipped - exact), 0.01) << "no slip: " << exact;
  EXPECT_DOUBLE_EQ(driven(0.2, 1), slipped) << "the same seed slips the same";
  EXPECT_NE(driven(0.2, 2), slipped) << "another seed slips otherwise";
}

class WallImpact : public ::testing::TestWithParam<double> {};

TEST_P(WallImpact, StopsAtTheWallWithBumperPressed) {
  const double speed = GetParam();
  aula::lcmbus::Bus bus("memq://");
  Listener listener(bus);
  aula::sim::Simulator sim(room(0, 0, 0), fastOptions(), bus);
  double max_x = -1e9;
  for (int i = 0; i < 200 && !listener.ever_pressed; ++i) {
    send(bus, speed);
    runFor(sim, bus, 0.02);
    max_x = std::max(max_x, listener.pose.x);
  }
  for (int i = 0; i < 50; ++i) {  // keep pushing into the wall for a second
    send(bus, speed);
    runFor(sim, bus, 0.02);
    max_x = std::max(max_x, listener.pose.x);
  }
  EXPECT_TRUE(listener.ever_pressed);
  EXPECT_EQ(listener.bumper.state, int8_t{aula::bumper_t::PRESSED});
  EXPECT_EQ(listener.bumper.bumper, int8_t{aula::bumper_t::CENTER});
  const double penetration = max_x + 0.165 - 5.0;
  EXPECT_LT(penetration, 0.02) << "at " << speed << " m/s";
  EXPECT_NEAR(listener.pose.z, 0.0, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Speeds, WallImpact, ::testing::Values(1.0, 5.0, 20.0));

TEST(MotorsDriver, WatchdogStopsASilentClient) {
  aula::lcmbus::Bus bus("memq://");
  Listener listener(bus);
  aula::sim::Simulator sim(room(-3, 0, 0), fastOptions(), bus);
  send(bus, 1.0);
  runFor(sim, bus, 0.3);
  const double moving_x = listener.pose.x;
  EXPECT_GT(moving_x, -2.85);  // it moved
  runFor(sim, bus, 0.7);         // no command for > 0.5 s
  const double x_after_watchdog = listener.pose.x;
  runFor(sim, bus, 1.0);
  EXPECT_NEAR(listener.pose.x, x_after_watchdog, 0.01) << "the robot kept moving";
  EXPECT_LT(listener.pose.x, -1.9);
}

TEST(MotorsDriver, NonFiniteCommandIsIgnored) {
  aula::lcmbus::Bus bus("memq://");
  Listener listener(bus);
  aula::sim::Simulator sim(room(-3, 0, 0), fastOptions(), bus);
  send(bus, 1.0);
  runFor(sim, bus, 0.2);
  send(bus, std::numeric_limits<double>::quiet_NaN());
  send(bus, std::numeric_limits<double>::infinity(), 1.0);
  const double x0 = listener.pose.x;
  runFor(sim, bus, 0.2);
  EXPECT_NEAR(listener.pose.x - x0, 0.2, 0.03) << "the previous command should still hold";
  EXPECT_TRUE(std::isfinite(listener.pose.x));
  EXPECT_NEAR(listener.pose.yaw, 0.0, 1e-3);
}

TEST(MotorsDriver, FilterClampsAndRejects) {
  aula::drivers::MotorLimits limits;
  limits.max_v_mps = 2;
  limits.max_w_radps = 1;
  aula::drivers::VelocityCommand c;
  ASSERT_TRUE(aula::drivers::filterCommand(limits, 50, -7, 3, c));
  EXPECT_EQ(c.v_mps, 2);
  EXPECT_EQ(c.w_radps, -1);
  EXPECT_EQ(c.l_mps, 0);  // not holonomic
  EXPECT_FALSE(aula::drivers::filterCommand(limits, NAN, 0, 0, c));
  EXPECT_EQ(c.v_mps, 2);  // unchanged
  limits.ackermann = true;
  limits.min_turn_radius_m = 5;
  ASSERT_TRUE(aula::drivers::filterCommand(limits, 1.0, 1.0, 0, c));
  EXPECT_NEAR(c.w_radps, 0.2, 1e-12);  // |w| <= |v| / R
  ASSERT_TRUE(aula::drivers::filterCommand(limits, 0.0, 1.0, 0, c));
  EXPECT_EQ(c.w_radps, 0.0);  // a car cannot turn in place
  EXPECT_EQ(c.l_mps, 0.0);
}

TEST(MotorsDriver, AckermannTurnsAboutTheRearAxle) {
  aula::drivers::MotorLimits limits;
  limits.max_v_mps = 3;
  limits.max_w_radps = 1;
  limits.ackermann = true;
  limits.min_turn_radius_m = 5;
  limits.rear_axle_x_m = -1.3;
  aula::drivers::VelocityCommand c;
  // The student's l is ignored; the centre slides so the rear axle has no sideways speed.
  ASSERT_TRUE(aula::drivers::filterCommand(limits, -2.0, 0.3, 9.0, c));
  EXPECT_NEAR(c.w_radps, 0.3, 1e-12);
  EXPECT_NEAR(c.l_mps, 0.39, 1e-12);
  const double rear_axle_lateral = c.l_mps + c.w_radps * limits.rear_axle_x_m;
  EXPECT_NEAR(rear_axle_lateral, 0.0, 1e-12);
  // Turning radius of the rear axle: |v| / |w| never below R.
  ASSERT_TRUE(aula::drivers::filterCommand(limits, 1.0, -1.0, 0, c));
  EXPECT_NEAR(std::abs(c.v_mps / c.w_radps), 5.0, 1e-12);
  EXPECT_NEAR(c.l_mps, -0.26, 1e-12);
}

namespace {
// A deterministic bounce controller on noisy laser data; returns the pose stream.
std::vector<aula::pose3d_t> bounceRun(int64_t seed) {
  aula::lcmbus::Bus bus("memq://");
  Listener listener(bus);
  auto options = fastOptions();
  options.seed = seed;
  aula::sim::Simulator sim(room(-1, 0.5, 0.2, 0.5, 0.01), options, bus);
  for (int i = 0; i < 500; ++i) {
    double front = 10;
    for (int b = 60; b < 120 && listener.scans > 0; ++b) front = std::min<double>(front, listener.laser.ranges[b]);
    if (listener.ever_pressed || front < 0.5) {
      send(bus, 0.0, 1.5);
      listener.ever_pressed = false;
    } else {
      send(bus, 0.5, front * 0.01);
    }
    runFor(sim, bus, 0.08);
  }
  return listener.poses;
}

bool samePoses(const std::vector<aula::pose3d_t>& a, const std::vector<aula::pose3d_t>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].utime != b[i].utime || a[i].x != b[i].x || a[i].y != b[i].y || a[i].yaw != b[i].yaw) return false;
  }
  return true;
}
}  // namespace

TEST(Simulator, SameSeedGivesIdenticalPoseStreams) {
  const auto a = bounceRun(7);
  const auto b = bounceRun(7);
  ASSERT_GT(a.size(), 1000u);
  EXPECT_TRUE(samePoses(a, b));
  const auto c = bounceRun(8);
  EXPECT_FALSE(samePoses(a, c)) << "laser noise should depend on the seed";
}

TEST(Simulator, ControlChannelTeleportsPausesAndResets) {
  aula::lcmbus::Bus bus("memq://");
  Listener listener(bus);
  aula::sim::Simulator sim(room(0, 0, 0), fastOptions(), bus);
  aula::sim_control_t cmd{};
  cmd.command = aula::sim_control_t::SET_POSE;
  cmd.robot = "bot";
  cmd.x = 2.0;
  cmd.y = -3.0;
  cmd.yaw = 1.0;
  bus.publish(aula::lcmbus::kControlChannel, &cmd);
  runFor(sim, bus, 0.1);
  EXPECT_NEAR(listener.pose.x, 2.0, 1e-6);
  EXPECT_NEAR(listener.pose.y, -3.0, 1e-6);
  EXPECT_NEAR(listener.pose.yaw, 1.0, 1e-6);
  cmd.robot = "nobody";  // unknown robot: logged and ignored
  bus.publish(aula::lcmbus::kControlChannel, &cmd);
  cmd.robot = "bot";
  cmd.x = NAN;  // non-finite pose: ignored
  bus.publish(aula::lcmbus::kControlChannel, &cmd);
  runFor(sim, bus, 0.1);
  EXPECT_NEAR(listener.pose.x, 2.0, 1e-6);
  cmd.command = aula::sim_control_t::RESET;
  bus.publish(aula::lcmbus::kControlChannel, &cmd);
  drain(bus);
  EXPECT_EQ(sim.timeUs(), 0) << "reset sets the clock back";
  sim.advanceToNextTick();
  drain(bus);
  EXPECT_NEAR(listener.pose.x, 0.0, 1e-6);
}
