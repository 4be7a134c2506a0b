#include <aula/world/car_kinematics.hpp>

#include <cmath>

namespace aula::world {

CarKinematics readCarKinematics(const PluginSpec& motors) {
  const std::string where = motors.owner + "/" + motors.name;
  CarKinematics k;
  const std::string kinematics = motors.getString("kinematics", "diff");
  if (kinematics == "diff") return k;
  if (kinematics != "ackermann") {
    throw WorldError(where + ": kinematics '" + kinematics + "' is not one of: diff, ackermann");
  }
  k.ackermann = true;
  k.wheelbase_m = motors.getDouble("wheelbase", 2.6);
  k.max_steer_rad = motors.getDouble("max_steer_rad", 0.48);
  if (!(k.wheelbase_m > 0) || !(k.max_steer_rad > 0) || !(k.max_steer_rad < 1.5)) {
    throw WorldError(where + ": ackermann needs wheelbase > 0 and 0 < max_steer_rad < 1.5");
  }
  k.min_turn_radius_m = k.wheelbase_m / std::tan(k.max_steer_rad);
  k.rear_axle_x_m = motors.getDouble("rear_axle_x", -k.wheelbase_m / 2);
  if (!std::isfinite(k.rear_axle_x_m) || std::abs(k.rear_axle_x_m) > k.wheelbase_m) {
    throw WorldError(where + ": rear_axle_x must be finite and within one wheelbase of the centre");
  }
  return k;
}

}  // namespace aula::world
