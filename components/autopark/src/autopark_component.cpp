#include "aula/autopark/autopark_component.hpp"

#include <aula/world/car_kinematics.hpp>

#include <cmath>

namespace aula::autopark {

namespace {

LaserMount mountOf(const world::RobotSpec& car, const std::string& plugin_name) {
  world::channelOf(car, "laser", plugin_name);  // says what is missing when there is no such laser
  const Eigen::Isometry3d pose = car.findPluginNamed(plugin_name)->getPose("pose");
  return LaserMount{pose.translation().x(), pose.translation().y(), world::yawOf(pose)};
}

}  // namespace

AutoparkComponent::AutoparkComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                                     const std::optional<auth::Key>& lockstep_key)
    : ExerciseComponent(bus, cfg, world, "autopark", lockstep_key),
      world_(world) {
  const world::RobotSpec* car = &world::requireRobot(world_, cfg.getString("Autopark.Robot"));
  // The car's three lasers are its plugins named laser_front, laser_rear and laser_right.
  front_ = std::make_unique<component::LaserProxy>(bus, world::channelOf(*car, "laser", "laser_front"));
  rear_ = std::make_unique<component::LaserProxy>(bus, world::channelOf(*car, "laser", "laser_rear"));
  right_ = std::make_unique<component::LaserProxy>(bus, world::channelOf(*car, "laser", "laser_right"));
  api_ = std::make_unique<AutoparkApi>(AutoparkApi{poseProxy(), *front_, *rear_, *right_, motorsProxy(), cfg.getDouble("Autopark.Period"),
                                                    mountOf(*car, "laser_front"), mountOf(*car, "laser_rear"),
                                                    mountOf(*car, "laser_right")});
  api_->car_length_m = car->shape.box_size_m.x();
  api_->car_width_m = car->shape.box_size_m.y();
  if (const world::PluginSpec* motors = car->findPlugin("motors")) {
    const world::CarKinematics kinematics = world::readCarKinematics(*motors);
    api_->min_turn_radius_m = kinematics.min_turn_radius_m;
    api_->turn_centre_x_m = kinematics.rear_axle_x_m;
    api_->wheelbase_m = kinematics.wheelbase_m;
  }
}

}  // namespace aula::autopark
