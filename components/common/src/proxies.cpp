#include "aula/component/proxies.hpp"

#include <aula/lcm/bus.hpp>

namespace aula::component {
namespace {

void unsubscribeOnce(lcmbus::Bus& bus, lcm::Subscription*& subscription) {
  if (subscription != nullptr) bus.unsubscribe(subscription);
  subscription = nullptr;
}

}  // namespace

Pose3dProxy::Pose3dProxy(lcmbus::Bus& bus, const std::string& channel) : bus_(bus) {
  subscription_ = bus_.subscribe(channel, &Pose3dProxy::onPose, this);
}
Pose3dProxy::~Pose3dProxy() { detach(); }
void Pose3dProxy::detach() { unsubscribeOnce(bus_, subscription_); }
void Pose3dProxy::onPose(const lcm::ReceiveBuffer*, const std::string&, const aula::pose3d_t* msg) {
  set(msg->x, msg->y, msg->yaw, msg->utime);
}

LaserProxy::LaserProxy(lcmbus::Bus& bus, const std::string& channel) : bus_(bus) {
  subscription_ = bus_.subscribe(channel, &LaserProxy::onLaser, this);
}
LaserProxy::~LaserProxy() { detach(); }
void LaserProxy::detach() { unsubscribeOnce(bus_, subscription_); }
void LaserProxy::onLaser(const lcm::ReceiveBuffer*, const std::string&, const aula::laser_t* msg) {
  LaserData data;
  data.values_m = msg->ranges;
  data.numLaser = msg->num_ranges;
  data.minAngle = msg->min_angle;
  data.maxAngle = msg->max_angle;
  data.angleIncrement = msg->angle_increment;
  data.minRange = msg->min_range;
  data.maxRange = msg->max_range;
  data.timeStamp = msg->utime;
  set(std::move(data));
}

BumperProxy::BumperProxy(lcmbus::Bus& bus, const std::string& channel) : bus_(bus) {
  subscription_ = bus_.subscribe(channel, &BumperProxy::onBumper, this);
}
BumperProxy::~BumperProxy() { detach(); }
void BumperProxy::detach() { unsubscribeOnce(bus_, subscription_); }
void BumperProxy::onBumper(const lcm::ReceiveBuffer*, const std::string&, const aula::bumper_t* msg) {
  set(BumperData{msg->bumper, msg->state, msg->utime});
}

MotorsProxy::MotorsProxy(lcmbus::Bus& bus, std::string channel, double max_v_mps, double max_w_radps)
    : Motors(max_v_mps, max_w_radps), bus_(bus), channel_(std::move(channel)) {}

void MotorsProxy::publish(int64_t sim_time_us) {
  aula::motors_t msg;
  msg.utime = sim_time_us;
  msg.v = halted_ ? 0.0 : getV();
  msg.w = halted_ ? 0.0 : getW();
  msg.l = halted_ ? 0.0 : getL();
  bus_.publish(channel_, &msg);
}

}  // namespace aula::component
