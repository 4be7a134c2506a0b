#include "aula/component/proxies.hpp"

#include <aula/lcm/bus.hpp>

#include <algorithm>
#include <cmath>

namespace aula::component {
namespace {
// Non-finite input would be rejected by the simulator anyway; zero it here so the student's
// robot stops instead of keeping an old command.
double clampFinite(double value, double limit) {
  if (!std::isfinite(value)) return 0.0;
  return std::clamp(value, -limit, limit);
}
}  // namespace

Pose3dProxy::Pose3dProxy(lcm::LCM& bus, const std::string& channel) : bus_(bus) {
  subscription_ = lcmbus::subscribe(bus_, channel, &Pose3dProxy::onPose, this);
}
Pose3dProxy::~Pose3dProxy() { bus_.unsubscribe(subscription_); }
void Pose3dProxy::onPose(const lcm::ReceiveBuffer*, const std::string&, const aula::pose3d_t* msg) {
  pose_ = *msg;
  received_ = true;
}

LaserProxy::LaserProxy(lcm::LCM& bus, const std::string& channel) : bus_(bus) {
  subscription_ = lcmbus::subscribe(bus_, channel, &LaserProxy::onLaser, this);
}
LaserProxy::~LaserProxy() { bus_.unsubscribe(subscription_); }
void LaserProxy::onLaser(const lcm::ReceiveBuffer*, const std::string&, const aula::laser_t* msg) {
  data_.values_m = msg->ranges;
  data_.distanceData.resize(msg->ranges.size());
  for (size_t i = 0; i < msg->ranges.size(); ++i) {
    data_.distanceData[i] = static_cast<int>(std::lround(msg->ranges[i] * 1000.0));
  }
  data_.numLaser = msg->num_ranges;
  data_.minAngle = msg->min_angle;
  data_.maxAngle = msg->max_angle;
  data_.angleIncrement = msg->angle_increment;
  data_.minRange = msg->min_range;
  data_.maxRange = msg->max_range;
  data_.timeStamp = msg->utime;
}

BumperProxy::BumperProxy(lcm::LCM& bus, const std::string& channel) : bus_(bus) {
  subscription_ = lcmbus::subscribe(bus_, channel, &BumperProxy::onBumper, this);
}
BumperProxy::~BumperProxy() { bus_.unsubscribe(subscription_); }
void BumperProxy::onBumper(const lcm::ReceiveBuffer*, const std::string&, const aula::bumper_t* msg) {
  data_.bumper = msg->bumper;
  data_.state = msg->state;
  data_.timeStamp = msg->utime;
}

MotorsProxy::MotorsProxy(lcm::LCM& bus, std::string channel, double max_v_mps, double max_w_radps)
    : bus_(bus), channel_(std::move(channel)), max_v_(max_v_mps), max_w_(max_w_radps) {}

void MotorsProxy::sendV(double v_mps) { v_ = clampFinite(v_mps, max_v_); }
void MotorsProxy::sendW(double w_radps) { w_ = clampFinite(w_radps, max_w_); }
void MotorsProxy::sendL(double l_mps) { l_ = clampFinite(l_mps, max_v_); }

void MotorsProxy::publish(int64_t sim_time_us) {
  aula::motors_t msg;
  msg.utime = sim_time_us;
  msg.v = v_;
  msg.w = w_;
  msg.l = l_;
  bus_.publish(channel_, &msg);
}

}  // namespace aula::component
