#pragma once
// The vacuum cleaner academic component without its window: proxies, the student's algorithm
// on sim time, the episode messages for the referee. The true pose is read only for the GUI
// (robot glyph and cleaned area); the algorithm never sees it.

#include <aula/component/algorithm_host.hpp>
#include <aula/component/control_loop.hpp>
#include <aula/component/episode_sender.hpp>
#include <aula/component/proxies.hpp>
#include <aula/component/referee_status.hpp>
#include <aula/config/config.hpp>
#include <aula/vacuum/vacuum_algorithm.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include <aula/lcm/bus.hpp>
#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <memory>
#include <string>

namespace aula::vacuum {

class VacuumComponent {
 public:
  // `cfg`: the effective settings (aula_settings); the robot, its channels and the map come
  // from `world`.
  VacuumComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world);

  void setRunning(bool running);  // "Run my algorithm" toggle
  bool running() const { return loop_->running(); }
  void teleoperate(double v_mps, double w_radps);  // ignored while the algorithm runs
  // With windows: a hung execute() halts the algorithm instead of ending the process.
  void containHangs() { host_->containHangs(); }
  void poll() { loop_->poll(); }
  void leave() { loop_->leave(); }

  const component::Pose3dProxy& truePose() const { return *pose_; }  // GUI only
  const component::LaserProxy& laser() const { return *laser_; }
  const component::MotorsProxy& motors() const { return *motors_; }
  int64_t simTimeUs() const { return loop_->simTimeUs(); }
  const std::string& algorithmName() const { return algorithm_name_; }
  const component::AlgorithmHostBase& algorithm() const { return *host_; }
  // Hot reload: loads the algorithm again (a plugin's new build), puts the robot back at its
  // start and starts a new episode, running if it ran. False when the new build cannot be
  // used (the algorithm's fault says why).
  bool reloadAlgorithm();
  int generation() const { return episode_->generation(); }
  lcmbus::Bus& bus() { return bus_; }  // the window's speed control (SIM_CONTROL)
  double maxV() const { return motors_->maxV(); }
  double maxW() const { return motors_->maxW(); }
  const world::OccupancyMap& map() const { return map_; }
  double robotRadiusM() const { return robot_radius_m_; }
  double runDurationS() const { return run_duration_s_; }  // the referee's Vacuum.Referee.Duration
  // The referee's word on the episode (time left, its end); when it ends, the algorithm stops.
  const component::RefereeStatusListener& refereeStatus() const { return *referee_status_; }
  int64_t startedUtime() const { return started_utime_; }  // the episode's first Run (-1: not yet)
  void setOnTick(std::function<void(int64_t)> hook) { on_tick_ = std::move(hook); }

 private:
  void tick(int64_t utime);
  void step();

  lcmbus::Bus& bus_;
  std::string algorithm_name_, episode_channel_;
  world::OccupancyMap map_;
  double robot_radius_m_ = 0;
  double period_s_;
  double run_duration_s_ = 900;
  bool autostart_ = false;
  bool autostarted_ = false;
  std::unique_ptr<component::Pose3dProxy> pose_;
  std::unique_ptr<component::LaserProxy> laser_;
  std::unique_ptr<component::BumperProxy> bumper_;
  std::unique_ptr<component::MotorsProxy> motors_;
  std::unique_ptr<YawSensor> yaw_;
  std::unique_ptr<VacuumApi> api_;
  std::unique_ptr<component::AlgorithmHost<VacuumAlgorithm>> host_;  // created at the first tick, with the run's seed
  std::unique_ptr<component::ControlLoop> loop_;
  std::unique_ptr<component::EpisodeSender> episode_;
  std::unique_ptr<component::RefereeStatusListener> referee_status_;
  component::StartPose start_;
  int64_t started_utime_ = -1;  // the first Run of this episode (-1: not yet)
  std::function<void(int64_t)> on_tick_;
};

}  // namespace aula::vacuum
