// aula-demo-client [--config=config/demo.cfg] [--duration=S] [--lcm-url=URL] [--Demo.Key=value]
// A minimal academic-component stand-in: reads a robot's pose, laser and bumper from the
// simulator and bounces around with a reactive rule, printing what it sees once per sim second.
// It shows the whole path sensor -> LCM -> client -> LCM -> motors without any exercise code.
#include <aula/app/bus_pump.hpp>
#include <aula/app/process_setup.hpp>
#include <aula/bumper_t.hpp>
#include <aula/config/config.hpp>
#include <aula/laser_t.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/lcm/lockstep_client.hpp>
#include <aula/motors_t.hpp>
#include <aula/pose3d_t.hpp>
#include <aula/process/guarded_main.hpp>

#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include <unistd.h>

namespace {

constexpr const char* kUsage =
    "usage: aula-demo-client [--config=config/demo.cfg] [--duration=S] [--quiet] [--lcm-url=URL] [--Demo.Key=value]\n"
    "A minimal client: the roomba bouncing around the house, printing what it sees once per sim second.\n";

struct Demo {
  void onPose(const lcm::ReceiveBuffer*, const std::string&, const aula::pose3d_t* m) { pose = *m; }
  void onLaser(const lcm::ReceiveBuffer*, const std::string&, const aula::laser_t* m) {
    laser = *m;
    have_laser = true;
  }
  void onBumper(const lcm::ReceiveBuffer*, const std::string&, const aula::bumper_t* m) {
    bumper = *m;
    if (m->state == aula::bumper_t::PRESSED) ++bumps;
  }

  // Reactive bounce: forward while the way is clear, back off and turn after a bump.
  aula::motors_t control(int64_t utime) {
    aula::motors_t cmd{};
    cmd.utime = utime;
    float front = have_laser ? laser.max_range : 10.0f;
    if (have_laser && laser.num_ranges > 0) {
      const int n = laser.num_ranges;
      for (int i = n / 3; i < 2 * n / 3; ++i) front = std::min(front, laser.ranges[i]);
    }
    if (bumper.state == aula::bumper_t::PRESSED) turning_until_us = utime + 1'200'000;
    if (utime < turning_until_us || front < clearance_m) {
      cmd.v = utime < turning_until_us - 900'000 ? -0.1 : 0.0;
      cmd.w = turn_radps;
    } else {
      cmd.v = max_v;
      cmd.w = 0.0;
    }
    return cmd;
  }

  aula::pose3d_t pose{};
  aula::laser_t laser{};
  aula::bumper_t bumper{};
  bool have_laser = false;
  long bumps = 0;
  int64_t turning_until_us = 0;
  double max_v = 0.3, turn_radps = 1.0, clearance_m = 0.4;
};

}  // namespace

int main(int argc, char** argv) {
  using namespace aula;
  return process::guardedMain("aula-demo-client", [&] {
    auto setup = app::ProcessSetup::fromArgs(argc, argv, "aula-demo-client", {"duration", "quiet"}, kUsage, false);
    const config::Config& cfg = setup.cfg;
    const config::CommandLine& cl = setup.command_line;
    Demo demo;
    demo.max_v = cfg.getDouble("Demo.MaxV");
    demo.turn_radps = cfg.getDouble("Demo.TurnW");
    demo.clearance_m = cfg.getDouble("Demo.Clearance");
    const int64_t period_us = static_cast<int64_t>(cfg.getDouble("Demo.Period") * 1e6);
    const double duration_s = cl.optionDouble("duration", 0);
    const world::RobotSpec& robot = world::requireRobot(setup.world, cfg.getString("Demo.Robot"));
    const std::string motors = world::channelOf(robot, "motors");
    const bool quiet = cl.flag("quiet");

    lcmbus::Bus* bus = setup.bus.get();
    bus->subscribe(world::channelOf(robot, "pose3d"), &Demo::onPose, &demo);
    bus->subscribe(world::channelOf(robot, "laser"), &Demo::onLaser, &demo);
    bus->subscribe(world::channelOf(robot, "bumper"), &Demo::onBumper, &demo);

    int64_t last_print_s = -1;
    bool done = false;
    lcmbus::LockstepClient clock(*bus, "aula-demo-client", period_us, [&](int64_t utime) {
      aula::motors_t cmd = demo.control(utime);
      bus->publish(motors, &cmd);
      if (!quiet && utime / 1'000'000 != last_print_s) {
        last_print_s = utime / 1'000'000;
        std::printf("t=%6.1f s  x=%6.2f y=%6.2f yaw=%5.2f  front=%5.2f m  bumps=%ld  v=%.2f w=%.2f\n",
                    utime / 1e6, demo.pose.x, demo.pose.y, demo.pose.yaw,
                    demo.have_laser ? demo.laser.ranges[demo.laser.num_ranges / 2] : -1.0f,
                    demo.bumps, cmd.v, cmd.w);
        std::fflush(stdout);
      }
      if (duration_s > 0 && utime >= duration_s * 1e6) done = true;
    });

    app::runHeadless(*bus, [&] { return done; }, [&] { clock.poll(); });
    clock.leave();
    aula::motors_t stop{};
    bus->publish(motors, &stop);
    std::printf("aula-demo-client: done at t=%.1f s sim, %ld bump messages\n", clock.simTimeUs() / 1e6,
                demo.bumps);
    return 0;
  });
}
