#include "aula/teletaxi/taxi_component.hpp"

#include <aula/teletaxi/gradient_field.hpp>
#include <aula/geometry/map_transform.hpp>
#include <aula/plan_t.hpp>

#include <opencv2/core.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace aula::teletaxi {
TaxiComponent::TaxiComponent(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                             const std::optional<auth::Key>& lockstep_key)
    : ExerciseComponent(bus, cfg, world, "teletaxi", lockstep_key), plan_channel_(cfg.getString("TeleTaxi.Plan.Channel")) {
  const auto z_band = cfg.getDoubleList("TeleTaxi.Map.ZBand");
  world::OccupancyMap map = world::occupancyMapOf(world, {cfg.getDouble("TeleTaxi.Map.Resolution"), z_band[0], z_band[1]});
  grid_ = std::make_unique<Grid>(map.image, map.transform);
  map_ = std::move(map);
  start_xy_m_ = {startPose().x_m, startPose().y_m};
  grid_window_ = desktop::placementOf(cfg, "TeleTaxi.GridWindow");
  // The configured destination must be one the taxi can reach: refused at once, with the reason.
  const auto d = cfg.getDoubleList("TeleTaxi.Destination");
  if (const auto problem = destinationProblem(d[0], d[1])) {
    throw config::ConfigError(cfg.origin("TeleTaxi.Destination") + ": TeleTaxi.Destination = " + cfg.getString("TeleTaxi.Destination") +
                              ": " + *problem);
  }
  api_ = std::make_unique<TaxiApi>(poseProxy(), motorsProxy(), *grid_);
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
  episode().markChanged();
}

bool TaxiComponent::generatePath(std::string* why) {
  auto fail = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  if (!destination_) return fail("choose a destination first (double-click on the map)");
  if (!truePose().received()) return fail("no pose from the simulator yet");
  // The taxi may have been teleoperated (or started) somewhere the destination cannot be reached from.
  if (const auto problem = tripProblem({truePose().getX(), truePose().getY()}, *destination_, "where the taxi stands")) {
    return fail("cannot generate a path: " + *problem);
  }
  const auto [px, py] = grid_->worldToGrid(truePose().getX(), truePose().getY());
  grid_->setPose(px, py);
  grid_->resetPath();
  if (!callAlgorithm(component::CallKind::Plan, "generatePath()")) {
    episode().markChanged();
    return fail("the algorithm failed in generatePath(); see the message");
  }
  path_generated_ = true;
  publishPlan();
  return true;
}

void TaxiComponent::publishPlan() {
  aula::plan_t msg{};
  msg.utime = simTimeUs();
  const geometry::MapTransform& t = grid_->transform();
  msg.width = grid_->getWidth();
  msg.height = grid_->getHeight();
  msg.resolution_m = t.resolution_m;
  msg.origin_x_m = t.origin_x_m;
  msg.origin_y_m = t.origin_y_m;
  if (cv::countNonZero(grid_->field()) > 0) {
    const cv::Mat image = grid_->fieldImage();
    msg.field.assign(image.datastart, image.dataend);  // continuous: made by fieldImage()
    msg.field_count = static_cast<int32_t>(msg.field.size());
  }
  const cv::Mat& path = grid_->path();
  for (int row = 0; row < path.rows; ++row) {
    for (int col = 0; col < path.cols; ++col) {
      if (path.at<float>(row, col) == 0) continue;
      msg.path_col.push_back(col);
      msg.path_row.push_back(row);
    }
  }
  msg.path_count = static_cast<int32_t>(msg.path_col.size());
  bus().publish(plan_channel_, &msg);
}

bool TaxiComponent::hasPath() const {
  return grid_->isPathFinded() && cv::countNonZero(grid_->path()) > 0;
}

bool TaxiComponent::go(std::string* why) {
  if (!destination_) {
    if (why) *why = "choose a destination first";
    return false;
  }
  pressRun(true);
  return true;
}

bool TaxiComponent::startNewEpisode() {
  path_generated_ = false;
  grid_->resetPath();
  return false;
}

void TaxiComponent::beforeTick(int64_t) {
  if (truePose().received() && !algorithm().hung()) {
    const auto [px, py] = grid_->worldToGrid(truePose().getX(), truePose().getY());
    grid_->setPose(px, py);
  }
}

bool TaxiComponent::prepareAutostart() {
  if (!path_generated_) {
    const std::pair<double, double> here{truePose().getX(), truePose().getY()};
    if (const auto problem = tripProblem(here, *destination_, "where the taxi stands")) {
      // Nothing to drive to: headless, the process ends with the reason (runComponent).
      refusal_ = "cannot generate a path: " + *problem;
      return false;
    }
    generatePath();  // a fault in the student's generatePath() is the run's fault, graded as such
  }
  // GO! takes effect from this tick: the first execute() runs at the next period.
  return true;
}

}  // namespace aula::teletaxi
