#include "aula/teletaxi/taxi_component.hpp"

#include <aula/teletaxi/gradient_field.hpp>
#include <aula/geometry/map_transform.hpp>

#include <opencv2/core.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace aula::teletaxi {
TaxiComponent::TaxiComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world) : bus_(bus) {
  const double period_s = cfg.getDouble("TeleTaxi.Period");
  episode_channel_ = cfg.getString("TeleTaxi.Episode.Channel");
  algorithm_name_ = cfg.getString("TeleTaxi.Algorithm");

  const auto z_band = cfg.getDoubleList("TeleTaxi.Map.ZBand");
  world::OccupancyMap map = world::occupancyMapOf(world, {cfg.getDouble("TeleTaxi.Map.Resolution"), z_band[0], z_band[1]});
  grid_ = std::make_unique<Grid>(map.image, map.transform);
  map_ = std::move(map);

  const world::RobotSpec& robot = world::requireRobot(world, cfg.getString("TeleTaxi.Robot"));
  start_xy_m_ = {robot.pose.translation().x(), robot.pose.translation().y()};
  start_ = {robot.name, start_xy_m_.first, start_xy_m_.second, world::yawOf(robot.pose)};
  // The configured destination must be one the taxi can reach: refused at once, with the reason.
  const auto d = cfg.getDoubleList("TeleTaxi.Destination");
  if (const auto problem = destinationProblem(d[0], d[1])) {
    throw config::ConfigError(cfg.origin("TeleTaxi.Destination") + ": TeleTaxi.Destination = " + cfg.getString("TeleTaxi.Destination") +
                              ": " + *problem);
  }
  pose_ = std::make_unique<component::Pose3dProxy>(bus, world::channelOf(robot, "pose3d"));
  motors_ = std::make_unique<component::MotorsProxy>(bus, world::channelOf(robot, "motors"), cfg.getDouble("TeleTaxi.MaxV"),
                                                     cfg.getDouble("TeleTaxi.MaxW"));
  host_ = std::make_unique<component::AlgorithmHost<TaxiAlgorithm>>(
      "teletaxi", "teletaxi",
      std::map<std::string, component::AlgorithmHost<TaxiAlgorithm>::Factory>{
          {"reference", [](uint64_t) { return makeReferenceAlgorithm(); }}},
      algorithm_name_, *motors_, cfg.getDouble("Component.ExecuteBudget"));
  episode_ = std::make_unique<component::EpisodeSender>(bus, episode_channel_, "teletaxi", *host_);
  host_->setOnHung([this] {  // the stuck call may still read these (and the grid): never written again
    pose_->detach();
    motors_->halt();
  });
  referee_status_ = std::make_unique<component::RefereeStatusListener>(
      bus, cfg.getString("TeleTaxi.RefereeStatus.Channel"), "teletaxi", [this] { return generation(); });
  referee_status_->setOnFinished([this](const aula::referee_status_t&) { stop(); });
  api_ = std::make_unique<TaxiApi>(*pose_, *motors_, *grid_);
  loop_ = std::make_unique<component::ControlLoop>(
      bus, "teletaxi", static_cast<int64_t>(std::llround(period_s * 1e6)), *motors_, [this] {
        if (!host_->call(0, "execute()", [this](TaxiAlgorithm& a) { a.execute(*api_); })) stop();
      });
  loop_->setOnTick([this](int64_t utime) { tick(utime); });

  autostart_ = cfg.getBool("TeleTaxi.Autostart");
  setDestination(d[0], d[1]);
}

std::optional<std::string> TaxiComponent::destinationProblem(double x_m, double y_m) const {
  if (const auto problem = world::pointProblem(map_, x_m, y_m)) return problem;
  if (std::hypot(x_m - start_xy_m_.first, y_m - start_xy_m_.second) < kMinTripM) {
    char where[96];
    std::snprintf(where, sizeof where, "(%.1f, %.1f)", x_m, y_m);
    return std::string(where) + " is closer than " + std::to_string(static_cast<int>(kMinTripM)) +
           " m to the taxi's start: choose a destination to drive to";
  }
  return tripProblem(start_xy_m_, {x_m, y_m}, "the taxi's start");
}

