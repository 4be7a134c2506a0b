#include "coverage_referee_node.hpp"

#include <aula/vacuum/coverage_picture.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace aula::vacuum {

CoverageRefereeNode::CoverageRefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                                         const std::optional<auth::Key>& run_key)
    : RefereeNode(bus, cfg, world, run_key, "vacuum") {
  settings_ = coverageSettings(cfg);
  const auto z_band = cfg.getDoubleList("Vacuum.Map.ZBand");
  map_ = world::occupancyMapOf(world, {cfg.getDouble("Vacuum.Map.Resolution"), z_band[0], z_band[1]});
  // The floor is the free space reachable from where the robot starts in the world.
  const world::RobotSpec& robot = world::requireRobot(world, robotName());
  const Eigen::Vector3d start = robot.pose.translation();
  start_x_m_ = start.x();
  start_y_m_ = start.y();
  try {
    referee_ = newReferee(0);
  } catch (const std::exception& e) {
    throw world::WorldError(world.source_path + ": robot '" + robot.name + "' starts at (" + std::to_string(start.x()) +
                            ", " + std::to_string(start.y()) + "), which is not on the floor of the map (" + e.what() + ")");
  }
}

std::unique_ptr<CoverageReferee> CoverageRefereeNode::newReferee(int64_t origin_utime) const {
  return std::make_unique<CoverageReferee>(CoverageGrid(map_.image, map_.transform, start_x_m_, start_y_m_), settings_,
                                           origin_utime);
}

void CoverageRefereeNode::start(int64_t utime) {
  // The episode's 900 s count from "Run my algorithm" (at once when headless: sim time 0).
  referee_ = newReferee(utime);
  started_ = true;
  trace().start(utime);
  cells_ = std::make_unique<CleanedCellsTrace>(referee_->grid(), settings_.robot_radius_m);
  thresholds_passed_ = 0;
  if (waiting_pose_ && waiting_pose_->utime >= utime) {
    referee_->onPose(waiting_pose_->utime, waiting_pose_->x_m, waiting_pose_->y_m);
    cells_->touched(waiting_pose_->x_m, waiting_pose_->y_m);
    for (int n = trace().onPose(waiting_pose_->utime, waiting_pose_->x_m, waiting_pose_->y_m, waiting_pose_->yaw_rad); n > 0; --n) {
      cells_->sample();
    }
  }
  waiting_pose_.reset();
}

void CoverageRefereeNode::onTruePose(const aula::pose3d_t& msg) {
  ++pose_messages_;
  if (!started_) {
    // Before Run nothing is graded (teleoperation is free); the pose at the start is kept.
    waiting_pose_ = {msg.utime, msg.x, msg.y, msg.yaw};
    if (on_pose_) on_pose_(msg.x, msg.y, msg.yaw);
    return;
  }
  const double stuck_before_s = referee_->stuckS();
  referee_->onPose(msg.utime, msg.x, msg.y);
  if (!referee_->finished()) {
    cells_->touched(msg.x, msg.y);
    for (int n = trace().onPose(msg.utime, msg.x, msg.y, msg.yaw); n > 0; --n) cells_->sample();
    traceProgress(msg.utime, stuck_before_s);
    have_pose_ = true;
    x_m_ = msg.x;
    y_m_ = msg.y;
    yaw_rad_ = msg.yaw;
  }
  if (on_pose_) on_pose_(msg.x, msg.y, msg.yaw);
}

void CoverageRefereeNode::onContact(int64_t utime, bool pressed) {
  if (!started_) return;
  const long long before = referee_->bumps();
  referee_->onBump(utime, pressed);
  if (referee_->bumps() > before) {
    trace().addEvent(utime, "bump", "bump " + std::to_string(referee_->bumps()),
                     "no points off: the mark counts only the floor cleaned, but a bump costs time");
  }
}

void CoverageRefereeNode::traceProgress(int64_t utime, double stuck_before_s) {
  const CoverageReferee& r = *referee_;
  char text[160];
  const double stuck_s = r.stuckS() - stuck_before_s;
  if (stuck_s > 0) {
    // Consecutive windows are one stretch stuck.
    auto& events = trace().events();
    const double from_s = trace().timeS(utime) - stuck_s;
    if (!events.empty() && events.back().kind == "stuck" &&
        std::abs(events.back().t_s + events.back().duration_s - from_s) < 1e-6) {
      events.back().duration_s += stuck_s;
    } else {
      referee::TraceEvent& e = trace().addEvent(utime, "stuck", "stuck", "time that cleaned nothing new");
      e.t_s = from_s;
      e.duration_s = stuck_s;
    }
    std::snprintf(text, sizeof text, "stuck for %.0f s (moved under %.0f cm in each %.0f s)", trace().events().back().duration_s,
                  r.settings().stuck_distance_m * 100, r.settings().stuck_window_s);
    trace().events().back().text = text;
  }
  const double thresholds[2] = {r.settings().half_mark_coverage_percent, r.settings().full_mark_coverage_percent};
  while (thresholds_passed_ < 2 && r.coveragePercent() >= thresholds[thresholds_passed_]) {
    std::snprintf(text, sizeof text, "coverage %.4g %%", thresholds[thresholds_passed_]);
    referee::TraceEvent& e = trace().addEvent(utime, "mark", text, thresholds_passed_ == 0 ? "5 of 10 points" : "10 of 10 points");
    e.points = 5;
    ++thresholds_passed_;
  }
}

