#include "../support/mesh_files.hpp"

#include <aula/physics/physics_world.hpp>

#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/ShapeNode.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/simulation/World.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <set>

using aula::physics::PhysicsWorld;
using namespace aula::world;

namespace {

StaticObject box(const std::string& name, double cx, double cy, double sx, double sy) {
  StaticObject o;
  o.name = name;
  o.pose.translation() = Eigen::Vector3d(cx, cy, 1.0);
  o.shape.box_size_m = Eigen::Vector3d(sx, sy, 2.0);
  return o;
}

RobotSpec taxi(const std::string& name, double x, double y, double yaw) {
  RobotSpec r;
  r.name = name;
  r.mass_kg = 750;
  r.shape.box_size_m = Eigen::Vector3d(4, 2, 1.5);
  r.shape_offset.translation() = Eigen::Vector3d(0, 0, 0.75);
  r.pose = Eigen::Translation3d(x, y, 0) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
  return r;
}

// A 0.2 m thick wall whose near face is at x = 10, and the taxi at the origin facing it.
WorldSpec wallWorld() {
  WorldSpec w;
  w.name = "wall";
  w.statics.push_back(box("wall", 10.1, 0, 0.2, 40));
  w.robots.push_back(taxi("taxi", 0, 0, 0));
  return w;
}

void run(PhysicsWorld& p, double seconds) {
  const int64_t end = p.timeUs() + static_cast<int64_t>(seconds * 1e6);
  while (p.timeUs() < end) p.step();
}

}  // namespace

class TaxiIntoWall : public ::testing::TestWithParam<double> {};

