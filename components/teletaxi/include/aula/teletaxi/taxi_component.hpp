#pragma once
// The TeleTaxi academic component without its window: proxies, the grid, the student's
// algorithm, the sim-time control loop and the episode messages for the referee. The Qt window
// (taxi_window.hpp) and the headless main both drive this one object.

#include <aula/component/algorithm_host.hpp>
#include <aula/component/control_loop.hpp>
#include <aula/component/episode_sender.hpp>
#include <aula/component/proxies.hpp>
#include <aula/component/referee_status.hpp>
#include <aula/config/config.hpp>
#include <aula/teletaxi/grid.hpp>
#include <aula/teletaxi/taxi_algorithm.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include <aula/lcm/bus.hpp>
#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace aula::teletaxi {

class TaxiComponent {
 public:
  // `cfg`: the effective settings; the robot, its channels and the map come from `world`.
  // Throws config::ConfigError for a destination the taxi cannot drive to.
  TaxiComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world);
  // Why the taxi cannot drive to (x, y) from its start (off the map, inside a building,
  // walled off, too close to the start), or nothing when it can.
  std::optional<std::string> destinationProblem(double x_m, double y_m) const;
  static constexpr double kMinTripM = 2.0;

  void setDestination(double x_m, double y_m);  // world metres; clears any previous path
  // Runs the algorithm's generatePath(); false (with the reason) when it cannot: no destination
  // or pose yet, the destination unreachable from where the taxi stands now (GPP's field from
  // the destination does not reach it), or the algorithm failed.
  bool generatePath(std::string* why = nullptr);
  // The algorithm's generatePath() marked a path (setPathFinded and at least one path cell).
  bool hasPath() const;
  // Headless, the run cannot go on (the destination cannot be reached from where the taxi
  // stands): the reason, and the process ends with exit code 2 (aula_app's runComponent).
  std::optional<std::string> refusal() const { return refusal_; }
  bool go(std::string* why = nullptr);  // "GO!": execute() every control period from now on
  void stop();                           // "Stop": algorithm off, taxi stopped
  // Hot reload: loads the algorithm again (a plugin's new build), puts the taxi back at its start
  // and starts a new episode (generate the path and GO! again). False when the new build cannot
  // be used (the algorithm's fault says why).
  bool reloadAlgorithm();
  int generation() const { return episode_->generation(); }
  lcmbus::Bus& bus() { return bus_; }  // the window's speed control (SIM_CONTROL)
  void teleoperate(double v_mps, double w_radps);  // ignored while the algorithm runs
  // With windows: a hung execute() halts the algorithm instead of ending the process.
  void containHangs() { host_->containHangs(); }
  void poll();                           // housekeeping (lockstep registration)
  void leave() { loop_->leave(); }

  // Headless automation: with TeleTaxi.Autostart, generate the path and GO as soon as the
  // destination and the taxi's pose are known.
  bool autostart() const { return autostart_; }

  Grid& grid() { return *grid_; }
  const component::Pose3dProxy& pose() const { return *pose_; }
  const component::MotorsProxy& motors() const { return *motors_; }
  bool running() const { return loop_->running(); }
  bool pathGenerated() const { return path_generated_; }
  std::optional<std::pair<double, double>> destination() const { return destination_; }
  int64_t simTimeUs() const { return loop_->simTimeUs(); }
  const std::string& algorithmName() const { return algorithm_name_; }
  const component::AlgorithmHostBase& algorithm() const { return *host_; }
  double maxV() const { return motors_->maxV(); }
  double maxW() const { return motors_->maxW(); }
  // The referee's word on the episode (time left, arrival, its end); when it ends, the
  // algorithm stops and the teleoperator drives again.
  const component::RefereeStatusListener& refereeStatus() const { return *referee_status_; }
  // Called after every control tick (GUI refresh hooks, tests).
  void setOnTick(std::function<void(int64_t)> hook) { on_tick_ = std::move(hook); }

 private:
  void tick(int64_t utime);
  void autostartAt(int64_t utime);  // Generate Path and GO! (TeleTaxi.Autostart)
  // Why the taxi cannot drive from (from) to (to): off the map, in a building, walled off.
  // `from_what` names the start in the message ("the taxi's start").
  std::optional<std::string> tripProblem(std::pair<double, double> from, std::pair<double, double> to,
                                         const std::string& from_what) const;

  lcmbus::Bus& bus_;
  std::string episode_channel_;
  std::string algorithm_name_;
  std::unique_ptr<component::Pose3dProxy> pose_;
  std::unique_ptr<component::MotorsProxy> motors_;
  std::unique_ptr<Grid> grid_;
  world::OccupancyMap map_;
  std::pair<double, double> start_xy_m_{0, 0};  // the robot's pose in the world
  std::unique_ptr<component::AlgorithmHost<TaxiAlgorithm>> host_;
  component::StartPose start_;
  std::unique_ptr<TaxiApi> api_;
  std::unique_ptr<component::ControlLoop> loop_;
  std::optional<std::pair<double, double>> destination_;
  bool path_generated_ = false;
  std::optional<std::string> refusal_;
  bool autostart_ = false;
  int64_t started_utime_ = -1;
  std::unique_ptr<component::EpisodeSender> episode_;
  std::unique_ptr<component::RefereeStatusListener> referee_status_;
  std::function<void(int64_t)> on_tick_;
};

}  // namespace aula::teletaxi
