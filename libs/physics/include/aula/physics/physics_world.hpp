#pragma once
// The DART world of a run: static geometry welded into one immobile skeleton, each robot a
// body on a planar joint driven by SERVO velocity commands with finite force limits, so that
// contacts win over commands: a robot stops at a wall at any speed and slides along it.
// The physics world owns the simulated clock (integer microseconds, no drift).
//
// Speed: Bullet updates the bounding box of every collision object and walks every touching
// static-static pair at each step, so a city of 135 touching buildings cost ~50 us per step.
// Only the static primitives near some robot are therefore given to the collision detector
// (the "near set", rebuilt when a robot has moved kNearRefresh_m since the last rebuild -- checked
// at every sub-step, so at most 1 cm further -- it
// holds everything within kNearMargin_m of each robot's footprint, so nothing a robot can
// touch before the next rebuild is ever missing). All statics stay in the world as visuals.

#include <aula/world/world_spec.hpp>

#include <dart/dynamics/Skeleton.hpp>
#include <dart/simulation/World.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace aula::physics {

struct RobotState {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  // body frame origin, world
  double yaw_rad = 0.0;
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector2d velocity_mps = Eigen::Vector2d::Zero();  // world frame
  double yaw_rate_radps = 0.0;
};

struct ContactState {
  bool in_contact = false;  // the robot body touches anything (static or another robot)
  double bearing_rad = 0.0; // direction of the mean contact point in the body frame (0 = ahead, +left)
  int contact_points = 0;
};

class PhysicsWorld {
 public:
  // Throws world::WorldError if a robot shape is unusable. step_s > 0.
  PhysicsWorld(const world::WorldSpec& spec, double step_s);
  ~PhysicsWorld();
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  void step();                         // advance one physics step
  int64_t timeUs() const { return time_us_; }
  int64_t stepUs() const { return step_us_; }

  int robotCount() const;
  int robotIndex(const std::string& name) const;  // -1 when absent
  const world::RobotSpec& robotSpec(int robot) const;

  // Body-frame velocity command held until the next call: forward v, lateral l, yaw rate w.
  // Non-finite values are the caller's job to reject (the motors driver does).
  void commandVelocity(int robot, double v_mps, double w_radps, double lateral_mps = 0.0);
  RobotState robotState(int robot) const;
  ContactState contact(int robot) const;  // from the last step's collision result

  // Teleport ("magic"): pose set, velocities zeroed, command cleared.
  void setRobotPose(int robot, double x_m, double y_m, double yaw_rad);
  // All robots back to their spec poses, commands cleared, clock back to zero.
  void reset();

  dart::simulation::WorldPtr dartWorld() const { return world_; }
  // How many static primitives the collision detector currently sees (for tests/benchmarks).
  int nearStaticCount() const { return static_cast<int>(near_set_.size()); }

  static constexpr double kNearMargin_m = 0.5;
  static constexpr double kNearRefresh_m = 0.2;

 private:
  struct Robot;
  struct StaticPrimitive;
  void refreshNearStatics(bool force);

  std::vector<Robot> robots_;
  std::vector<StaticPrimitive> statics_;
  std::vector<int> near_set_;
  dart::dynamics::BodyNode* near_body_ = nullptr;
  dart::simulation::WorldPtr world_;
  int64_t step_us_ = 0;
  int64_t time_us_ = 0;
};

}  // namespace aula::physics
