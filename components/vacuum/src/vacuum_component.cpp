#include "aula/vacuum/vacuum_component.hpp"


#include <cmath>

namespace aula::vacuum {

VacuumComponent::VacuumComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world)
    : bus_(bus) {
  period_s_ = cfg.getDouble("Vacuum.Period");
  algorithm_name_ = cfg.getString("Vacuum.Algorithm");
  episode_channel_ = cfg.getString("Vacuum.Episode.Channel");
  autostart_ = cfg.getBool("Vacuum.Autostart");
  run_duration_s_ = cfg.getDouble("Vacuum.Referee.Duration");
  const auto z_band = cfg.getDoubleList("Vacuum.Map.ZBand");
  map_ = world::occupancyMapOf(world, {cfg.getDouble("Vacuum.Map.Resolution"), z_band[0], z_band[1]});
  const world::RobotSpec& robot = world::requireRobot(world, cfg.getString("Vacuum.Robot"));
  start_ = {robot.name, robot.pose.translation().x(), robot.pose.translation().y(), world::yawOf(robot.pose)};
  robot_radius_m_ = robot.shape.kind == world::ShapeKind::Cylinder ? robot.shape.radius_m
                                                                    : 0.5 * robot.shape.box_size_m.head<2>().norm();
  pose_ = std::make_unique<component::Pose3dProxy>(bus, world::channelOf(robot, "pose3d"));
  laser_ = std::make_unique<component::LaserProxy>(bus, world::channelOf(robot, "laser"));
  bumper_ = std::make_unique<component::BumperProxy>(bus, world::channelOf(robot, "bumper"));
  motors_ = std::make_unique<component::MotorsProxy>(bus, world::channelOf(robot, "motors"), cfg.getDouble("Vacuum.MaxV"),
                                                     cfg.getDouble("Vacuum.MaxW"));
  host_ = std::make_unique<component::AlgorithmHost<VacuumAlgorithm>>(
      "vacuum-cleaner", "vacuum",
      std::map<std::string, component::AlgorithmHost<VacuumAlgorithm>::Factory>{
          {"reference", makeReferenceAlgorithm}, {"bounce", makeRandomBounceAlgorithm}},
      algorithm_name_, *motors_, cfg.getDouble("Component.ExecuteBudget"));
  episode_ = std::make_unique<component::EpisodeSender>(bus, episode_channel_, "vacuum", *host_);
  host_->setOnHung([this] {  // the stuck call may still read these: never written again
    pose_->detach();
    laser_->detach();
    bumper_->detach();
    motors_->halt();
  });
  referee_status_ = std::make_unique<component::RefereeStatusListener>(
      bus, cfg.getString("Vacuum.RefereeStatus.Channel"), "vacuum-cleaner", [this] { return generation(); });
  referee_status_->setOnFinished([this](const aula::referee_status_t&) { setRunning(false); });
  yaw_ = std::make_unique<YawSensor>(*pose_);
  api_ = std::make_unique<VacuumApi>(VacuumApi{*yaw_, *laser_, *bumper_, *motors_, period_s_});
  loop_ = std::make_unique<component::ControlLoop>(bus, "vacuum-cleaner", static_cast<int64_t>(std::llround(period_s_ * 1e6)),
                                                   *motors_, [this] { step(); });
  loop_->setOnTick([this](int64_t utime) { tick(utime); });
}

void VacuumComponent::step() {
  if (!host_->call(static_cast<uint64_t>(loop_->seed()), "execute()", [this](VacuumAlgorithm& a) { a.execute(*api_); })) {
    setRunning(false);
  }
}

bool VacuumComponent::reloadAlgorithm() {
  if (algorithm().hung()) return false;  // a call is still stuck in it: the fault says so
  const bool was_running = running();
  setRunning(false);
  const bool loaded = host_->reload();
  started_utime_ = -1;  // a new episode: its clock starts at the next Run
  episode_->restart(start_);
  if (was_running && loaded) setRunning(true);
  return loaded;
}

void VacuumComponent::setRunning(bool running) {
  loop_->setRunning(running);
  if (running && started_utime_ < 0) started_utime_ = loop_->simTimeUs();  // the referee's 900 s start at Run
  episode_->markChanged();
}

void VacuumComponent::teleoperate(double v_mps, double w_radps) {
  if (running()) return;
  motors_->sendV(v_mps);
  motors_->sendW(w_radps);
}

void VacuumComponent::tick(int64_t utime) {
  // Autostart runs the algorithm from the first tick the component sees (sim time 0 in a
  // headless lockstep run; later when windows join a running world), once.
  if (autostart_ && !autostarted_) {
    autostarted_ = true;
    setRunning(true);
  }
  episode_->tick(utime, {running(), started_utime_, std::nullopt});
  if (on_tick_) on_tick_(utime);
}

}  // namespace aula::vacuum
