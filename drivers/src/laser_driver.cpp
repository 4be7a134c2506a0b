#include "laser_driver.hpp"

#include "robot_footprint.hpp"

#include <aula/lcm/bus.hpp>
#include <aula/physics/physics_world.hpp>

#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <cmath>

namespace aula::drivers {

void LaserDriver::attach(DriverContext& context, int robot, const world::PluginSpec& plugin) {
  context_ = &context;
  robot_ = robot;
  const std::string where = plugin.owner + "/" + plugin.name;
  channel_ = plugin.getString("channel", "");
  if (channel_.empty()) throw world::WorldError(where + ": laser needs a <channel>");
  mount_ = plugin.has("pose") ? plugin.getPose("pose") : Eigen::Isometry3d::Identity();
  mount_yaw_rad_ = world::yawOf(mount_);
  const int samples = plugin.getInt("samples", 180);
  const double min_angle = plugin.getDouble("min_angle", -M_PI / 2);
  const double max_angle = plugin.getDouble("max_angle", M_PI / 2);
  const double min_range = plugin.getDouble("min_range", 0.08);
  const double max_range = plugin.getDouble("max_range", 10.0);
  const double rate_hz = plugin.getDouble("rate_hz", 20.0);
  noise_stddev_m_ = plugin.getDouble("noise_stddev", 0.0);
  if (samples < 2 || samples > 100000) throw world::WorldError(where + ": samples must be 2..100000");
  if (!(max_angle > min_angle)) throw world::WorldError(where + ": max_angle must exceed min_angle");
  if (!(min_range >= 0) || !(max_range > min_range)) {
    throw world::WorldError(where + ": need 0 <= min_range < max_range");
  }
  if (!(rate_hz > 0)) throw world::WorldError(where + ": rate_hz must be > 0");
  if (!(noise_stddev_m_ >= 0)) throw world::WorldError(where + ": noise_stddev must be >= 0");

  request_.num_beams = samples;
  request_.min_angle_rad = min_angle;
  request_.angle_increment_rad = (max_angle - min_angle) / (samples - 1);
  request_.min_range_m = min_range;
  request_.max_range_m = max_range;
  schedule_ = Periodic(rate_hz);

  const auto& spec = context.physics->robotSpec(robot);
  const double sensor_z = spec.pose.translation().z() + mount_.translation().z();
  raycaster_ = context.raycaster_at(sensor_z);

  // Noise: the plugin's own, or the run's preset's when larger, from this device's stream.
  rng_.seed(deviceSeed(context.seed, plugin));
  noise_stddev_m_ = std::max(noise_stddev_m_, context.noise.laser_stddev_m);
  dropout_ = context.noise.laser_dropout;

  message_.num_ranges = samples;
  message_.ranges.assign(samples, static_cast<float>(max_range));
  message_.min_angle = static_cast<float>(min_angle);
  message_.max_angle = static_cast<float>(max_angle);
  message_.angle_increment = static_cast<float>(request_.angle_increment_rad);
  message_.min_range = static_cast<float>(min_range);
  message_.max_range = static_cast<float>(max_range);
}

void LaserDriver::scan(aula::laser_t& out) {
  const physics::RobotState s = context_->physics->robotState(robot_);
  const double c = std::cos(s.yaw_rad), sn = std::sin(s.yaw_rad);
  const Eigen::Vector2d m = mount_.translation().head<2>();
  request_.origin_m = s.position_m.head<2>() + Eigen::Vector2d(c * m.x() - sn * m.y(), sn * m.x() + c * m.y());
  request_.yaw_rad = s.yaw_rad + mount_yaw_rad_;

  others_.rects.clear();
  others_.circles.clear();
  for (int r = 0; r < context_->physics->robotCount(); ++r) {
    if (r != robot_) appendFootprint(*context_->physics, r, others_);
  }
  out.ranges.resize(request_.num_beams);
  raycaster_->scan(request_, out.ranges.data(), &others_);
  if (noise_stddev_m_ > 0) {
    std::normal_distribution<double> noise(0.0, noise_stddev_m_);
    for (auto& r : out.ranges) {
      if (r < out.max_range) {
        r = static_cast<float>(std::clamp(r + noise(rng_), request_.min_range_m, request_.max_range_m));
      }
    }
  }
  if (dropout_ > 0) {  // no echo: the beam reads max_range, as a real scanner's missing return
    std::bernoulli_distribution lost(dropout_);
    for (auto& r : out.ranges) {
      if (lost(rng_)) r = static_cast<float>(request_.max_range_m);
    }
  }
}

void LaserDriver::step(int64_t sim_time_us) {
  if (!schedule_.due(sim_time_us)) return;
  message_.utime = sim_time_us;
  scan(message_);
  context_->bus->publish(channel_, &message_);
}

}  // namespace aula::drivers