std::optional<std::string> TaxiComponent::tripProblem(std::pair<double, double> from, std::pair<double, double> to,
                                                      const std::string& from_what) const {
  if (const auto problem = world::pointProblem(map_, to.first, to.second)) return problem;
  char where[96];
  std::snprintf(where, sizeof where, "(%.1f, %.1f)", to.first, to.second);
  // Reachable: the GPP field grown from the destination covers the start.
  GradientField field(map_.image);
  const auto [gx, gy] = grid_->worldToGrid(to.first, to.second);
  if (!field.compute({gx, gy})) return std::string(where) + " is too close to a building for the taxi";
  const auto [sx, sy] = grid_->worldToGrid(from.first, from.second);
  if (!std::isfinite(field.value(sx, sy))) {
    char start[96];
    std::snprintf(start, sizeof start, " (%.1f, %.1f)", from.first, from.second);
    return std::string(where) + " cannot be reached from " + from_what + start +
           ": GPP's field from the destination does not reach it (walled off, or the taxi is not on the streets)";
  }
  return std::nullopt;
}

void TaxiComponent::setDestination(double x_m, double y_m) {
  if (running()) stop();
  destination_ = std::make_pair(x_m, y_m);
  const auto [gx, gy] = grid_->worldToGrid(x_m, y_m);
  grid_->setDestiny(gx, gy);
  grid_->resetPath();
  path_generated_ = false;
  episode_->markChanged();
}

bool TaxiComponent::generatePath(std::string* why) {
  auto fail = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  if (!destination_) return fail("choose a destination first (double-click on the map)");
  if (!pose_->received()) return fail("no pose from the simulator yet");
  // The taxi may have been teleoperated (or started) somewhere the destination cannot be reached from.
  if (const auto problem = tripProblem({pose_->getX(), pose_->getY()}, *destination_, "where the taxi stands")) {
    return fail("cannot generate a path: " + *problem);
  }
  const auto [px, py] = grid_->worldToGrid(pose_->getX(), pose_->getY());
  grid_->setPose(px, py);
  grid_->resetPath();
  if (!host_->call(0, "generatePath()", [this](TaxiAlgorithm& a) { a.generatePath(*api_); })) {
    episode_->markChanged();
    return fail("the algorithm failed in generatePath(); see the message");
  }
  path_generated_ = true;
  return true;
}

bool TaxiComponent::hasPath() const {
  return grid_->isPathFinded() && cv::countNonZero(grid_->path()) > 0;
}

bool TaxiComponent::go(std::string* why) {
  if (!destination_) {
    if (why) *why = "choose a destination first";
    return false;
  }
  if (started_utime_ < 0) started_utime_ = loop_->simTimeUs();
  loop_->setRunning(true);
  episode_->markChanged();
  return true;
}

bool TaxiComponent::reloadAlgorithm() {
  if (algorithm().hung()) return false;  // a call is still stuck in it: the fault says so
  stop();
  const bool loaded = host_->reload();
  started_utime_ = -1;  // the referee's clock starts again at the next GO!
  path_generated_ = false;
  grid_->resetPath();
  episode_->restart(start_);
  return loaded;
}

void TaxiComponent::stop() {
  loop_->setRunning(false);
  episode_->markChanged();
}

void TaxiComponent::teleoperate(double v_mps, double w_radps) {
  if (running()) return;
  motors_->sendV(v_mps);
  motors_->sendW(w_radps);
}

void TaxiComponent::poll() { loop_->poll(); }

void TaxiComponent::tick(int64_t utime) {
  if (pose_->received() && !host_->hung()) {
    const auto [px, py] = grid_->worldToGrid(pose_->getX(), pose_->getY());
    grid_->setPose(px, py);
  }
  if (autostart_ && destination_ && pose_->received() && !running() && started_utime_ < 0 && !refusal_) autostartAt(utime);
  episode_->tick(utime, {running(), started_utime_, destination_});
  if (on_tick_) on_tick_(utime);
}

void TaxiComponent::autostartAt(int64_t utime) {
  if (!path_generated_) {
    const std::pair<double, double> here{pose_->getX(), pose_->getY()};
    if (const auto problem = tripProblem(here, *destination_, "where the taxi stands")) {
      // Nothing to drive to: headless, the process ends with the reason (runComponent).
      refusal_ = "cannot generate a path: " + *problem;
      return;
    }
    generatePath();  // a fault in the student's generatePath() is the run's fault, graded as such
  }
  // GO! takes effect from this tick: the first execute() runs at the next period.
  started_utime_ = utime;
  loop_->setRunning(true);
  episode_->markChanged();
}


}  // namespace aula::teletaxi
