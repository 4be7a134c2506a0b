#include "taxi_referee_node.hpp"

#include <aula/teletaxi/taxi_picture.hpp>

#include <cstdio>

namespace aula::teletaxi {

TaxiRefereeNode::TaxiRefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                                 const std::optional<auth::Key>& run_key)
    : RefereeNode(bus, cfg, world, run_key, "teletaxi"),
      settings_(taxiRefereeSettings(cfg)),
      referee_(settings_),
      world_(world) {
  const auto z_band = cfg.getDoubleList("TeleTaxi.Map.ZBand");
  map_params_ = {cfg.getDouble("TeleTaxi.Map.Resolution"), z_band[0], z_band[1]};
}

void TaxiRefereeNode::onTruePose(const aula::pose3d_t& msg) {
  const bool graded = referee_.started() && !referee_.finished();
  referee_.onPose(msg.utime, msg.x, msg.y, msg.yaw);
  if (graded) trace().onPose(msg.utime, msg.x, msg.y, msg.yaw);
}

void TaxiRefereeNode::onContact(int64_t utime, bool pressed) {
  if (pressed && !pressed_ && referee_.started() && !referee_.finished()) {
    ++bumps_;
    trace().addEvent(utime, "bump", "bump " + std::to_string(bumps_) + " against a wall",
                     "no points off: the mark counts arrival and speed, but a bump costs time");
  }
  pressed_ = pressed;
}

void TaxiRefereeNode::onClockTick(int64_t utime) {
  const bool was_finished = referee_.finished();
  referee_.onTick(utime);
  if (!referee_.finished() || was_finished) return;
  const TaxiGrade& g = referee_.grade();
  char effect[96];
  if (g.reached) {
    std::snprintf(effect, sizeof effect, "base %.1f + 0.2 x speed mark %.2f = %.2f", g.base_mark, g.speed_mark, g.mark);
  } else {
    std::snprintf(effect, sizeof effect, "mark 0: %.1f m left to the destination", referee_.distanceToGoalM());
  }
  // At the moment the referee's clock stopped (the taxi at rest), not when it was sure of it.
  trace().addEvent(utime, g.reached ? "arrival" : "end", g.verdict, effect).t_s = referee_.elapsedS();
  trace().stop(utime);
}

void TaxiRefereeNode::startNewEpisode(int64_t) {
  // Hot reload: the taxi is back at its start; the clock starts again at the next GO!.
  referee_ = TaxiReferee(settings_);
  trace().clear();
  bumps_ = 0;
  pressed_ = false;
}

void TaxiRefereeNode::onEpisode(const aula::episode_t& msg) {
  if (msg.goal_set) referee_.setGoal(msg.goal_x, msg.goal_y);
  const bool was_started = referee_.started();
  if (msg.started_utime >= 0) referee_.start(msg.started_utime);
  if (referee_.started() && !was_started) {
    // The trace is the graded drive: from GO!, where the taxi stood.
    trace().start(msg.started_utime);
    start_x_m_ = referee_.x();
    start_y_m_ = referee_.y();
    if (referee_.hasPose()) trace().onPose(msg.started_utime, referee_.x(), referee_.y(), referee_.yawRad());
    char text[96];
    std::snprintf(text, sizeof text, "GO! to (%.1f, %.1f), %.1f m away", referee_.goalX(), referee_.goalY(),
                  referee_.straightDistanceM());
    trace().addEvent(msg.started_utime, "start", text, "the clock starts");
  }
}

referee::EpisodeStatus TaxiRefereeNode::status() const {
  const bool arrived = referee_.finished() && referee_.grade().reached;
  referee::EpisodeStatus s = outcome().episodeStatus(referee_.started(), referee_.elapsedS(), settings_.timeout_s,
                                                    referee_.finished(), arrived ? "Arrived" : "Time's up");
  char line[192];
  if (s.finished) {
    const TaxiGrade g = grade();
    std::snprintf(line, sizeof line, "mark %.2f / 10, %s", g.mark, g.verdict.c_str());
  } else if (referee_.hasGoal() && referee_.hasPose()) {
    std::snprintf(line, sizeof line, "%.1f m to the destination", referee_.distanceToGoalM());
  } else {
    line[0] = '\0';
  }
  s.summary = line;
  return s;
}

void TaxiRefereeNode::addGrading(referee::Report& r) const {
  const TaxiGrade g = grade();
  r.set("reached", g.reached);
  r.set("final_distance_m", referee_.distanceToGoalM());
  r.set("path_length_m", referee_.pathLengthM());
  r.set("straight_distance_m", referee_.straightDistanceM());
  r.set("driving_time_s", referee_.elapsedS());
  r.set("average_speed_mps", g.average_speed_mps);
  r.set("base_mark", g.base_mark);
  r.set("speed_mark", g.speed_mark);
  r.set("bumps", bumps_);
  r.set("destination_m", std::vector<double>{referee_.goalX(), referee_.goalY()});
  r.set("final_pose", std::vector<double>{referee_.x(), referee_.y(), referee_.yawRad()});
  r.set("verdict", g.verdict);
}

