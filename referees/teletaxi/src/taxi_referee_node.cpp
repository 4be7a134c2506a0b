#include "taxi_referee_node.hpp"

#include <aula/lcm/bus.hpp>
#include <aula/referee/rubric.hpp>
#include <aula/settings/tables.hpp>
#include <aula/teletaxi/taxi_picture.hpp>
#include <cmath>
#include <filesystem>
#include <cstdio>

namespace aula::teletaxi {

TaxiRefereeNode::TaxiRefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                                 const std::optional<auth::Key>& run_key)
    : settings_(taxiRefereeSettings(cfg)), referee_(settings_), world_file_(std::filesystem::path(world.source_path).filename().string()), world_sha256_(world.sha256), world_(world) {
  outcome_.truth() = referee::TruthGate(run_key);
  rubric_ = referee::rubricReport(cfg, settings::tableOf("teletaxi-referee"), "TeleTaxi.Referee.Rubric");
  const auto z_band = cfg.getDoubleList("TeleTaxi.Map.ZBand");
  map_params_ = {cfg.getDouble("TeleTaxi.Map.Resolution"), z_band[0], z_band[1]};
  const world::RobotSpec& robot = world::requireRobot(world, cfg.getString("TeleTaxi.Robot"));
  bus.subscribe(world::channelOf(robot, "pose3d"), &TaxiRefereeNode::onPose, this);
  bus.subscribe(cfg.getString("TeleTaxi.Episode.Channel"), &TaxiRefereeNode::onEpisode, this);
  bus.subscribe(world::channelOf(robot, "bumper"), &TaxiRefereeNode::onBumper, this);
  status_ = std::make_unique<referee::StatusSender>(bus, cfg.getString("TeleTaxi.RefereeStatus.Channel"), "teletaxi");
  const double period_s = cfg.getDouble("TeleTaxi.Referee.Period");
  clock_ = std::make_unique<lcmbus::LockstepClient>(
      bus, "teletaxi-referee", static_cast<int64_t>(std::llround(period_s * 1e6)),
      [this](int64_t utime) { onTick(utime); });
  clock_->expectWorld(world.sha256, world.source_path);
  clock_->setTickFilter([this](const std::string& channel, const aula::sim_clock_t& tick) {
    return outcome_.truth().acceptTick(channel, tick);
  });
}

void TaxiRefereeNode::onPose(const lcm::ReceiveBuffer*, const std::string& channel, const aula::pose3d_t* msg) {
  if (!outcome_.truth().accept(channel, *msg)) return;  // forged: counted, not graded
  if (msg->utime <= episode_from_utime_) return;
  referee_.onPose(msg->utime, msg->x, msg->y, msg->yaw);
}

void TaxiRefereeNode::onEpisode(const lcm::ReceiveBuffer*, const std::string& channel, const aula::episode_t* msg) {
  if (outcome_.truth().contradictsEpisode(channel, *msg)) return;  // counted, not followed
  if (outcome_.onEpisode(msg->algorithm, msg->fault, msg->non_finite_commands, msg->generation)) {
    // Hot reload: the taxi is back at its start; the clock starts again at the next GO!.
    referee_ = TaxiReferee(settings_);
    episode_from_utime_ = msg->utime;
    bumps_ = 0;
    pressed_ = false;
  }
  outcome_.announceOnce(finished(), on_finished_);
  if (msg->goal_set) referee_.setGoal(msg->goal_x, msg->goal_y);
  if (msg->started_utime >= 0) referee_.start(msg->started_utime);
  status_->tick(msg->utime, status());
}

void TaxiRefereeNode::onBumper(const lcm::ReceiveBuffer*, const std::string& channel, const aula::bumper_t* msg) {
  if (!outcome_.truth().accept(channel, *msg)) return;  // forged: counted, not graded
  if (msg->utime <= episode_from_utime_) return;
  const bool pressed = msg->state == aula::bumper_t::PRESSED;
  if (pressed && !pressed_ && referee_.started() && !referee_.finished()) ++bumps_;
  pressed_ = pressed;
}

