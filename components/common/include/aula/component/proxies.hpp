#pragma once
// The student's devices (devices.hpp) fed from the bus: each proxy is the plain device plus its
// LCM subscription (or, for the motors, its publisher). Proxies only cache the latest message;
// nothing here blocks or spawns threads. All of them are fed by the component's single event
// loop (LCM handled in the Qt loop or the headless loop). After a call into the student's code
// was abandoned (AlgorithmHostBase::hung), a sensor proxy is detached (never written again: the
// stuck call may still read it) and the motors are halted (they publish 0 whatever it writes).

#include <aula/component/devices.hpp>

#include <aula/bumper_t.hpp>
#include <aula/laser_t.hpp>
#include <aula/motors_t.hpp>
#include <aula/pose3d_t.hpp>

#include <aula/lcm/bus.hpp>
#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <string>

namespace aula::component {

class Pose3dProxy : public Pose3d {
 public:
  Pose3dProxy(lcmbus::Bus& bus, const std::string& channel);
  ~Pose3dProxy();
  Pose3dProxy(const Pose3dProxy&) = delete;
  Pose3dProxy& operator=(const Pose3dProxy&) = delete;
  void detach();  // no more messages: the value stays as it is

 private:
  void onPose(const lcm::ReceiveBuffer*, const std::string&, const aula::pose3d_t* msg);
  lcmbus::Bus& bus_;
  lcm::Subscription* subscription_ = nullptr;
};

class LaserProxy : public Laser {
 public:
  LaserProxy(lcmbus::Bus& bus, const std::string& channel);
  ~LaserProxy();
  LaserProxy(const LaserProxy&) = delete;
  LaserProxy& operator=(const LaserProxy&) = delete;
  void detach();  // no more messages: the value stays as it is

 private:
  void onLaser(const lcm::ReceiveBuffer*, const std::string&, const aula::laser_t* msg);
  lcmbus::Bus& bus_;
  lcm::Subscription* subscription_ = nullptr;
};

class BumperProxy : public Bumper {
 public:
  BumperProxy(lcmbus::Bus& bus, const std::string& channel);
  ~BumperProxy();
  BumperProxy(const BumperProxy&) = delete;
  BumperProxy& operator=(const BumperProxy&) = delete;
  void detach();  // no more messages: the value stays as it is

 private:
  void onBumper(const lcm::ReceiveBuffer*, const std::string&, const aula::bumper_t* msg);
  lcmbus::Bus& bus_;
  lcm::Subscription* subscription_ = nullptr;
};

// The command is held and published once per control period by the component's loop
// (publish()), so a live component keeps the simulator's watchdog fed and a dead one lets the
// robot stop.
class MotorsProxy : public Motors {
 public:
  MotorsProxy(lcmbus::Bus& bus, std::string channel, double max_v_mps, double max_w_radps);

  void publish(int64_t sim_time_us);
  void halt() { halted_ = true; }  // from now on every published command is 0

 private:
  bool halted_ = false;
  lcmbus::Bus& bus_;
  std::string channel_;
};

}  // namespace aula::component
