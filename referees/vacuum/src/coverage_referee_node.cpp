#include "coverage_referee_node.hpp"

#include <aula/geometry/map_transform.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/referee/rubric.hpp>
#include <aula/referee/run_picture.hpp>
#include <aula/settings/tables.hpp>
#include <aula/vacuum/coverage_picture.hpp>
#include <aula/world/world_spec.hpp>

#include <cmath>
#include <filesystem>
#include <cstdio>
#include <stdexcept>

namespace aula::vacuum {

CoverageRefereeNode::CoverageRefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                                         const std::optional<auth::Key>& run_key)
    : world_file_(std::filesystem::path(world.source_path).filename().string()), world_sha256_(world.sha256) {
  outcome_.truth() = referee::TruthGate(run_key);
  settings_ = coverageSettings(cfg);
  rubric_ = referee::rubricReport(cfg, settings::tableOf("vacuum-cleaner-referee"), "Vacuum.Referee.Rubric");
  const auto z_band = cfg.getDoubleList("Vacuum.Map.ZBand");
  map_ = world::occupancyMapOf(world, {cfg.getDouble("Vacuum.Map.Resolution"), z_band[0], z_band[1]});
  // The floor is the free space reachable from where the robot starts in the world.
  const world::RobotSpec& robot = world::requireRobot(world, cfg.getString("Vacuum.Robot"));
  const Eigen::Vector3d start = robot.pose.translation();
  start_x_m_ = start.x();
  start_y_m_ = start.y();
  try {
    referee_ = newReferee(0);
  } catch (const std::exception& e) {
    throw world::WorldError(world.source_path + ": robot '" + robot.name + "' starts at (" + std::to_string(start.x()) +
                            ", " + std::to_string(start.y()) + "), which is not on the floor of the map (" + e.what() + ")");
  }

  bus.subscribe(world::channelOf(robot, "pose3d"), &CoverageRefereeNode::onPose, this);
  bus.subscribe(world::channelOf(robot, "bumper"), &CoverageRefereeNode::onBumper, this);
  bus.subscribe(cfg.getString("Vacuum.Episode.Channel"), &CoverageRefereeNode::onEpisode, this);
  status_ = std::make_unique<referee::StatusSender>(bus, cfg.getString("Vacuum.RefereeStatus.Channel"), "vacuum");
  const double period_s = cfg.getDouble("Vacuum.Referee.Period");
  clock_ = std::make_unique<lcmbus::LockstepClient>(
      bus, "vacuum-referee", static_cast<int64_t>(std::llround(period_s * 1e6)), [this](int64_t utime) {
        if (started_) referee_->onTick(utime);  // the episode's clock runs from Run
        outcome_.announceOnce(finished(), on_finished_);
        status_->tick(utime, status());
      });
  clock_->expectWorld(world.sha256, world.source_path);
  clock_->setTickFilter([this](const std::string& channel, const aula::sim_clock_t& tick) {
    return outcome_.truth().acceptTick(channel, tick);
  });
}

std::unique_ptr<CoverageReferee> CoverageRefereeNode::newReferee(int64_t origin_utime) const {
  return std::make_unique<CoverageReferee>(CoverageGrid(map_.image, map_.transform, start_x_m_, start_y_m_), settings_,
                                           origin_utime);
}

void CoverageRefereeNode::start(int64_t utime) {
  // The episode's 900 s count from "Run my algorithm" (at once when headless: sim time 0).
  referee_ = newReferee(utime);
  started_ = true;
  if (waiting_pose_ && waiting_pose_->utime >= utime) referee_->onPose(waiting_pose_->utime, waiting_pose_->x_m, waiting_pose_->y_m);
  waiting_pose_.reset();
}

void CoverageRefereeNode::onPose(const lcm::ReceiveBuffer*, const std::string& channel, const aula::pose3d_t* msg) {
  if (!outcome_.truth().accept(channel, *msg)) return;  // forged: counted, not graded
  if (msg->utime <= episode_from_utime_) return;
  ++pose_messages_;
  if (!started_) {
    // Before Run nothing is graded (teleoperation is free); the pose at the start is kept.
    waiting_pose_ = {msg->utime, msg->x, msg->y};
    if (on_pose_) on_pose_(msg->x, msg->y, msg->yaw);
    return;
  }
  referee_->onPose(msg->utime, msg->x, msg->y);
  if (!referee_->finished()) {
    have_pose_ = true;
    x_m_ = msg->x;
    y_m_ = msg->y;
    yaw_rad_ = msg->yaw;
  }
  if (on_pose_) on_pose_(msg->x, msg->y, msg->yaw);
}

