#include "aula/autopark/autopark_box.hpp"

namespace aula::autopark {

namespace {

void ioMount(component::BoxWire& wire, LaserMount& mount) {
  wire.io(mount.x_m, "laser mount");
  wire.io(mount.y_m, "laser mount");
  wire.io(mount.yaw_rad, "laser mount");
}

}  // namespace

void exchangeInputs(component::BoxWire& wire, AutoparkApi& api) {
  component::ioPose(wire, api.pose3d);
  component::ioLaser(wire, api.laser1);
  component::ioLaser(wire, api.laser2);
  component::ioLaser(wire, api.laser3);
  component::ioMotorCommands(wire, api.motors);
  component::ioClock(wire, api.clock);
  wire.io(api.period_s, "period");
  ioMount(wire, api.mount1);
  ioMount(wire, api.mount2);
  ioMount(wire, api.mount3);
  wire.io(api.car_length_m, "car");
  wire.io(api.car_width_m, "car");
  wire.io(api.min_turn_radius_m, "car");
  wire.io(api.turn_centre_x_m, "car");
  wire.io(api.wheelbase_m, "car");
  wire.io(api.status, kMaxStatusBytes, "status");  // what the algorithm left, as it reads it again
}

void exchangeOutputs(component::BoxWire& wire, AutoparkApi& api) {
  component::ioMotorCommands(wire, api.motors);
  wire.io(api.status, kMaxStatusBytes, "status");
}

}  // namespace aula::autopark
