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

AutoparkComponent::AutoparkComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world)
    : bus_(bus), world_(world) {
  period_s_ = cfg.getDouble("Autopark.Period");
  algorithm_name_ = cfg.getString("Autopark.Algorithm");
  episode_channel_ = cfg.getString("Autopark.Episode.Channel");
  autostart_ = cfg.getBool("Autopark.Autostart");
  robot_name_ = cfg.getString("Autopark.Robot");
  const world::RobotSpec* car = &world::requireRobot(world_, robot_name_);
  start_ = {car->name, car->pose.translation().x(), car->pose.translation().y(), world::yawOf(car->pose)};
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
  host_ = std::make_unique<component::AlgorithmHost<AutoparkAlgorithm>>(
      "autopark", "autopark",
      std::map<std::string, component::AlgorithmHost<AutoparkAlgorithm>::Factory>{
          {"reactive", makeReactiveAlgorithm}, {"planner", makePlannedAlgorithm}},
      algorithm_name_, *motors_, cfg.getDouble("Component.ExecuteBudget"));
  episode_ = std::make_unique<component::EpisodeSender>(bus, episode_channel_, "autopark", *host_);
  host_->setOnHung([this] {  // the stuck call may still read these: never written again
    for (component::LaserProxy* laser : {front_.get(), rear_.get(), right_.get()}) laser->detach();
    pose_->detach();
    motors_->halt();
  });
  referee_status_ = std::make_unique<component::RefereeStatusListener>(
      bus, cfg.getString("Autopark.RefereeStatus.Channel"), "autopark", [this] { return generation(); });
  referee_status_->setOnFinished([this](const aula::referee_status_t&) { setRunning(false); });
  loop_ = std::make_unique<component::ControlLoop>(bus, "autopark", static_cast<int64_t>(std::llround(period_s_ * 1e6)),
                                                   *motors_, [this] { step(); });
  loop_->setOnTick([this](int64_t utime) { tick(utime); });
}

void AutoparkComponent::step() {
  if (!host_->call(static_cast<uint64_t>(loop_->seed()), "execute()", [this](AutoparkAlgorithm& a) { a.execute(*api_); })) {
    setRunning(false);
  }
}

bool AutoparkComponent::reloadAlgorithm() {
  if (algorithm().hung()) return false;  // a call is still stuck in it: the fault says so
  const bool was_running = running();
  setRunning(false);
  const bool loaded = host_->reload();
  started_utime_ = -1;  // the referee's clock starts again at the next Run
  episode_->restart(start_);
  if (was_running && loaded) setRunning(true);
  return loaded;
}

void AutoparkComponent::setRunning(bool running) {
  loop_->setRunning(running);
  if (running && started_utime_ < 0) started_utime_ = loop_->simTimeUs();  // the referee's clock starts at Run
  episode_->markChanged();
}

void AutoparkComponent::teleoperate(double v_mps, double w_radps) {
  if (running()) return;
  motors_->sendV(v_mps);
  motors_->sendW(w_radps);
}

void AutoparkComponent::tick(int64_t utime) {
  // Autostart runs the algorithm from the first tick the component sees (sim time 0 in a
  // headless lockstep run; later when windows join a running world), once.
  if (autostart_ && !autostarted_) {
    autostarted_ = true;
    setRunning(true);
  }
  episode_->tick(utime, {running(), started_utime_, std::nullopt});
  if (on_tick_) on_tick_(utime);
}

}  // namespace aula::autopark
