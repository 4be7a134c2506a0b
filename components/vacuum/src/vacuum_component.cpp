#include "aula/vacuum/vacuum_component.hpp"

#include <aula/episode_t.hpp>

#include <cmath>

namespace aula::vacuum {

VacuumComponent::VacuumComponent(lcm::LCM& bus, const config::Config& cfg) : bus_(bus) {
  const double max_v = cfg.getDouble("Vacuum.MaxV", 0.5);
  const double max_w = cfg.getDouble("Vacuum.MaxW", 3.0);
  period_s_ = cfg.getDouble("Vacuum.Period", 0.08);
  if (!(max_v > 0) || !(max_w > 0)) throw config::ConfigError(cfg.origin("Vacuum.MaxV") + ": Vacuum.MaxV and Vacuum.MaxW must be > 0");
  if (!(period_s_ >= 0.005 && period_s_ <= 1.0)) throw config::ConfigError(cfg.origin("Vacuum.Period") + ": Vacuum.Period must be in [0.005, 1] s");
  algorithm_name_ = cfg.getString("Vacuum.Algorithm", "student");
  if (algorithm_name_ != "student" && algorithm_name_ != "reference" && algorithm_name_ != "bounce") {
    throw config::ConfigError(cfg.origin("Vacuum.Algorithm") + ": Vacuum.Algorithm = '" + algorithm_name_ +
                              "': expected student, reference or bounce");
  }
  episode_channel_ = cfg.getString("Vacuum.Episode.Channel", "VACUUM_EPISODE");
  map_yaml_ = cfg.getString("Vacuum.Map", "vacuum.yaml");
  autostart_ = cfg.getBool("Vacuum.Autostart", false);
  run_duration_s_ = cfg.getDouble("Vacuum.Referee.Duration", 900);
  pose_ = std::make_unique<component::Pose3dProxy>(bus, cfg.getString("Vacuum.Pose3D.Channel", "ROOMBA_POSE"));
  laser_ = std::make_unique<component::LaserProxy>(bus, cfg.getString("Vacuum.Laser.Channel", "ROOMBA_LASER"));
  bumper_ = std::make_unique<component::BumperProxy>(bus, cfg.getString("Vacuum.Bumper.Channel", "ROOMBA_BUMPER"));
  motors_ = std::make_unique<component::MotorsProxy>(bus, cfg.getString("Vacuum.Motors.Channel", "ROOMBA_MOTORS"), max_v, max_w);
  yaw_ = std::make_unique<YawSensor>(*pose_);
  api_ = std::make_unique<VacuumApi>(VacuumApi{*yaw_, *laser_, *bumper_, *motors_, period_s_});
  loop_ = std::make_unique<component::ControlLoop>(bus, "vacuum-cleaner", static_cast<int64_t>(std::llround(period_s_ * 1e6)),
                                                   *motors_, [this] { step(); });
  loop_->setOnTick([this](int64_t utime) { tick(utime); });
}

void VacuumComponent::step() {
  if (!algorithm_) {
    const auto seed = static_cast<uint64_t>(loop_->seed());
    algorithm_ = algorithm_name_ == "reference" ? makeReferenceAlgorithm(seed)
                 : algorithm_name_ == "bounce"  ? makeRandomBounceAlgorithm(seed)
                                                : makeStudentAlgorithm(seed);
  }
  algorithm_->execute(*api_);
}

void VacuumComponent::setRunning(bool running) {
  loop_->setRunning(running);
  episode_dirty_ = true;
}

void VacuumComponent::teleoperate(double v_mps, double w_radps) {
  if (running()) return;
  motors_->sendV(v_mps);
  motors_->sendW(w_radps);
}

void VacuumComponent::tick(int64_t utime) {
  if (autostart_ && !running() && utime == 0) setRunning(true);
  if (episode_dirty_ || utime - last_episode_utime_ >= 1'000'000) {
    aula::episode_t msg;
    msg.utime = utime;
    msg.exercise = "vacuum";
    msg.algorithm = algorithm_name_;
    msg.goal_set = false;
    msg.goal_x = msg.goal_y = 0;
    msg.running = running();
    msg.started_utime = -1;
    bus_.publish(episode_channel_, &msg);
    last_episode_utime_ = utime;
    episode_dirty_ = false;
  }
  if (on_tick_) on_tick_(utime);
}

}  // namespace aula::vacuum
