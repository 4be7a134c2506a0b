#include <aula/component/control_loop.hpp>
#include <aula/component/proxies.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/sim_clock_t.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>
#include <limits>

using namespace aula::component;

namespace {
void drain(aula::lcmbus::Bus& bus) {
  while (bus.handleTimeout(0) > 0) {
  }
}
}  // namespace

TEST(LaserProxy, MillimetreViewMatchesMetres) {
  aula::lcmbus::Bus bus("memq://");
  LaserProxy laser(bus, "LASER");
  aula::laser_t msg{};
  msg.utime = 123;
  msg.ranges = {0.08f, 1.2345f, 9.9996f, 10.0f};
  msg.num_ranges = 4;
  msg.min_angle = -1.5f;
  msg.max_angle = 1.5f;
  msg.angle_increment = 1.0f;
  msg.min_range = 0.08f;
  msg.max_range = 10.0f;
  bus.publish("LASER", &msg);
  drain(bus);
  const LaserData& d = laser.getLaserData();
  ASSERT_EQ(d.numLaser, 4);
  ASSERT_EQ(d.distanceData.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(d.distanceData[i] / 1000.0, d.values_m[i], 0.0005) << i;
  }
  EXPECT_EQ(d.distanceData[1], 1235);
  EXPECT_EQ(d.distanceData[3], 10000);
  EXPECT_DOUBLE_EQ(d.angle(2), 0.5);
  EXPECT_EQ(d.timeStamp, 123);
}

TEST(LaserProxy, TheMillimetresAreStdLroundsForEveryRange) {
  // The original's ints, rounded as std::lround rounds (halves away from zero), for every float a
  // range may be: halves, their neighbours, the far end, and what no range is (not finite, huge).
  std::vector<float> ranges;
  for (int mm = -3000; mm <= 3000; ++mm) {
    const float half = (mm + 0.5f) / 1000.0f;
    ranges.insert(ranges.end(), {half, std::nextafter(half, 0.0f), std::nextafter(half, 100.0f), mm / 1000.0f});
  }
  for (uint32_t bits = 0x3c000000; bits < 0x42000000; bits += 4099) {  // 0.0078 m to 32 m, spread
    float range = 0;
    std::memcpy(&range, &bits, sizeof range);
    ranges.push_back(range);
  }
  ranges.insert(ranges.end(), {0.0f, -0.0f, 1e7f, -1e7f, 3e9f, std::numeric_limits<float>::infinity(),
                               std::numeric_limits<float>::quiet_NaN()});
  aula::component::Laser laser;
  LaserData scan;
  scan.values_m = ranges;
  scan.numLaser = static_cast<int>(ranges.size());
  laser.set(scan);
  const LaserData& d = laser.getLaserData();
  ASSERT_EQ(d.distanceData.size(), ranges.size());
  for (size_t i = 0; i < ranges.size(); ++i) {
    ASSERT_EQ(d.distanceData[i], static_cast<int>(std::lround(ranges[i] * 1000.0))) << "range " << ranges[i];
  }
}

TEST(MotorsProxy, ClampsToTheExerciseLimitsAndZeroesNonFinite) {
  aula::lcmbus::Bus bus("memq://");
  MotorsProxy motors(bus, "MOTORS", 2.0, 0.5);
  motors.sendV(10);
  motors.sendW(-3);
  EXPECT_EQ(motors.getV(), 2.0);
  EXPECT_EQ(motors.getW(), -0.5);
  motors.sendV(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(motors.getV(), 0.0);
  motors.setW(0.25);  // TeleTaxi alias
  EXPECT_EQ(motors.getW(), 0.25);
}

TEST(ControlLoop, RunsTheAlgorithmOnSimTimeAndPublishesEveryPeriod) {
  aula::lcmbus::Bus bus("memq://");
  MotorsProxy motors(bus, "MOTORS", 1.0, 1.0);
  int executions = 0;
  ControlLoop loop(bus, "test", 80000, motors, [&] {
    ++executions;
    motors.sendV(0.5);
  });
  struct Sink {
    int count = 0;
    double last_v = -1;
    void on(const lcm::ReceiveBuffer*, const std::string&, const aula::motors_t* m) {
      ++count;
      last_v = m->v;
    }
  } sink;
  bus.subscribe("MOTORS", &Sink::on, &sink);
  auto tick = [&](int64_t seq, int64_t utime) {
    aula::sim_clock_t t{};
    t.seq = seq;
    t.utime = utime;
    bus.publish(aula::lcmbus::kClockChannel, &t);
    drain(bus);
  };
  tick(0, 0);  // due, not running: command published, algorithm not run
  EXPECT_EQ(executions, 0);
  EXPECT_EQ(sink.count, 1);
  loop.setRunning(true);
  for (int i = 1; i <= 8; ++i) tick(i, i * 20000);  // 160 ms: due at 80 and 160 ms
  EXPECT_EQ(executions, 2);
  EXPECT_EQ(sink.count, 3);
  EXPECT_EQ(sink.last_v, 0.5);
  loop.setRunning(false);
  tick(9, 240000);
  EXPECT_EQ(executions, 2);
  EXPECT_EQ(sink.last_v, 0.0) << "stopping the algorithm stops the robot";
}
