#include "aula/teletaxi/taxi_component.hpp"

#include <aula/world/map_transform.hpp>

#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <stdexcept>

namespace aula::teletaxi {
namespace {

std::string resolveMapPath(const std::string& value) {
  if (!value.empty() && value.front() == '/') return value;
  return std::string(AULA_MAPS_DIR) + "/" + value;
}

}  // namespace

TaxiComponent::TaxiComponent(lcm::LCM& bus, const config::Config& cfg) : bus_(bus) {
  const double max_v = cfg.getDouble("TeleTaxi.MaxV", 20.0);
  const double max_w = cfg.getDouble("TeleTaxi.MaxW", 2.0);
  const double period_s = cfg.getDouble("TeleTaxi.Period", 0.08);
  if (!(max_v > 0) || !(max_w > 0)) throw config::ConfigError(cfg.origin("TeleTaxi.MaxV") + ": TeleTaxi.MaxV and TeleTaxi.MaxW must be > 0");
  if (!(period_s >= 0.005 && period_s <= 1.0)) {
    throw config::ConfigError(cfg.origin("TeleTaxi.Period") + ": TeleTaxi.Period must be in [0.005, 1] s");
  }
  episode_channel_ = cfg.getString("TeleTaxi.Episode.Channel", "TELETAXI_EPISODE");
  algorithm_name_ = cfg.getString("TeleTaxi.Algorithm", "student");
  if (algorithm_name_ == "student") {
    algorithm_ = makeStudentAlgorithm();
  } else if (algorithm_name_ == "reference") {
    algorithm_ = makeReferenceAlgorithm();
  } else {
    throw config::ConfigError(cfg.origin("TeleTaxi.Algorithm") + ": TeleTaxi.Algorithm = '" +
                              algorithm_name_ + "': expected student or reference");
  }

  std::string image_path;
  const std::string yaml = resolveMapPath(cfg.getString("TeleTaxi.Map", "cityLarge.yaml"));
  const world::MapTransform transform = world::MapTransform::load(yaml, &image_path);
  cv::Mat map = cv::imread(image_path, cv::IMREAD_GRAYSCALE);
  if (map.empty()) throw std::runtime_error(image_path + ": cannot read the map image");
  grid_ = std::make_unique<Grid>(map, transform);

  pose_ = std::make_unique<component::Pose3dProxy>(bus, cfg.getString("TeleTaxi.Pose3D.Channel", "TAXI_POSE"));
  motors_ = std::make_unique<component::MotorsProxy>(
      bus, cfg.getString("TeleTaxi.Motors.Channel", "TAXI_MOTORS"), max_v, max_w);
  api_ = std::make_unique<TaxiApi>(*pose_, *motors_, *grid_);
  loop_ = std::make_unique<component::ControlLoop>(
      bus, "teletaxi", static_cast<int64_t>(std::llround(period_s * 1e6)), *motors_,
      [this] { algorithm_->execute(*api_); });
  loop_->setOnTick([this](int64_t utime) { tick(utime); });

  autostart_ = cfg.getBool("TeleTaxi.Autostart", false);
  if (cfg.has("TeleTaxi.Destination")) {
    const auto d = cfg.getDoubleList("TeleTaxi.Destination");
    if (d.size() != 2) {
      throw config::ConfigError(cfg.origin("TeleTaxi.Destination") +
                                ": TeleTaxi.Destination needs two numbers: x, y in metres");
    }
    setDestination(d[0], d[1]);
  }
}

void TaxiComponent::setDestination(double x_m, double y_m) {
  if (running()) stop();
  destination_ = std::make_pair(x_m, y_m);
  const auto [gx, gy] = grid_->worldToGrid(x_m, y_m);
  grid_->setDestiny(gx, gy);
  grid_->resetPath();
  path_generated_ = false;
  episode_dirty_ = true;
}

bool TaxiComponent::generatePath(std::string* why) {
  auto fail = [&](const char* reason) {
    if (why) *why = reason;
    return false;
  };
  if (!destination_) return fail("choose a destination first (double-click on the map)");
  if (!pose_->received()) return fail("no pose from the simulator yet");
  const auto [px, py] = grid_->worldToGrid(pose_->getX(), pose_->getY());
  grid_->setPose(px, py);
  grid_->resetPath();
  algorithm_->generatePath(*api_);
  path_generated_ = true;
  return true;
}

bool TaxiComponent::go(std::string* why) {
  if (!destination_) {
    if (why) *why = "choose a destination first";
    return false;
  }
  if (started_utime_ < 0) started_utime_ = loop_->simTimeUs();
  loop_->setRunning(true);
  episode_dirty_ = true;
  return true;
}

void TaxiComponent::stop() {
  loop_->setRunning(false);
  episode_dirty_ = true;
}

void TaxiComponent::teleoperate(double v_mps, double w_radps) {
  if (running()) return;
  motors_->sendV(v_mps);
  motors_->sendW(w_radps);
}

void TaxiComponent::poll() { loop_->poll(); }

void TaxiComponent::tick(int64_t utime) {
  if (pose_->received()) {
    const auto [px, py] = grid_->worldToGrid(pose_->getX(), pose_->getY());
    grid_->setPose(px, py);
  }
  if (autostart_ && destination_ && pose_->received() && !running() && started_utime_ < 0) {
    if (!path_generated_) generatePath();
    // GO! takes effect from this tick: the first execute() runs at the next period.
    started_utime_ = utime;
    loop_->setRunning(true);
    episode_dirty_ = true;
  }
  if (episode_dirty_ || utime - last_episode_utime_ >= 1'000'000) publishEpisode(utime);
  if (on_tick_) on_tick_(utime);
}

void TaxiComponent::publishEpisode(int64_t utime) {
  aula::episode_t msg;
  msg.utime = utime;
  msg.exercise = "teletaxi";
  msg.algorithm = algorithm_name_;
  msg.goal_set = destination_.has_value();
  msg.goal_x = destination_ ? destination_->first : 0.0;
  msg.goal_y = destination_ ? destination_->second : 0.0;
  msg.running = running();
  msg.started_utime = started_utime_;
  bus_.publish(episode_channel_, &msg);
  last_episode_utime_ = utime;
  episode_dirty_ = false;
}

}  // namespace aula::teletaxi
