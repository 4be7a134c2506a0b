#pragma once
// How a robot's motors plugin says it moves: "diff" turns in place about its centre; "ackermann"
// is car-like and turns about a point on its rear axle line, never tighter than a minimum radius.
// One reader, shared by the simulator's motors driver and the components that draw or plan for
// the car, so they cannot disagree.

#include <aula/world/world_spec.hpp>

namespace aula::world {

struct CarKinematics {
  bool ackermann = false;
  double wheelbase_m = 2.6;
  double max_steer_rad = 0.48;
  double min_turn_radius_m = 0.0;  // of the rear axle centre; 0 when the robot turns in place
  double rear_axle_x_m = 0.0;      // body-frame x of the point the robot turns about
};

// Reads kinematics, wheelbase, max_steer_rad and rear_axle_x; throws WorldError naming the
// robot and plugin when a value is out of range.
CarKinematics readCarKinematics(const PluginSpec& motors);

}  // namespace aula::world
