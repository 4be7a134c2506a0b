#pragma once
// What crosses between the Autopark component and its algorithm's own process
// (algorithm_box.hpp), said once for both ends: the pose, the three lasers, the commands as they
// stand, the car's description and the sim clock in; the commands and api.status back.

#include <aula/autopark/autopark_algorithm.hpp>
#include <aula/component/algorithm_host.hpp>
#include <aula/component/box_wire.hpp>

namespace aula::autopark {

// api.status crosses whole up to this (the component reports its first 300 bytes).
constexpr size_t kMaxStatusBytes = 1 << 16;

void exchangeInputs(component::BoxWire& wire, AutoparkApi& api);
void exchangeOutputs(component::BoxWire& wire, AutoparkApi& api);

// The algorithm's end: its own devices and API (runAlgorithmBox<AutoparkBox>).
class AutoparkBox {
 public:
  using Algorithm = AutoparkAlgorithm;
  explicit AutoparkBox(component::Motors& motors) : api_{pose_, front_, rear_, right_, motors, 0.0, {}, {}, {}} {}
  void readInputs(component::BoxWire& wire, component::CallKind) { exchangeInputs(wire, api_); }
  void invoke(AutoparkAlgorithm& algorithm, component::CallKind) { algorithm.execute(api_); }
  void writeOutputs(component::BoxWire& wire, component::CallKind) { exchangeOutputs(wire, api_); }

 private:
  component::Pose3d pose_;
  component::Laser front_, rear_, right_;
  AutoparkApi api_;
};

}  // namespace aula::autopark
