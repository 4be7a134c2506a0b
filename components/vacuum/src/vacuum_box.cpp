#include "aula/vacuum/vacuum_box.hpp"

namespace aula::vacuum {

void exchangeInputs(component::BoxWire& wire, const VacuumDevices& devices) {
  component::ioPose(wire, devices.pose);
  component::ioLaser(wire, devices.laser);
  component::ioBumper(wire, devices.bumper);
  component::ioMotorCommands(wire, devices.motors);
  component::ioClock(wire, devices.api.clock);
  wire.io(devices.api.period_s, "period");
}

void exchangeOutputs(component::BoxWire& wire, const VacuumDevices& devices, int64_t& map_version_sent) {
  component::ioMotorCommands(wire, devices.motors);
  component::ioBelief(wire, devices.belief, map_version_sent);
}

}  // namespace aula::vacuum
