// What crosses to the algorithm's own process (box_wire.hpp): each device written at one end
// reads back the same at the other, a belief's map crosses once per setMap, and a short or
// overlong message is refused naming what was being read.
#include <aula/component/box_wire.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace aula::component {
namespace {

TEST(BoxWire, EveryDeviceReadsBackAsItWasWritten) {
  Pose3d pose;
  pose.set(1.5, -2.25, 0.75, 123456);
  Laser laser;
  LaserData scan;
  scan.values_m = {0.5f, 1.25f, 7.0f};
  scan.numLaser = 3;
  scan.minAngle = -1.5;
  scan.maxAngle = 1.5;
  scan.angleIncrement = 1.5;
  scan.minRange = 0.1;
  scan.maxRange = 8;
  scan.timeStamp = 42;
  laser.set(scan);
  Bumper bumper;
  bumper.set({2, 1, 99});
  SimClock clock;
  clock.set(8'000'000);
  Motors motors(0.5, 3.0);
  motors.sendV(0.25);
  motors.sendW(-9);  // clamped to -3 here, and so it crosses

  BoxWire out = BoxWire::writing();
  ioPose(out, pose);
  ioLaser(out, laser);
  ioBumper(out, bumper);
  ioClock(out, clock);
  ioMotorCommands(out, motors);

  BoxWire in = BoxWire::reading(out.bytes());
  Pose3d pose2;
  Laser laser2;
  Bumper bumper2;
  SimClock clock2;
  Motors motors2(0.5, 3.0);
  ioPose(in, pose2);
  ioLaser(in, laser2);
  ioBumper(in, bumper2);
  ioClock(in, clock2);
  ioMotorCommands(in, motors2);
  in.expectEnd("test");

  EXPECT_TRUE(pose2.received());
  EXPECT_EQ(pose2.getX(), 1.5);
  EXPECT_EQ(pose2.getY(), -2.25);
  EXPECT_EQ(pose2.getYaw(), 0.75);
  EXPECT_EQ(pose2.utime(), 123456);
  EXPECT_EQ(laser2.getLaserData().values_m, scan.values_m);
  EXPECT_EQ(laser2.getLaserData().distanceData, (std::vector<int>{500, 1250, 7000}));  // derived again
  EXPECT_EQ(laser2.getLaserData().timeStamp, 42);
  EXPECT_EQ(laser2.getLaserData().maxRange, 8);
  EXPECT_EQ(bumper2.getBumperData().bumper, 2);
  EXPECT_EQ(bumper2.getBumperData().state, 1);
  EXPECT_EQ(clock2.utime(), 8'000'000);
  EXPECT_EQ(motors2.getV(), 0.25);
  EXPECT_EQ(motors2.getW(), -3.0);
  EXPECT_EQ(motors2.nonFiniteTotal(), 0);
}

TEST(BoxWire, ABeliefsMapCrossesOncePerSetMap) {
  Belief belief;
  belief.setPose(1, 2, 3);
  belief.setMap({2, 1, 0.5, -1, -2, {0, 255}});
  int64_t sent = 0;
  BoxWire first = BoxWire::writing();
  ioBelief(first, belief, sent);
  EXPECT_EQ(sent, 1);
  BoxWire second = BoxWire::writing();
  ioBelief(second, belief, sent);
  EXPECT_LT(second.bytes().size(), first.bytes().size());  // the pose only

  Belief here;
  int64_t unused = 0;
  BoxWire in = BoxWire::reading(first.bytes());
  ioBelief(in, here, unused);
  in.expectEnd("test");
  EXPECT_TRUE(here.hasPose());
  EXPECT_EQ(here.yaw_rad(), 3);
  EXPECT_EQ(here.mapVersion(), 1);
  EXPECT_EQ(here.map().cells, (std::vector<uint8_t>{0, 255}));
  BoxWire again = BoxWire::reading(second.bytes());
  ioBelief(again, here, unused);
  EXPECT_EQ(here.mapVersion(), 1);  // no new map: the window is not told of one
}

TEST(BoxWire, AShortOrOverlongMessageIsRefusedNamingWhat) {
  Laser laser;
  LaserData scan;
  scan.values_m = {1, 2, 3};
  scan.numLaser = 3;
  laser.set(scan);
  BoxWire out = BoxWire::writing();
  ioLaser(out, laser);
  const std::string bytes = out.bytes();

  BoxWire shorter = BoxWire::reading(bytes.substr(0, bytes.size() - 4));
  Laser into;
  try {
    ioLaser(shorter, into);
    FAIL() << "a short message was read";
  } catch (const BoxWireError& e) {
    EXPECT_EQ(std::string(e.what()), "laser: the message ends 4 bytes short");
  }
  BoxWire longer = BoxWire::reading(bytes + "xx");
  ioLaser(longer, into);
  EXPECT_THROW(longer.expectEnd("call"), BoxWireError);

  std::string text(100, 'x');
  BoxWire cut = BoxWire::writing();
  cut.io(text, 10, "status");  // cut when written
  BoxWire read = BoxWire::reading(cut.bytes());
  std::string back;
  read.io(back, 10, "status");
  EXPECT_EQ(back, std::string(10, 'x'));
  BoxWire whole = BoxWire::writing();
  whole.io(text, 1000, "status");
  BoxWire refused = BoxWire::reading(whole.bytes());
  EXPECT_THROW(refused.io(back, 10, "status"), BoxWireError);  // refused when read
}

}  // namespace
}  // namespace aula::component