void CoverageRefereeNode::startNewEpisode(int64_t utime) {
  // Hot reload: the robot is back at its start; a new 900 s from its Run.
  referee_ = newReferee(utime);
  trace().clear();
  cells_.reset();
  pose_messages_ = 0;
  have_pose_ = false;
  started_ = false;
  waiting_pose_.reset();
}

void CoverageRefereeNode::onEpisode(const aula::episode_t& msg) {
  if (!started_ && msg.started_utime >= 0) start(msg.started_utime);
}

void CoverageRefereeNode::onClockTick(int64_t utime) {
  if (!started_) return;
  const bool was_finished = referee_->finished();
  referee_->onTick(utime);  // the episode's clock runs from Run
  if (referee_->finished() && !was_finished) {
    char text[96], effect[32];
    std::snprintf(text, sizeof text, "time's up: coverage %.2f %% in %.0f s", referee_->coveragePercent(), referee_->elapsedS());
    std::snprintf(effect, sizeof effect, "mark %.2f / 10", referee_->mark());
    trace().addEvent(utime, "end", text, effect);
    trace().stop(utime);
  }
}

void CoverageRefereeNode::addGrading(referee::Report& out) const {
  const CoverageReferee& r = *referee_;
  out.set("coverage_percent", r.coveragePercent());
  out.set("coverage_per_100s", r.coveragePer100s());
  out.set("cleaned_area_m2", r.grid().cleanedPixels() * std::pow(r.grid().transform().resolution_m, 2));
  out.set("floor_area_m2", r.grid().floorAreaM2());
  out.set("bumps", r.bumps());
  out.set("stuck_s", r.stuckS());
  out.set("stuck_at_end_s", r.stuckAtEndS());
  out.set("wedged", r.wedged());
  out.set("final_pose", std::vector<double>{x_m_, y_m_, yaw_rad_});
  // 50 Hz x the run: fewer means the bus lost messages and the coverage is an underestimate.
  out.set("pose_messages", pose_messages_);
}

std::string CoverageRefereeNode::gradeSummary() const {
  const CoverageReferee& r = *referee_;
  char text[512];
  std::snprintf(text, sizeof text,
                "Vacuum cleaner mark: %.2f / 10\n"
                "  coverage %.2f %% of %.1f m2 of floor in %.0f s sim (%s)\n"
                "  bumps %lld, time stuck %.1f s\n",
                r.mark(), r.coveragePercent(), r.grid().floorAreaM2(), r.elapsedS(), scaleText(r.settings()).c_str(),
                r.bumps(), r.stuckS());
  return text;
}

cv::Mat CoverageRefereeNode::picture(const std::vector<std::string>& notes) const {
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
  run.notes = notes;
  return coveragePicture(map_.image, r.grid(), run);
}

void CoverageRefereeNode::addTrace(referee::Report& out) const {
  const CoverageReferee& r = *referee_;
  out.set("robot", referee::traceDisc(r.settings().robot_radius_m));
  out.set("map", referee::traceMap(map_.image, map_.transform));
  referee::Report state;
  state.set("floor_area_m2", r.grid().floorAreaM2());
  state.set("cell_px", static_cast<long long>(cells_ ? cells_->cellPx() : 1));
  state.set("cells_cleaned", cells_ ? cells_->cellsCleaned() : 0LL);
  state.set("cells", cells_ ? cells_->cells() : std::string());
  state.setJson("coverage_cp", referee::deltaArray(cells_ ? cells_->coverageCentiPercent() : std::vector<int64_t>{}));
  state.set("coverage_percent", r.coveragePercent());
  state.set("bumps", r.bumps());
  state.set("stuck_s", r.stuckS());
  out.set("state", state);
  char measure[96];
  std::snprintf(measure, sizeof measure, "%.2f %% of the floor (a 5 at %.4g %%, a 10 at %.4g %%)", r.coveragePercent(),
                r.settings().half_mark_coverage_percent, r.settings().full_mark_coverage_percent);
  out.setJson("breakdown", referee::breakdownJson({{"coverage", measure, r.mark(), 10.0}}));
}

referee::EpisodeStatus CoverageRefereeNode::status() const {
  const CoverageReferee& r = *referee_;
  referee::EpisodeStatus s =
      outcome().episodeStatus(started_, r.elapsedS(), r.settings().duration_s, r.finished(), "Time's up");
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
