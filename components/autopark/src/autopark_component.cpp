#include "aula/autopark/autopark_component.hpp"

#include <aula/episode_t.hpp>
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

AutoparkComponent::AutoparkComponent(lcm::LCM& bus, const config::Config& cfg, const world::WorldSpec& world)
    : bus_(bus), world_(world) {
  period_s_ = cfg.getDouble("Autopark.Period");
  algorithm_name_ = cfg.getString("Autopark.Algorithm");
  episode_channel_ = cfg.getString("Autopark.Episode.Channel");
  autostart_ = cfg.getBool("Autopark.Autostart");
  robot_name_ = cfg.getString("Autopark.Robot");
  const world::RobotSpec* car = &world::requireRobot(world_, robot_name_);
  // The car's three lasers are its plugins named laser_front, laser_rear and laser_right.
  pose_ = std::make_unique<component::Pose3dProxy>(bus, world::channelOf(*car, "pose3d"));
  front_ = std::make_unique<component::LaserProxy>(bus, world::channelOf(*car, "laser", "laser_front"));
  rear_ = std::make_unique<component::LaserProxy>(bus, world::channelOf(*car, "laser", "laser_rear"));
  right_ = std::make_unique<component::LaserProxy>(bus, world::channelOf(*car, "laser", "laser_right"));
  motors_ = std::make_unique<component::MotorsProxy>(bus, world::channelOf(*car, "motors"), cfg.getDouble("Autopark.MaxV"),
                                                     cfg.getDouble("Autopark.MaxW"));
  api_ = std::make_unique<AutoparkApi>(AutoparkApi{*pose_, *front_, *rear_, *right_, *motors_, period_s_,
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
  loop_ = std::make_unique<component::ControlLoop>(bus, "autopark", static_cast<int64_t>(std::llround(period_s_ * 1e6)),
                                                   *motors_, [this] { step(); });
  loop_->setOnTick([this](int64_t utime) { tick(utime); });
}

void AutoparkComponent::step() {
  if (!algorithm_) {
    const auto seed = static_cast<uint64_t>(loop_->seed());
    algorithm_ = algorithm_name_ == "reactive"  ? makeReactiveAlgorithm(seed)
                 : algorithm_name_ == "planner" ? makePlannedAlgorithm(seed)
                                                : makeStudentAlgorithm(seed);
  }
  algorithm_->execute(*api_);
}

void AutoparkComponent::setRunning(bool running) {
  loop_->setRunning(running);
  if (running && started_utime_ < 0) started_utime_ = loop_->simTimeUs();  // the referee's clock starts at Run
  episode_dirty_ = true;
}

void AutoparkComponent::teleoperate(double v_mps, double w_radps) {
  if (running()) return;
  motors_->sendV(v_mps);
  motors_->sendW(w_radps);
}

void AutoparkComponent::tick(int64_t utime) {
  if (autostart_ && !running() && utime == 0) setRunning(true);
  if (episode_dirty_ || utime - last_episode_utime_ >= 1'000'000) {
    aula::episode_t msg;
    msg.utime = utime;
    msg.exercise = "autopark";
    msg.algorithm = algorithm_name_;
    msg.goal_set = false;
    msg.goal_x = msg.goal_y = 0;
    msg.running = running();
    msg.started_utime = started_utime_;
    bus_.publish(episode_channel_, &msg);
    last_episode_utime_ = utime;
    episode_dirty_ = false;
  }
  if (on_tick_) on_tick_(utime);
}

}  // namespace aula::autopark