void TaxiRefereeNode::onTick(int64_t utime) {
  referee_.onTick(utime);
  outcome_.announceOnce(finished(), on_finished_);
  status_->tick(utime, status());
}

referee::EpisodeStatus TaxiRefereeNode::status() const {
  const bool arrived = referee_.finished() && referee_.grade().reached;
  referee::EpisodeStatus s = outcome_.episodeStatus(referee_.started(), referee_.elapsedS(), settings_.timeout_s,
                                                    referee_.finished(), arrived ? "Arrived" : "Time's up");
  char line[192];
  if (s.finished) {
    const TaxiGrade g = referee_.finished() ? referee_.grade() : referee_.provisionalGrade();
    std::snprintf(line, sizeof line, "mark %.2f / 10, %s", g.mark, g.verdict.c_str());
  } else if (referee_.hasGoal() && referee_.hasPose()) {
    std::snprintf(line, sizeof line, "%.1f m to the destination", referee_.distanceToGoalM());
  } else {
    line[0] = '\0';
  }
  s.summary = line;
  return s;
}

aula::referee::Report TaxiRefereeNode::report() const {
  const TaxiGrade g = referee_.finished() ? referee_.grade() : referee_.provisionalGrade();
  const auto& tick = clock_->lastTick();
  aula::referee::Report r;
  r.set("exercise", "teletaxi");
  r.set("mark", g.mark);
  r.set("sim_time_s", simTimeUs() / 1e6);
  r.set("seed", static_cast<long long>(tick.seed));
  r.set("world", world_file_);
  r.set("world_sha256", world_sha256_);
  r.set("finished", referee_.finished());
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
  r.set("verdict", g.verdict);
  r.set("rubric", rubric_);
  // The raw measures `aula grade` shows beside the mark.
  r.set("measures", std::vector<std::string>{"driving_time_s", "final_distance_m", "path_length_m"});
  outcome_.addTo(r);
  return r;
}

std::string TaxiRefereeNode::summary() const {
  const TaxiGrade g = referee_.finished() ? referee_.grade() : referee_.provisionalGrade();
  char text[512];
  std::snprintf(text, sizeof text,
                "TeleTaxi mark: %.2f / 10\n"
                "  %s\n"
                "  base %.1f (distance %.2f m) + 0.2 x speed mark %.2f (%.2f m/s = %.1f km/h over %.1f m in %.1f s sim)\n"
                "  straight distance start -> destination: %.1f m; bumps against walls: %lld\n"
                "  rubric %s: arrival within %.3g m, a speed mark of 10 at %.3g m/s, a distance mark from %.3g m travelled\n",
                g.mark, g.verdict.c_str(), g.base_mark, referee_.distanceToGoalM(), g.speed_mark,
                g.average_speed_mps, g.average_speed_mps * 3.6, referee_.pathLengthM(),
                referee_.elapsedS(), referee_.straightDistanceM(), bumps_, settings_.rubric.c_str(),
                settings_.scale.arrival_radius_m, settings_.scale.reference_speed_mps, settings_.scale.min_travel_m);
  return std::string(text) + outcome_.summary();
}

void TaxiRefereeNode::writePicture(const std::string& png_path) const {
  const TaxiReferee& r = referee_;
  TaxiRunSummary run;
  run.grade = r.finished() ? r.grade() : r.provisionalGrade();
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
  run.notes = outcome_.pictureNotes(world_file_, static_cast<long long>(clock_->lastTick().seed));
  const world::OccupancyMap map = world::occupancyMapOf(world_, map_params_);
  referee::writePngAtomically(taxiPicture(map.image, map.transform, run), png_path);
}

void TaxiRefereeNode::abort(const std::string& reason) {
  outcome_.abort(reason);
  outcome_.announceOnce(finished(), on_finished_);
  status_->send(simTimeUs(), status());
}

}  // namespace aula::teletaxi
