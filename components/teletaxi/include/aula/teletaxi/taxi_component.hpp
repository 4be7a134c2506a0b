#pragma once
// The TeleTaxi academic component without its window: the city's grid, the destination and the
// path, on every exercise's ExerciseComponent (motors, control loop, episode, teleoperation,
// hot reload). The Qt window (taxi_window.hpp) and the headless main both drive this one object.

#include <aula/component/exercise_component.hpp>
#include <aula/desktop/window_layout.hpp>
#include <aula/teletaxi/grid.hpp>
#include <aula/teletaxi/taxi_algorithm.hpp>
#include <aula/teletaxi/taxi_box.hpp>
#include <aula/world/occupancy_map.hpp>

#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace aula::teletaxi {

class TaxiComponent : public component::ExerciseComponent<TaxiAlgorithm> {
 public:
  // `cfg`: the effective settings; the robot, its channels and the map come from `world`.
  // Throws config::ConfigError for a destination the taxi cannot drive to.
  // `lockstep_key`: a graded run's key for its lockstep client (ProcessSetup's).
  TaxiComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                const std::optional<auth::Key>& lockstep_key = std::nullopt);
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
  void stop() { pressRun(false); }       // "Stop": algorithm off, taxi stopped

  Grid& grid() { return *grid_; }
  const component::Pose3dProxy& pose() const { return truePose(); }  // the taxi's API has it too
  bool pathGenerated() const { return path_generated_; }
  std::optional<std::pair<double, double>> destination() const { return destination_; }
  // The "Grid Field" window's size and place (TeleTaxi.GridWindow.*), for the window to open it.
  const desktop::Placement& gridWindow() const { return grid_window_; }

 private:
  void invoke(TaxiAlgorithm& algorithm, component::CallKind kind) override {
    api_->clock.set(simTimeUs());
    if (kind == component::CallKind::Plan) {
      algorithm.generatePath(*api_);
    } else {
      algorithm.execute(*api_);
    }
  }
  void boxInputs(component::BoxWire& wire, component::CallKind kind) override {
    api_->clock.set(simTimeUs());
    bool with_map = map_sent_to_ != host().boxStarts();  // once to each process of the algorithm
    exchangeInputs(wire, poseProxy(), motorsProxy(), api_->clock, grid_, with_map, kind);
    map_sent_to_ = host().boxStarts();
  }
  void boxOutputs(component::BoxWire& wire, component::CallKind kind) override {
    bool show_grid = false;  // read: the algorithm asked for it
    exchangeOutputs(wire, motorsProxy(), *grid_, show_grid, kind);
  }
  void beforeTick(int64_t utime) override;
  // Autostart (TeleTaxi.Autostart): generate the path and GO! as soon as the destination and
  // the taxi's pose are known.
  bool readyToAutostart() const override { return destination_ && truePose().received() && !refusal_; }
  bool prepareAutostart() override;
  std::optional<std::pair<double, double>> episodeGoal() const override { return destination_; }
  bool startNewEpisode() override;  // generate the path and GO! again
  // Why the taxi cannot drive from (from) to (to): off the map, in a building, walled off.
  // `from_what` names the start in the message ("the taxi's start").
  std::optional<std::string> tripProblem(std::pair<double, double> from, std::pair<double, double> to,
                                         const std::string& from_what) const;
  // The field and path generatePath() left, on the bus (plan_t): the run's log and the player's.
  void publishPlan();

  std::string plan_channel_;
  std::unique_ptr<Grid> grid_;
  world::OccupancyMap map_;
  std::pair<double, double> start_xy_m_{0, 0};  // the robot's pose in the world
  std::unique_ptr<TaxiApi> api_;
  std::optional<std::pair<double, double>> destination_;
  bool path_generated_ = false;
  int64_t map_sent_to_ = 0;  // the algorithm's process (host().boxStarts()) that has the map
  std::optional<std::string> refusal_;
  desktop::Placement grid_window_;
};

}  // namespace aula::teletaxi
