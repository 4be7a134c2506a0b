#pragma once
// The Autopark academic component without its window: the world's geometry (for the GUI and the
// laser mounts), proxies, the student's algorithm on sim time, the episode messages for the
// referee.

#include <aula/autopark/autopark_algorithm.hpp>
#include <aula/component/algorithm_host.hpp>
#include <aula/component/control_loop.hpp>
#include <aula/component/episode_sender.hpp>
#include <aula/component/proxies.hpp>
#include <aula/component/referee_status.hpp>
#include <aula/config/config.hpp>
#include <aula/world/world_spec.hpp>

#include <aula/lcm/bus.hpp>
#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <memory>
#include <string>

namespace aula::autopark {

class AutoparkComponent {
 public:
  AutoparkComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world);

  void setRunning(bool running);  // "Run my algorithm" toggle
  // Hot reload: loads the algorithm again (a plugin's new build), puts the car back at its start
  // and starts a new episode, running if it ran. False when the new build cannot be used.
  bool reloadAlgorithm();
  int generation() const { return episode_->generation(); }
  lcmbus::Bus& bus() { return bus_; }  // the window's speed control (SIM_CONTROL)
  bool running() const { return loop_->running(); }
  void teleoperate(double v_mps, double w_radps);  // ignored while the algorithm runs
  // With windows: a hung execute() halts the algorithm instead of ending the process.
  void containHangs() { host_->containHangs(); }
  void poll() { loop_->poll(); }
  void leave() { loop_->leave(); }

  const AutoparkApi& api() const { return *api_; }
  const world::WorldSpec& world() const { return world_; }
  const std::string& robotName() const { return robot_name_; }  // the car in the world
  int64_t simTimeUs() const { return loop_->simTimeUs(); }
  const std::string& algorithmName() const { return algorithm_name_; }
  const component::AlgorithmHostBase& algorithm() const { return *host_; }
  double maxV() const { return motors_->maxV(); }
  double maxW() const { return motors_->maxW(); }
  void setOnTick(std::function<void(int64_t)> hook) { on_tick_ = std::move(hook); }
  // The referee's word on the episode (time left, parked, its end); when it ends, the
  // algorithm stops.
  const component::RefereeStatusListener& refereeStatus() const { return *referee_status_; }

 private:
  void tick(int64_t utime);
  void step();

  lcmbus::Bus& bus_;
  world::WorldSpec world_;
  std::string algorithm_name_, episode_channel_, robot_name_;
  double period_s_;
  bool autostart_ = false;
  bool autostarted_ = false;
  std::unique_ptr<component::Pose3dProxy> pose_;
  std::unique_ptr<component::LaserProxy> front_, rear_, right_;
  std::unique_ptr<component::MotorsProxy> motors_;
  std::unique_ptr<AutoparkApi> api_;
  std::unique_ptr<component::AlgorithmHost<AutoparkAlgorithm>> host_;  // the algorithm is created at the first tick
  std::unique_ptr<component::EpisodeSender> episode_;
  std::unique_ptr<component::RefereeStatusListener> referee_status_;
  component::StartPose start_;
  std::unique_ptr<component::ControlLoop> loop_;
  int64_t started_utime_ = -1;
  std::function<void(int64_t)> on_tick_;
};

}  // namespace aula::autopark
