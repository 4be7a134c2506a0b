#include "coverage_referee_node.hpp"

#include <aula/lcm/bus.hpp>
#include <aula/world/map_transform.hpp>
#include <aula/world/world_spec.hpp>

#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace aula::vacuum {

CoverageRefereeNode::CoverageRefereeNode(lcm::LCM& bus, const config::Config& cfg) {
  CoverageSettings s;
  s.duration_s = cfg.getDouble("Vacuum.Referee.Duration", s.duration_s);
  s.full_mark_coverage_percent = cfg.getDouble("Vacuum.Referee.FullMarkCoverage", s.full_mark_coverage_percent);
  s.robot_radius_m = cfg.getDouble("Vacuum.Referee.RobotRadius", s.robot_radius_m);
  if (!(s.duration_s > 0)) throw config::ConfigError(cfg.origin("Vacuum.Referee.Duration") + ": Vacuum.Referee.Duration must be > 0");
  if (!(s.full_mark_coverage_percent > 0 && s.full_mark_coverage_percent <= 100)) {
    throw config::ConfigError(cfg.origin("Vacuum.Referee.FullMarkCoverage") + ": Vacuum.Referee.FullMarkCoverage must be in (0, 100]");
  }
  map_yaml_ = cfg.getString("Vacuum.Map", "vacuum.yaml");
  std::string image;
  const world::MapTransform t = world::MapTransform::load(std::string(AULA_MAPS_DIR) + "/" + map_yaml_, &image);
  const cv::Mat map = cv::imread(image, cv::IMREAD_GRAYSCALE);
  if (map.empty()) throw std::runtime_error(image + ": cannot read the map image");
  const auto start = cfg.getDoubleList("Vacuum.Referee.FloorPoint", {-1.0, 1.5});
  if (start.size() != 2) throw config::ConfigError(cfg.origin("Vacuum.Referee.FloorPoint") + ": needs x, y");
  referee_ = std::make_unique<CoverageReferee>(CoverageGrid(map, t, start[0], start[1]), s);

  lcmbus::subscribe(bus, cfg.getString("Vacuum.Pose3D.Channel", "ROOMBA_POSE"), &CoverageRefereeNode::onPose, this);
  lcmbus::subscribe(bus, cfg.getString("Vacuum.Bumper.Channel", "ROOMBA_BUMPER"), &CoverageRefereeNode::onBumper, this);
  lcmbus::subscribe(bus, cfg.getString("Vacuum.Episode.Channel", "VACUUM_EPISODE"), &CoverageRefereeNode::onEpisode, this);
  const double period_s = cfg.getDouble("Vacuum.Referee.Period", 0.2);
  clock_ = std::make_unique<lcmbus::LockstepClient>(
      bus, "vacuum-referee", static_cast<int64_t>(std::llround(period_s * 1e6)), [this](int64_t utime) {
        referee_->onTick(utime);
        if (referee_->finished() && !announced_) {
          announced_ = true;
          if (on_finished_) on_finished_();
        }
      });
}

void CoverageRefereeNode::onPose(const lcm::ReceiveBuffer*, const std::string&, const aula::pose3d_t* msg) {
  ++pose_messages_;
  referee_->onPose(msg->utime, msg->x, msg->y);
  if (on_pose_) on_pose_(msg->x, msg->y, msg->yaw);
}

void CoverageRefereeNode::onBumper(const lcm::ReceiveBuffer*, const std::string&, const aula::bumper_t* msg) {
  referee_->onBump(msg->utime, msg->state == aula::bumper_t::PRESSED);
}

void CoverageRefereeNode::onEpisode(const lcm::ReceiveBuffer*, const std::string&, const aula::episode_t* msg) {
  algorithm_ = msg->algorithm;
}

referee::Report CoverageRefereeNode::report() const {
  const CoverageReferee& r = *referee_;
  const auto& tick = clock_->lastTick();
  referee::Report out;
  out.set("exercise", "vacuum");
  out.set("mark", r.mark());
  out.set("sim_time_s", r.elapsedS());
  out.set("seed", static_cast<long long>(tick.seed));
  out.set("world", tick.world);
  out.set("algorithm", algorithm_);
  out.set("finished", r.finished());
  out.set("coverage_percent", r.coveragePercent());
  out.set("full_mark_coverage_percent", r.settings().full_mark_coverage_percent);
  out.set("coverage_per_100s", r.coveragePer100s());
  out.set("cleaned_area_m2", r.grid().cleanedPixels() * std::pow(r.grid().transform().resolution_m, 2));
  out.set("floor_area_m2", r.grid().floorAreaM2());
  out.set("bumps", r.bumps());
  out.set("stuck_s", r.stuckS());
  // 50 Hz x the run: fewer means the bus lost messages and the coverage is an underestimate.
  out.set("pose_messages", pose_messages_);
  return out;
}

std::string CoverageRefereeNode::summary() const {
  const CoverageReferee& r = *referee_;
  char text[512];
  std::snprintf(text, sizeof text,
                "Vacuum cleaner mark: %.2f / 10\n"
                "  coverage %.2f %% of %.1f m2 of floor in %.0f s sim (full mark at %.0f %%)\n"
                "  bumps %lld, time stuck %.1f s\n",
                r.mark(), r.coveragePercent(), r.grid().floorAreaM2(), r.elapsedS(),
                r.settings().full_mark_coverage_percent, r.bumps(), r.stuckS());
  return text;
}

}  // namespace aula::vacuum
