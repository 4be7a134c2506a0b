#include "aula/vacuum/vacuum_component.hpp"

namespace aula::vacuum {

VacuumComponent::VacuumComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                                 const std::optional<auth::Key>& lockstep_key)
    : ExerciseComponent(bus, cfg, world, "vacuum", lockstep_key) {
  run_duration_s_ = cfg.getDouble("Vacuum.Referee.Duration");
  const auto z_band = cfg.getDoubleList("Vacuum.Map.ZBand");
  map_ = world::occupancyMapOf(world, {cfg.getDouble("Vacuum.Map.Resolution"), z_band[0], z_band[1]});
  const world::RobotSpec& robot = world::requireRobot(world, cfg.getString("Vacuum.Robot"));
  robot_radius_m_ = robot.shape.kind == world::ShapeKind::Cylinder ? robot.shape.radius_m
                                                                    : 0.5 * robot.shape.box_size_m.head<2>().norm();
  laser_ = std::make_unique<component::LaserProxy>(bus, world::channelOf(robot, "laser"));
  bumper_ = std::make_unique<component::BumperProxy>(bus, world::channelOf(robot, "bumper"));
  yaw_ = std::make_unique<YawSensor>(poseProxy());
  belief_publisher_ = std::make_unique<component::BeliefPublisher>(bus, cfg.getString("Vacuum.Belief.Channel"), belief_);
  api_ = std::make_unique<VacuumApi>(
      VacuumApi{*yaw_, *laser_, *bumper_, motorsProxy(), belief_, cfg.getDouble("Vacuum.Period")});
}

}  // namespace aula::vacuum
