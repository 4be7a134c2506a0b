#pragma once
// The vacuum cleaner academic component without its window: the laser, the bumper and the yaw
// for the student's algorithm, and the map for the window. The true pose is read only for the
// GUI (robot glyph and cleaned area); the algorithm never sees it. The rest (motors, control
// loop, episode, teleoperation, hot reload) is every exercise's ExerciseComponent.

#include <aula/component/belief_publisher.hpp>
#include <aula/component/exercise_component.hpp>
#include <aula/vacuum/vacuum_algorithm.hpp>
#include <aula/vacuum/vacuum_box.hpp>
#include <aula/world/occupancy_map.hpp>

#include <memory>

namespace aula::vacuum {

class VacuumComponent : public component::ExerciseComponent<VacuumAlgorithm> {
 public:
  // `cfg`: the effective settings (aula_settings); the robot, its channels and the map come
  // from `world`.
  // `lockstep_key`: a graded run's key for its lockstep client (ProcessSetup's).
  VacuumComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                  const std::optional<auth::Key>& lockstep_key = std::nullopt);

  const component::LaserProxy& laser() const { return *laser_; }
  const world::OccupancyMap& map() const { return map_; }
  double robotRadiusM() const { return robot_radius_m_; }
  double runDurationS() const { return run_duration_s_; }  // the referee's Vacuum.Referee.Duration
  // What the algorithm says it believes (api.belief); read it between calls into the algorithm,
  // never while one is hung (algorithm().hung()).
  const component::Belief& belief() const { return belief_; }

 private:
  void invoke(VacuumAlgorithm& algorithm, component::CallKind) override {
    api_->clock.set(simTimeUs());
    algorithm.execute(*api_);
  }
  void boxInputs(component::BoxWire& wire, component::CallKind) override {
    api_->clock.set(simTimeUs());
    exchangeInputs(wire, devices());
  }
  void boxOutputs(component::BoxWire& wire, component::CallKind) override {
    int64_t unused = 0;  // the map's version is the writing end's
    exchangeOutputs(wire, devices(), unused);
  }
  VacuumDevices devices() { return {poseProxy(), *laser_, *bumper_, motorsProxy(), belief_, *api_}; }
  // A new algorithm believes nothing yet.
  bool startNewEpisode() override {
    belief_ = component::Belief{};
    return true;
  }
  // After this period's execute(): what the algorithm believes, on the bus.
  void beforeTick(int64_t utime) override {
    if (running()) belief_publisher_->publish(utime);
  }
  void detachSensors() override {
    laser_->detach();
    bumper_->detach();
  }

  world::OccupancyMap map_;
  double robot_radius_m_ = 0;
  double run_duration_s_ = 900;
  std::unique_ptr<component::LaserProxy> laser_;
  std::unique_ptr<component::BumperProxy> bumper_;
  std::unique_ptr<YawSensor> yaw_;
  component::Belief belief_;
  std::unique_ptr<component::BeliefPublisher> belief_publisher_;
  std::unique_ptr<VacuumApi> api_;
};

}  // namespace aula::vacuum
