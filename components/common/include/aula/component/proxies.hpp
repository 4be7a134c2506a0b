#pragma once
// The student's view of the robot: JdeRobot-style sensor and actuator proxies over LCM.
// Proxies only cache the latest message; nothing here blocks or spawns threads. All of them are
// fed by the component's single event loop (LCM handled in the Qt loop or the headless loop).

#include <aula/bumper_t.hpp>
#include <aula/laser_t.hpp>
#include <aula/motors_t.hpp>
#include <aula/pose3d_t.hpp>

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace aula::component {

class Pose3dProxy {
 public:
  Pose3dProxy(lcm::LCM& bus, const std::string& channel);
  ~Pose3dProxy();
  Pose3dProxy(const Pose3dProxy&) = delete;
  Pose3dProxy& operator=(const Pose3dProxy&) = delete;

  double getX() const { return pose_.x; }      // metres
  double getY() const { return pose_.y; }      // metres
  double getYaw() const { return pose_.yaw; }  // radians
  // TeleTaxi's original names.
  double getRobotX() const { return getX(); }
  double getRobotY() const { return getY(); }
  double getRobotTheta() const { return getYaw(); }
  bool received() const { return received_; }
  int64_t utime() const { return pose_.utime; }

 private:
  void onPose(const lcm::ReceiveBuffer*, const std::string&, const aula::pose3d_t* msg);
  lcm::LCM& bus_;
  lcm::Subscription* subscription_ = nullptr;
  aula::pose3d_t pose_{};
  bool received_ = false;
};

// Like JdeRobot's LaserData: ranges in metres, plus the original's millimetre view.
struct LaserData {
  std::vector<float> values_m;        // metres, beam i at minAngle + i * angleIncrement
  std::vector<int> distanceData;      // the same ranges in millimetres (the original's ints)
  int numLaser = 0;
  double minAngle = 0, maxAngle = 0, angleIncrement = 0;  // radians
  double minRange = 0, maxRange = 0;                      // metres
  int64_t timeStamp = 0;                                  // sim time, microseconds

  double angle(int i) const { return minAngle + i * angleIncrement; }
};

class LaserProxy {
 public:
  LaserProxy(lcm::LCM& bus, const std::string& channel);
  ~LaserProxy();
  LaserProxy(const LaserProxy&) = delete;
  LaserProxy& operator=(const LaserProxy&) = delete;

  const LaserData& getLaserData() const { return data_; }
  bool received() const { return data_.numLaser > 0; }

 private:
  void onLaser(const lcm::ReceiveBuffer*, const std::string&, const aula::laser_t* msg);
  lcm::LCM& bus_;
  lcm::Subscription* subscription_ = nullptr;
  LaserData data_;
};

struct BumperData {
  int bumper = 1;  // 0 left, 1 centre, 2 right
  int state = 0;   // 1 pressed
  int64_t timeStamp = 0;
};

class BumperProxy {
 public:
  BumperProxy(lcm::LCM& bus, const std::string& channel);
  ~BumperProxy();
  BumperProxy(const BumperProxy&) = delete;
  BumperProxy& operator=(const BumperProxy&) = delete;

  const BumperData& getBumperData() const { return data_; }

 private:
  void onBumper(const lcm::ReceiveBuffer*, const std::string&, const aula::bumper_t* msg);
  lcm::LCM& bus_;
  lcm::Subscription* subscription_ = nullptr;
  BumperData data_;
};

// Motor commands, clamped to the exercise's limits. The command is held and published once per
// control period by the component's loop (publish()), so a live component keeps the
// simulator's watchdog fed and a dead one lets the robot stop.
class MotorsProxy {
 public:
  MotorsProxy(lcm::LCM& bus, std::string channel, double max_v_mps, double max_w_radps);

  void sendV(double v_mps);
  void sendW(double w_radps);
  void sendL(double l_mps);
  // TeleTaxi's original names.
  void setV(double v_mps) { sendV(v_mps); }
  void setW(double w_radps) { sendW(w_radps); }
  void stop() { v_ = w_ = l_ = 0.0; }

  double getV() const { return v_; }
  double getW() const { return w_; }
  double getL() const { return l_; }
  double maxV() const { return max_v_; }
  double maxW() const { return max_w_; }

  void publish(int64_t sim_time_us);

 private:
  lcm::LCM& bus_;
  std::string channel_;
  double max_v_, max_w_;
  double v_ = 0, w_ = 0, l_ = 0;
};

}  // namespace aula::component
