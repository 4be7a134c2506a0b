#include "motors_driver.hpp"

#include <aula/lcm/bus.hpp>
#include <aula/physics/physics_world.hpp>
#include <aula/world/car_kinematics.hpp>

#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace aula::drivers {

bool filterCommand(const MotorLimits& limits, double v, double w, double l, VelocityCommand& out) {
  if (!std::isfinite(v) || !std::isfinite(w) || !std::isfinite(l)) return false;
  VelocityCommand c;
  c.v_mps = std::clamp(v, -limits.max_v_mps, limits.max_v_mps);
  c.w_radps = std::clamp(w, -limits.max_w_radps, limits.max_w_radps);
  c.l_mps = limits.holonomic ? std::clamp(l, -limits.max_v_mps, limits.max_v_mps) : 0.0;
  if (limits.ackermann) {
    const double max_w = limits.min_turn_radius_m > 0 ? std::abs(c.v_mps) / limits.min_turn_radius_m
                                                       : limits.max_w_radps;
    c.w_radps = std::clamp(c.w_radps, -max_w, max_w);
    // v is the same at the centre and at the rear axle; the centre slides sideways by w * lever.
    c.l_mps = -limits.rear_axle_x_m * c.w_radps;
  }
  out = c;
  return true;
}

MotorsDriver::~MotorsDriver() {
  if (subscription_ != nullptr && context_ != nullptr) context_->bus->unsubscribe(subscription_);
}

void MotorsDriver::attach(DriverContext& context, int robot, const world::PluginSpec& plugin) {
  context_ = &context;
  robot_ = robot;
  const std::string where = plugin.owner + "/" + plugin.name;
  channel_ = plugin.getString("channel", "");
  if (channel_.empty()) throw world::WorldError(where + ": motors needs a <channel>");
  limits_.max_v_mps = plugin.getDouble("max_v", 1.0);
  limits_.max_w_radps = plugin.getDouble("max_w", 1.0);
  limits_.holonomic = plugin.getBool("holonomic", false);
  const world::CarKinematics kinematics = world::readCarKinematics(plugin);
  limits_.ackermann = kinematics.ackermann;
  limits_.min_turn_radius_m = kinematics.min_turn_radius_m;
  limits_.rear_axle_x_m = kinematics.rear_axle_x_m;
  if (!(limits_.max_v_mps > 0) || !(limits_.max_w_radps > 0)) {
    throw world::WorldError(where + ": max_v and max_w must be > 0");
  }
  const double watchdog_s = plugin.getDouble("watchdog_s", 0.5);
  if (!(watchdog_s > 0)) throw world::WorldError(where + ": watchdog_s must be > 0");
  watchdog_us_ = static_cast<int64_t>(std::llround(watchdog_s * 1e6));
  slip_rng_.seed(deviceSeed(context.seed, plugin));
  subscription_ = context.bus->subscribe(channel_, &MotorsDriver::onCommand, this);
}

void MotorsDriver::onCommand(const lcm::ReceiveBuffer*, const std::string& channel,
                             const aula::motors_t* msg) {
  VelocityCommand filtered;
  if (!filterCommand(limits_, msg->v, msg->w, msg->l, filtered)) {
    ++rejected_;
    // Log the first few and then every 100th, so a broken client cannot flood the terminal.
    if (rejected_ <= 3 || rejected_ % 100 == 0) {
      std::cerr << "aula-sim: " << channel << ": rejected non-finite motors command (v=" << msg->v
                << " w=" << msg->w << " l=" << msg->l << "), " << rejected_ << " so far\n";
    }
    return;
  }
  command_ = filtered;
  have_command_ = true;
  fresh_command_ = true;
}

void MotorsDriver::step(int64_t sim_time_us) {
  now_us_ = sim_time_us;
  if (fresh_command_) {
    last_command_us_ = sim_time_us;
    fresh_command_ = false;
    if (context_->noise.wheel_slip > 0) {  // drawn here, in sim-time order: the same seed slips the same
      std::normal_distribution<double> slip(1.0, context_->noise.wheel_slip);
      const double v_factor = std::max(0.0, slip(slip_rng_));
      // A car keeps its curvature (the steering does not slip); a differential drive's two wheels slip apart.
      const double w_factor = limits_.ackermann ? v_factor : std::max(0.0, slip(slip_rng_));
      command_.v_mps = std::clamp(command_.v_mps * v_factor, -limits_.max_v_mps, limits_.max_v_mps);
      command_.w_radps = std::clamp(command_.w_radps * w_factor, -limits_.max_w_radps, limits_.max_w_radps);
    }
  }
  if (have_command_ && sim_time_us - last_command_us_ > watchdog_us_) {
    command_ = VelocityCommand{};  // watchdog: the client went quiet, stop the robot
    have_command_ = false;
  }
  context_->physics->commandVelocity(robot_, command_.v_mps, command_.w_radps, command_.l_mps);
}

void MotorsDriver::reset() {
  command_ = VelocityCommand{};
  have_command_ = false;
  fresh_command_ = false;
  last_command_us_ = 0;
}

}  // namespace aula::drivers
