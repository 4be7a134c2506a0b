#include "pose3d_driver.hpp"

#include <aula/lcm/bus.hpp>
#include <aula/physics/physics_world.hpp>
#include <aula/pose3d_t.hpp>

#include <lcm/lcm-cpp.hpp>

namespace aula::drivers {

void Pose3dDriver::attach(DriverContext& context, int robot, const world::PluginSpec& plugin) {
  context_ = &context;
  robot_ = robot;
  channel_ = plugin.getString("channel", "");
  if (channel_.empty()) {
    throw world::WorldError(plugin.owner + "/" + plugin.name + ": pose3d needs a <channel>");
  }
  const double rate_hz = plugin.getDouble("rate_hz", 50.0);
  if (!(rate_hz > 0.0)) {
    throw world::WorldError(plugin.owner + "/" + plugin.name + ": rate_hz must be > 0");
  }
  schedule_ = Periodic(rate_hz);
}

void Pose3dDriver::step(int64_t sim_time_us) {
  if (!schedule_.due(sim_time_us)) return;
  const physics::RobotState s = context_->physics->robotState(robot_);
  aula::pose3d_t msg;
  msg.utime = sim_time_us;
  msg.x = s.position_m.x();
  msg.y = s.position_m.y();
  msg.z = s.position_m.z();
  msg.yaw = s.yaw_rad;
  msg.q0 = s.orientation.w();
  msg.q1 = s.orientation.x();
  msg.q2 = s.orientation.y();
  msg.q3 = s.orientation.z();
  context_->stamper->stamp(channel_, msg);
  context_->bus->publish(channel_, &msg);
}

}  // namespace aula::drivers