TEST_P(TaxiIntoWall, StopsWithoutPassingThrough) {
  PhysicsWorld p(wallWorld(), 0.005);
  p.commandVelocity(0, GetParam(), 0);
  double max_front = -1e9;
  bool touched = false;
  for (int i = 0; i < 2400; ++i) {  // 12 s
    p.step();
    max_front = std::max(max_front, p.robotState(0).position_m.x() + 2.0);
    if (p.contact(0).in_contact) {
      touched = true;
      EXPECT_NEAR(p.contact(0).bearing_rad, 0.0, 0.3);
    }
  }
  EXPECT_TRUE(touched);
  EXPECT_LT(max_front - 10.0, 0.02) << "penetration at " << GetParam() << " m/s";
  EXPECT_LT(p.robotState(0).position_m.x(), 10.0);
  EXPECT_DOUBLE_EQ(p.robotState(0).position_m.z(), 0.0);
  EXPECT_NEAR(p.robotState(0).yaw_rad, 0.0, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Speeds, TaxiIntoWall, ::testing::Values(1.0, 5.0, 20.0));

TEST(PhysicsWorld, AtAnAngleItSlidesAlongTheWall) {
  PhysicsWorld p(wallWorld(), 0.005);
  p.setRobotPose(0, 5, 0, 0.3);
  p.commandVelocity(0, 2.0, 0);
  run(p, 6.0);
  const auto s = p.robotState(0);
  EXPECT_LT(s.position_m.x(), 10.0);
  EXPECT_GT(s.position_m.y(), 1.0) << "it should slide along the wall, not stick";
}

TEST(PhysicsWorld, FollowsVelocityCommandsInFreeSpace) {
  WorldSpec w;
  w.robots.push_back(taxi("taxi", 0, 0, 0));
  PhysicsWorld p(w, 0.005);
  p.commandVelocity(0, 0, 1.0);
  run(p, 1.0);
  EXPECT_NEAR(p.robotState(0).yaw_rad, 1.0, 0.05);  // minus the short spin-up
  p.commandVelocity(0, 0, 0);
  run(p, 1.0);
  const double yaw = p.robotState(0).yaw_rad;
  p.commandVelocity(0, 0, 0, 1.0);  // holonomic: sideways
  run(p, 2.0);
  const auto s = p.robotState(0);
  EXPECT_NEAR(s.yaw_rad, yaw, 1e-3);
  EXPECT_NEAR(std::hypot(s.position_m.x(), s.position_m.y()), 1.95, 0.1);
  EXPECT_NEAR(std::atan2(s.position_m.y(), s.position_m.x()), yaw + M_PI / 2, 0.05);
  p.commandVelocity(0, 0, 0, 0);  // zero command brakes
  run(p, 1.0);
  EXPECT_LT(s.velocity_mps.norm() + p.robotState(0).velocity_mps.norm(), 1.2);
  EXPECT_NEAR(p.robotState(0).velocity_mps.norm(), 0.0, 1e-3);
}

TEST(PhysicsWorld, TeleportAndReset) {
  PhysicsWorld p(wallWorld(), 0.005);
  p.commandVelocity(0, 3, 0);
  run(p, 1.0);
  p.setRobotPose(0, -5, 3, 1.0);
  EXPECT_NEAR(p.robotState(0).position_m.x(), -5, 1e-12);
  EXPECT_NEAR(p.robotState(0).velocity_mps.norm(), 0, 1e-12);
  run(p, 0.5);
  EXPECT_NEAR(p.robotState(0).position_m.x(), -5, 1e-6) << "teleport clears the command";
  p.reset();
  EXPECT_EQ(p.timeUs(), 0);
  EXPECT_NEAR(p.robotState(0).position_m.norm(), 0, 1e-12);
}

TEST(PhysicsWorld, RobotsCollideWithEachOther) {
  WorldSpec w;
  w.robots.push_back(taxi("a", 0, 0, 0));
  w.robots.push_back(taxi("b", 10, 0, M_PI));
  PhysicsWorld p(w, 0.005);
  p.commandVelocity(0, 3, 0);
  p.commandVelocity(1, 3, 0);
  bool touched = false;
  for (int i = 0; i < 800; ++i) {
    p.step();
    touched = touched || (p.contact(0).in_contact && p.contact(1).in_contact);
    EXPECT_GT(p.robotState(1).position_m.x() - p.robotState(0).position_m.x(), 4.0 - 0.02);
  }
  EXPECT_TRUE(touched);
}

TEST(PhysicsWorld, LongDrivesThroughManyObstaclesNeverPassThrough) {
  // A corridor of 200 short wall segments; the near set must always hold the ones in reach.
  WorldSpec w;
  for (int i = 0; i < 100; ++i) {
    w.statics.push_back(box("north_" + std::to_string(i), i * 2.0, 3.1, 2.0, 0.2));
    w.statics.push_back(box("south_" + std::to_string(i), i * 2.0, -3.1, 2.0, 0.2));
  }
  w.robots.push_back(taxi("taxi", 0, 0, 0.4));  // aimed at the north wall
  PhysicsWorld p(w, 0.005);
  p.commandVelocity(0, 15, 0);
  for (int i = 0; i < 2400; ++i) {
    p.step();
    const auto s = p.robotState(0);
    // The taxi's corners must stay between the walls (faces at +-3.0).
    const double c = std::cos(s.yaw_rad), sn = std::sin(s.yaw_rad);
    for (double lx : {-2.0, 2.0}) {
      for (double ly : {-1.0, 1.0}) {
        EXPECT_LT(std::abs(s.position_m.y() + sn * lx + c * ly), 3.0 + 0.02) << "step " << i;
      }
    }
    EXPECT_LT(p.nearStaticCount(), 20);
    // The collision body holds the near set and nothing else: each rebuild removes every old
    // shape (DART 6.13's removeAllShapeNodes() left every other one), so no name is ever a
    // duplicate that DART renames ("north_3(1)").
    const auto* near = p.dartWorld()->getSkeleton("statics_near")->getBodyNode(0);
    ASSERT_EQ(static_cast<int>(near->getNumShapeNodes()), p.nearStaticCount()) << "step " << i;
    std::set<std::string> names;
    for (std::size_t n = 0; n < near->getNumShapeNodes(); ++n) names.insert(near->getShapeNode(n)->getName());
    ASSERT_EQ(names.size(), near->getNumShapeNodes()) << "step " << i;
    for (const std::string& name : names) ASSERT_EQ(name.find('('), std::string::npos) << "step " << i;
  }
  EXPECT_GT(p.robotState(0).position_m.x(), 30.0) << "it should slide along the corridor";
}

TEST(PhysicsWorld, IdenticalWorldsStepIdentically) {
  PhysicsWorld a(wallWorld(), 0.005), b(wallWorld(), 0.005);
  for (int i = 0; i < 600; ++i) {
    const double v = 4.0 * std::sin(i * 0.01), w = std::cos(i * 0.013);
    a.commandVelocity(0, v, w);
    b.commandVelocity(0, v, w);
    a.step();
    b.step();
    ASSERT_EQ(a.robotState(0).position_m.x(), b.robotState(0).position_m.x());
    ASSERT_EQ(a.robotState(0).yaw_rad, b.robotState(0).yaw_rad);
  }
}

// Mesh walls (issue 55): an STL written here, read through the world reader, collide in DART as
// the box walls do; the mesh's floor holds no robot in contact.
TEST(MeshStatics, ATaxiStopsAtAnStlWallAndItsFloorIsNoContact) {
  const std::string dir = ::testing::TempDir() + "aula-mesh-physics-" + std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  setenv("XDG_CACHE_HOME", (dir + "/cache").c_str(), 1);
  // A wall whose near face is at x = 10 (as wallWorld's box), and a 60 m floor at z = 0.
  aula::testing::writeStl(dir + "/walls.stl",
                          aula::testing::boxTriangles({{{10, -20, 0}, {10.2, 20, 2}}}, 30.0));
  std::ofstream(dir + "/w.world") << "<sdf version='1.6'><world name='w'><model name='walls'><static>true</static>"
                                     "<link name='l'><collision name='c'><geometry><mesh><uri>walls.stl</uri></mesh>"
                                     "</geometry></collision></link></model></world></sdf>";
  WorldSpec w = loadWorld(dir + "/w.world", {dir});
  w.robots.push_back(taxi("taxi", 0, 0, 0));
  PhysicsWorld p(w, 0.005);
  run(p, 0.5);
  EXPECT_FALSE(p.contact(0).in_contact) << "standing on the mesh's floor";
  p.commandVelocity(0, 3.0, 0);
  double max_front = -1e9;
  bool touched = false;
  for (int i = 0; i < 2400; ++i) {  // 12 s
    p.step();
    max_front = std::max(max_front, p.robotState(0).position_m.x() + 2.0);
    touched = touched || p.contact(0).in_contact;
  }
  EXPECT_TRUE(touched);
  EXPECT_GT(max_front, 9.9) << "it reached the wall";
  EXPECT_LT(max_front, 10.05) << "and did not pass through it";
  EXPECT_NEAR(p.contact(0).bearing_rad, 0.0, 0.2) << "the contact is ahead";
  std::filesystem::remove_all(dir);
}

// RoboticsAcademy's parked cars (issue 55): a COLLADA car whose own axes run across, turned 1.57
// rad, <static>false</static> with no plugin, is kept still by the world reader; DART stops a taxi
// at its back, 2.45 m behind its centre, and the car does not move.
TEST(MeshStatics, ATaxiStopsAtAParkedMeshCarTheFileLeftNonStatic) {
  const std::string dir = ::testing::TempDir() + "aula-mesh-car-" + std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  setenv("XDG_CACHE_HOME", (dir + "/cache").c_str(), 1);
  aula::testing::writeCollada(dir + "/car.dae", {aula::testing::boxTriangles({{{-1.1, -2.45, 0}, {1.1, 2.45, 1.6}}})}, {"car"});
  std::ofstream(dir + "/w.world") << "<sdf version='1.4'><world name='w'><model name='car4'><pose>10 0 0 0 0 1.57</pose>"
                                     "<static>false</static><link name='l'><collision name='c'><geometry><mesh><uri>car.dae</uri>"
                                     "</mesh></geometry></collision></link></model></world></sdf>";
  WorldSpec w = loadWorld(dir + "/w.world", {dir});
  ASSERT_EQ(w.statics.size(), 1u);
  ASSERT_TRUE(w.robots.empty());
  w.robots.push_back(taxi("taxi", 0, 0, 0));
  PhysicsWorld p(w, 0.005);
  p.commandVelocity(0, 3.0, 0);
  double max_front = -1e9;
  bool touched = false;
  for (int i = 0; i < 1600; ++i) {  // 8 s
    p.step();
    max_front = std::max(max_front, p.robotState(0).position_m.x() + 2.0);
    touched = touched || p.contact(0).in_contact;
  }
  EXPECT_TRUE(touched);
  EXPECT_GT(max_front, 10 - 2.45 - 0.1) << "it reached the car's back";
  EXPECT_LT(max_front, 10 - 2.45 + 0.05) << "and did not pass into it";
  EXPECT_NEAR(p.contact(0).bearing_rad, 0.0, 0.2) << "the contact is ahead";
  std::filesystem::remove_all(dir);
}
