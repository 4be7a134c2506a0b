#pragma once
// The Autopark academic component without its window: the world's geometry (for the GUI and the
// laser mounts), the car's three lasers and the API the student's algorithm reads; the rest
// (motors, control loop, episode, teleoperation, hot reload) is every exercise's
// ExerciseComponent.

#include <aula/autopark/autopark_algorithm.hpp>
#include <aula/autopark/autopark_box.hpp>
#include <aula/component/exercise_component.hpp>

#include <memory>
#include <string>

namespace aula::autopark {

class AutoparkComponent : public component::ExerciseComponent<AutoparkAlgorithm> {
 public:
  // `lockstep_key`: a graded run's key for its lockstep client (ProcessSetup's).
  AutoparkComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                    const std::optional<auth::Key>& lockstep_key = std::nullopt);

  const AutoparkApi& api() const { return *api_; }
  const world::WorldSpec& world() const { return world_; }
  const std::string& robotName() const { return startPose().robot; }  // the car in the world

 private:
  void invoke(AutoparkAlgorithm& algorithm, component::CallKind) override {
    api_->clock.set(simTimeUs());
    algorithm.execute(*api_);
  }
  void boxInputs(component::BoxWire& wire, component::CallKind) override {
    api_->clock.set(simTimeUs());
    exchangeInputs(wire, *api_);
  }
  void boxOutputs(component::BoxWire& wire, component::CallKind) override { exchangeOutputs(wire, *api_); }
  std::string algorithmStatus() const override { return api_->status; }
  void detachSensors() override {
    for (component::LaserProxy* laser : {front_.get(), rear_.get(), right_.get()}) laser->detach();
  }

  world::WorldSpec world_;
  std::unique_ptr<component::LaserProxy> front_, rear_, right_;
  std::unique_ptr<AutoparkApi> api_;
};

}  // namespace aula::autopark