void CoverageRefereeNode::onBumper(const lcm::ReceiveBuffer*, const std::string& channel, const aula::bumper_t* msg) {
  if (!outcome_.truth().accept(channel, *msg)) return;  // forged: counted, not graded
  if (msg->utime <= episode_from_utime_ || !started_) return;
  referee_->onBump(msg->utime, msg->state == aula::bumper_t::PRESSED);
}

void CoverageRefereeNode::onEpisode(const lcm::ReceiveBuffer*, const std::string& channel, const aula::episode_t* msg) {
  if (outcome_.truth().contradictsEpisode(channel, *msg)) return;  // counted, not followed
  if (outcome_.onEpisode(msg->algorithm, msg->fault, msg->non_finite_commands, msg->generation)) {
    // Hot reload: the robot is back at its start; a new 900 s from now.
    referee_ = newReferee(msg->utime);
    episode_from_utime_ = msg->utime;
    pose_messages_ = 0;
    have_pose_ = false;
    started_ = false;
    waiting_pose_.reset();
  }
  if (!started_ && msg->started_utime >= 0) start(msg->started_utime);
  outcome_.announceOnce(finished(), on_finished_);
  status_->tick(msg->utime, status());
}

referee::Report CoverageRefereeNode::report() const {
  const CoverageReferee& r = *referee_;
  const auto& tick = clock_->lastTick();
  referee::Report out;
  out.set("exercise", "vacuum");
  out.set("mark", r.mark());
  out.set("sim_time_s", r.elapsedS());
  out.set("seed", static_cast<long long>(tick.seed));
  out.set("world", world_file_);
  out.set("world_sha256", world_sha256_);
  out.set("finished", r.finished());
  out.set("coverage_percent", r.coveragePercent());
  out.set("rubric", rubric_);
  out.set("measures", std::vector<std::string>{"coverage_percent"});  // the raw measure `aula grade` shows
  out.set("coverage_per_100s", r.coveragePer100s());
  out.set("cleaned_area_m2", r.grid().cleanedPixels() * std::pow(r.grid().transform().resolution_m, 2));
  out.set("floor_area_m2", r.grid().floorAreaM2());
  out.set("bumps", r.bumps());
  out.set("stuck_s", r.stuckS());
  // 50 Hz x the run: fewer means the bus lost messages and the coverage is an underestimate.
  out.set("pose_messages", pose_messages_);
  outcome_.addTo(out);
  return out;
}

std::string CoverageRefereeNode::summary() const {
  const CoverageReferee& r = *referee_;
  char text[512];
  std::snprintf(text, sizeof text,
                "Vacuum cleaner mark: %.2f / 10\n"
                "  coverage %.2f %% of %.1f m2 of floor in %.0f s sim (%s)\n"
                "  bumps %lld, time stuck %.1f s\n",
                r.mark(), r.coveragePercent(), r.grid().floorAreaM2(), r.elapsedS(), scaleText(r.settings()).c_str(),
                r.bumps(), r.stuckS());
  return std::string(text) + outcome_.summary();
}

void CoverageRefereeNode::writePicture(const std::string& png_path) const {
  const CoverageReferee& r = *referee_;
  CoverageRunSummary run;
  run.mark = r.mark();
  run.coverage_percent = r.coveragePercent();
  run.scale = scaleText(r.settings());
  run.elapsed_s = r.elapsedS();
  run.bumps = r.bumps();
  run.have_pose = have_pose_;
  run.x_m = x_m_;
  run.y_m = y_m_;
  run.yaw_rad = yaw_rad_;
  run.robot_radius_m = r.settings().robot_radius_m;
  run.notes = outcome_.pictureNotes(world_file_, static_cast<long long>(clock_->lastTick().seed));
  referee::writePngAtomically(coveragePicture(map_.image, r.grid(), run), png_path);
}

void CoverageRefereeNode::abort(const std::string& reason) {
  outcome_.abort(reason);
  outcome_.announceOnce(finished(), on_finished_);
  status_->send(clock_->simTimeUs(), status());
}

referee::EpisodeStatus CoverageRefereeNode::status() const {
  const CoverageReferee& r = *referee_;
  referee::EpisodeStatus s =
      outcome_.episodeStatus(started_, r.elapsedS(), r.settings().duration_s, r.finished(), "Time's up");
  char line[128];
  std::snprintf(line, sizeof line, "coverage %.2f %%", r.coveragePercent());
  s.summary = line;
  if (s.finished) {
    std::snprintf(line, sizeof line, ", mark %.2f / 10", r.mark());
    s.summary += line;
  }
  return s;
}

}  // namespace aula::vacuum
