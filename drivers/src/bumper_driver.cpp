#include "bumper_driver.hpp"

#include <aula/lcm/bus.hpp>
#include <aula/bumper_t.hpp>
#include <aula/physics/physics_world.hpp>

#include <lcm/lcm-cpp.hpp>

namespace aula::drivers {

int8_t bumperSide(double bearing_rad, double side_threshold_rad) {
  if (bearing_rad > side_threshold_rad) return aula::bumper_t::LEFT;
  if (bearing_rad < -side_threshold_rad) return aula::bumper_t::RIGHT;
  return aula::bumper_t::CENTER;
}

void BumperDriver::attach(DriverContext& context, int robot, const world::PluginSpec& plugin) {
  context_ = &context;
  robot_ = robot;
  const std::string where = plugin.owner + "/" + plugin.name;
  channel_ = plugin.getString("channel", "");
  if (channel_.empty()) throw world::WorldError(where + ": bumper needs a <channel>");
  const double rate_hz = plugin.getDouble("rate_hz", 20.0);
  if (!(rate_hz > 0)) throw world::WorldError(where + ": rate_hz must be > 0");
  side_threshold_rad_ = plugin.getDouble("side_threshold_rad", 0.35);
  schedule_ = Periodic(rate_hz);
}

void BumperDriver::step(int64_t sim_time_us) {
  const physics::ContactState contact = context_->physics->contact(robot_);
  aula::bumper_t msg;
  msg.utime = sim_time_us;
  msg.state = contact.in_contact ? aula::bumper_t::PRESSED : aula::bumper_t::RELEASED;
  msg.bumper = contact.in_contact ? bumperSide(contact.bearing_rad, side_threshold_rad_)
                                  : aula::bumper_t::CENTER;
  const bool changed = msg.state != last_state_ || (msg.state && msg.bumper != last_side_);
  if (!schedule_.due(sim_time_us) && !changed) return;
  last_state_ = msg.state;
  last_side_ = msg.bumper;
  context_->stamper->stamp(channel_, msg);
  context_->bus->publish(channel_, &msg);
}

void BumperDriver::reset() {
  schedule_.reset();
  last_state_ = -1;
  last_side_ = -1;
}

}  // namespace aula::drivers
