#include "aula/autopark/autopark_component.hpp"

#include <aula/app/process_setup.hpp>
#include <aula/episode_t.hpp>
#include <aula/world/car_kinematics.hpp>

#include <cmath>

namespace aula::autopark {

namespace {

LaserMount mountOf(const world::RobotSpec& car, const std::string& channel, const std::string& where) {
  for (const auto& p : car.plugins) {
    if (p.type == "laser" && p.getString("channel", "") == channel) {
      const Eigen::Isometry3d pose = p.getPose("pose");
      return LaserMount{pose.translation().x(), pose.translation().y(), world::yawOf(pose)};
    }
  }
  throw config::ConfigError(where + ": the car in the world has no laser on channel '" + channel + "'");
}

}  // namespace

AutoparkComponent::AutoparkComponent(lcm::LCM& bus, const config::Config& cfg) : bus_(bus) {
  const double max_v = cfg.getDouble("Autopark.MaxV", 3.0);
  const double max_w = cfg.getDouble("Autopark.MaxW", 1.0);
  period_s_ = cfg.getDouble("Autopark.Period", 0.05);
  if (!(max_v > 0) || !(max_w > 0)) throw config::ConfigError(cfg.origin("Autopark.MaxV") + ": Autopark.MaxV and Autopark.MaxW must be > 0");
  if (!(period_s_ >= 0.005 && period_s_ <= 1.0)) throw config::ConfigError(cfg.origin("Autopark.Period") + ": Autopark.Period must be in [0.005, 1] s");
  algorithm_name_ = cfg.getString("Autopark.Algorithm", "student");
  if (algorithm_name_ != "student" && algorithm_name_ != "reactive" && algorithm_name_ != "planner") {
    throw config::ConfigError(cfg.origin("Autopark.Algorithm") + ": Autopark.Algorithm = '" + algorithm_name_ +
                              "': expected student, reactive or planner");
  }
  episode_channel_ = cfg.getString("Autopark.Episode.Channel", "AUTOPARK_EPISODE");
  autostart_ = cfg.getBool("Autopark.Autostart", false);
  world_ = world::loadWorld(app::sourcePath(cfg, "Autopark.World", "worlds/autopark.world"));
  robot_name_ = cfg.getString("Autopark.Robot", "car");
  const world::RobotSpec* car = world_.findRobot(robot_name_);
  if (car == nullptr) throw config::ConfigError(cfg.origin("Autopark.Robot") + ": the world " + world_.source_path + " has no robot '" + robot_name_ + "'");

  const std::string front = cfg.getString("Autopark.Laser1.Channel", "CAR_LASER_FRONT");
  const std::string rear = cfg.getString("Autopark.Laser2.Channel", "CAR_LASER_REAR");
  const std::string right = cfg.getString("Autopark.Laser3.Channel", "CAR_LASER_RIGHT");
  pose_ = std::make_unique<component::Pose3dProxy>(bus, cfg.getString("Autopark.Pose3D.Channel", "CAR_POSE"));
  front_ = std::make_unique<component::LaserProxy>(bus, front);
  rear_ = std::make_unique<component::LaserProxy>(bus, rear);
  right_ = std::make_unique<component::LaserProxy>(bus, right);
  motors_ = std::make_unique<component::MotorsProxy>(bus, cfg.getString("Autopark.Motors.Channel", "CAR_MOTORS"), max_v, max_w);
  api_ = std::make_unique<AutoparkApi>(AutoparkApi{*pose_, *front_, *rear_, *right_, *motors_, period_s_,
                                                    mountOf(*car, front, world_.source_path), mountOf(*car, rear, world_.source_path),
                                                    mountOf(*car, right, world_.source_path)});
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
