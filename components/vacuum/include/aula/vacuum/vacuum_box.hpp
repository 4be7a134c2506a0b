#pragma once
// What crosses between the vacuum component and its algorithm's own process (algorithm_box.hpp),
// said once for both ends: the sensors (the pose, of which the API gives the yaw, the laser and
// the bumper), the commands as they stand and the sim clock in; the commands and the belief back.

#include <aula/component/algorithm_host.hpp>
#include <aula/component/box_wire.hpp>
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <cstdint>

namespace aula::vacuum {

// The devices behind a VacuumApi, in whichever process holds them.
struct VacuumDevices {
  component::Pose3d& pose;
  component::Laser& laser;
  component::Bumper& bumper;
  component::Motors& motors;
  component::Belief& belief;
  VacuumApi& api;
};

void exchangeInputs(component::BoxWire& wire, const VacuumDevices& devices);
// `map_version_sent`: the belief's map crosses once per setMap (the writing end keeps it).
void exchangeOutputs(component::BoxWire& wire, const VacuumDevices& devices, int64_t& map_version_sent);

// The algorithm's end: its own devices and API (runAlgorithmBox<VacuumBox>).
class VacuumBox {
 public:
  using Algorithm = VacuumAlgorithm;
  explicit VacuumBox(component::Motors& motors)
      : motors_(motors), api_{yaw_, laser_, bumper_, motors_, belief_, 0.0} {}
  void readInputs(component::BoxWire& wire, component::CallKind) { exchangeInputs(wire, devices()); }
  void invoke(VacuumAlgorithm& algorithm, component::CallKind) { algorithm.execute(api_); }
  void writeOutputs(component::BoxWire& wire, component::CallKind) { exchangeOutputs(wire, devices(), map_version_sent_); }

 private:
  VacuumDevices devices() { return {pose_, laser_, bumper_, motors_, belief_, api_}; }

  component::Motors& motors_;
  component::Pose3d pose_;
  YawSensor yaw_{pose_};
  component::Laser laser_;
  component::Bumper bumper_;
  component::Belief belief_;
  VacuumApi api_;
  int64_t map_version_sent_ = 0;
};

}  // namespace aula::vacuum