std::string TaxiRefereeNode::gradeSummary() const {
  const TaxiGrade g = grade();
  char scale[64];  // the speed scale: a world's calibrated time, or the fixed speed
  if (settings_.scale.full_mark_time_s > 0) {
    std::snprintf(scale, sizeof scale, "in %.3g s (calibrated)", settings_.scale.full_mark_time_s);
  } else {
    std::snprintf(scale, sizeof scale, "at %.3g m/s", settings_.scale.reference_speed_mps);
  }
  char text[512];
  std::snprintf(text, sizeof text,
                "TeleTaxi mark: %.2f / 10\n"
                "  %s\n"
                "  base %.1f (distance %.2f m) + 0.2 x speed mark %.2f (%.2f m/s = %.1f km/h over %.1f m in %.1f s sim)\n"
                "  straight distance start -> destination: %.1f m; bumps against walls: %lld\n"
                "  rubric %s: arrival within %.3g m, a speed mark of 10 %s, a distance mark from %.3g m travelled\n",
                g.mark, g.verdict.c_str(), g.base_mark, referee_.distanceToGoalM(), g.speed_mark,
                g.average_speed_mps, g.average_speed_mps * 3.6, referee_.pathLengthM(),
                referee_.elapsedS(), referee_.straightDistanceM(), bumps_, settings_.rubric.c_str(),
                settings_.scale.arrival_radius_m, scale, settings_.scale.min_travel_m);
  return text;
}

cv::Mat TaxiRefereeNode::picture(const std::vector<std::string>& notes) const {
  const TaxiReferee& r = referee_;
  TaxiRunSummary run;
  run.grade = grade();
  run.finished = r.finished();
  run.driving_time_s = r.elapsedS();
  run.path_length_m = r.pathLengthM();
  run.straight_distance_m = r.straightDistanceM();
  run.have_goal = r.hasGoal();
  run.goal_x_m = r.goalX();
  run.goal_y_m = r.goalY();
  run.arrival_radius_m = r.settings().scale.arrival_radius_m;
  run.have_pose = r.hasPose();
  run.x_m = r.x();
  run.y_m = r.y();
  run.yaw_rad = r.yawRad();
  run.path = r.trail().points();
  run.bumps = bumps_;
  run.notes = notes;
  const world::OccupancyMap map = world::occupancyMapOf(world_, map_params_);
  return taxiPicture(map.image, map.transform, run);
}

void TaxiRefereeNode::addTrace(referee::Report& out) const {
  const world::RobotSpec* robot = world_.findRobot(robotName());
  if (robot != nullptr && robot->shape.kind == world::ShapeKind::Box) {
    out.set("robot", referee::traceBox(robot->shape.box_size_m.x(), robot->shape.box_size_m.y()));
  } else {
    out.set("robot", referee::traceDisc(robot != nullptr ? robot->shape.radius_m : 1.0));
  }
  const world::OccupancyMap map = world::occupancyMapOf(world_, map_params_);
  out.set("map", referee::traceMap(map.image, map.transform));
  // The referee hears the destination, not the component's planned path: the drive is the trail.
  referee::Report state;
  state.set("destination_m", std::vector<double>{referee_.goalX(), referee_.goalY()});
  state.set("arrival_radius_m", settings_.scale.arrival_radius_m);
  state.set("start_m", std::vector<double>{start_x_m_, start_y_m_});
  state.set("straight_distance_m", referee_.straightDistanceM());
  state.set("path_length_m", referee_.pathLengthM());
  state.set("final_distance_m", referee_.distanceToGoalM());
  state.set("bumps", bumps_);
  out.set("state", state);
  const TaxiGrade g = grade();
  char distance[96], speed[96];
  std::snprintf(distance, sizeof distance, "%s %.2f m from the destination (8 within 2 m, 7.5 within 4, 7 within %.3g)",
                g.reached ? "stopped" : "not reached:", referee_.distanceToGoalM(), settings_.scale.arrival_radius_m);
  if (settings_.scale.full_mark_time_s > 0) {
    std::snprintf(speed, sizeof speed, "%.1f s driving (10 in %.3g s, the reference's time)", referee_.elapsedS(),
                  settings_.scale.full_mark_time_s);
  } else {
    std::snprintf(speed, sizeof speed, "%.2f m/s average over %.1f m (10 at %.3g m/s)", g.average_speed_mps,
                  referee_.pathLengthM(), settings_.scale.reference_speed_mps);
  }
  // mark = min(10, base + 0.2 x speed mark): with base <= 8 and the speed mark <= 10 the sum is the mark.
  out.setJson("breakdown", referee::breakdownJson({{"arrival", distance, g.base_mark, 8.0},
                                                   {"speed", speed, 0.2 * g.speed_mark, 2.0}}));
}

}  // namespace aula::teletaxi
