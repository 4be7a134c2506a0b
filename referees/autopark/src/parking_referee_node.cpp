#include "parking_referee_node.hpp"

#include <aula/geometry/angles.hpp>
#include <aula/autopark/parking_picture.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/referee/rubric.hpp>
#include <aula/settings/tables.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include <cmath>
#include <filesystem>
#include <cstdio>

namespace aula::autopark {

ParkingRefereeNode::ParkingRefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                                       const std::optional<auth::Key>& run_key)
    : world_file_(std::filesystem::path(world.source_path).filename().string()), world_sha256_(world.sha256), world_(world) {
  outcome_.truth() = referee::TruthGate(run_key);
  const world::RobotSpec& car = world::requireRobot(world, cfg.getString("Autopark.Robot"));
  scene_ = ParkingScene::fromWorld(world, car.name);
  settings_ = parkingRefereeSettings(cfg);
  rubric_ = referee::rubricReport(cfg, settings::tableOf("autopark-referee"), "Autopark.Referee.Rubric");
  referee_ = std::make_unique<ParkingReferee>(scene_, settings_);
  bus.subscribe(world::channelOf(car, "pose3d"), &ParkingRefereeNode::onPose, this);
  bus.subscribe(world::channelOf(car, "bumper"), &ParkingRefereeNode::onBumper, this);
  bus.subscribe(cfg.getString("Autopark.Episode.Channel"), &ParkingRefereeNode::onEpisode, this);
  status_ = std::make_unique<referee::StatusSender>(bus, cfg.getString("Autopark.RefereeStatus.Channel"), "autopark");
  const double period_s = cfg.getDouble("Autopark.Referee.Period");
  clock_ = std::make_unique<lcmbus::LockstepClient>(bus, "autopark-referee", static_cast<int64_t>(std::llround(period_s * 1e6)),
                                                    [this](int64_t utime) { onTick(utime); });
  clock_->expectWorld(world.sha256, world.source_path);
  clock_->setTickFilter([this](const std::string& channel, const aula::sim_clock_t& tick) {
    return outcome_.truth().acceptTick(channel, tick);
  });
}

void ParkingRefereeNode::onPose(const lcm::ReceiveBuffer*, const std::string& channel, const aula::pose3d_t* msg) {
  if (!outcome_.truth().accept(channel, *msg)) return;  // forged: counted, not graded
  if (msg->utime <= episode_from_utime_) return;
  referee_->onPose(msg->utime, msg->x, msg->y, msg->yaw);
}

void ParkingRefereeNode::onBumper(const lcm::ReceiveBuffer*, const std::string& channel, const aula::bumper_t* msg) {
  if (!outcome_.truth().accept(channel, *msg)) return;  // forged: counted, not graded
  if (msg->utime <= episode_from_utime_) return;
  const long long before = referee_->collisions();
  referee_->onContact(msg->utime, msg->state == aula::bumper_t::PRESSED);
  if (referee_->collisions() > before) {
    // Say where, so a student can see which part of the manoeuvre touched something.
    std::fprintf(stderr, "autopark-referee [%.2f s]: collision %lld, car at x %.2f y %.2f yaw %.1f deg\n",
                 referee_->elapsedS(), referee_->collisions(), referee_->x(), referee_->y(),
                 geometry::headingDeg(referee_->yawRad()));
  }
}

void ParkingRefereeNode::onEpisode(const lcm::ReceiveBuffer*, const std::string& channel, const aula::episode_t* msg) {
  if (outcome_.truth().contradictsEpisode(channel, *msg)) return;  // counted, not followed
  if (outcome_.onEpisode(msg->algorithm, msg->fault, msg->non_finite_commands, msg->generation)) {
    // Hot reload: the car is back at its start; the clock starts again at the next Run.
    referee_ = std::make_unique<ParkingReferee>(scene_, settings_);
    episode_from_utime_ = msg->utime;
  }
  outcome_.announceOnce(finished(), on_finished_);
  if (msg->started_utime >= 0) referee_->start(msg->started_utime);
  status_->tick(msg->utime, status());
}

void ParkingRefereeNode::onTick(int64_t utime) {
  referee_->onTick(utime);
  outcome_.announceOnce(finished(), on_finished_);
  status_->tick(utime, status());
}

referee::EpisodeStatus ParkingRefereeNode::status() const {
  const ParkingReferee& r = *referee_;
  referee::EpisodeStatus s = outcome_.episodeStatus(r.started(), r.elapsedS(), settings_.timeout_s, r.finished(),
                                                    r.parked() ? "Parked" : "Time's up");
  char line[160];
  std::snprintf(line, sizeof line, "%.2f m from the ideal pose, collisions %lld", r.measures().position_error_m,
                r.collisions());
  s.summary = line;
  if (s.finished) {
    std::snprintf(line, sizeof line, ", mark %.2f / 10", r.scores().mark);
    s.summary += line;
  }
  return s;
}

aula::referee::Report ParkingRefereeNode::report() const {
  const ParkingReferee& r = *referee_;
  const ParkingScores s = r.scores();
  const ParkingMeasures& m = r.measures();
  const auto& tick = clock_->lastTick();
  aula::referee::Report out;
  out.set("exercise", "autopark");
  out.set("mark", s.mark);
  out.set("sim_time_s", clock_->simTimeUs() / 1e6);
  out.set("seed", static_cast<long long>(tick.seed));
  out.set("world", world_file_);
  out.set("world_sha256", world_sha256_);
  out.set("finished", r.finished());
  out.set("parked", r.parked());
  out.set("park_time_s", r.elapsedS());
  out.set("front_gap_m", m.front_gap_m);
  out.set("rear_gap_m", m.rear_gap_m);
  out.set("curb_gap_m", m.curb_gap_m);
  out.set("yaw_error_deg", m.yaw_error_deg);
  out.set("position_error_m", m.position_error_m);
  out.set("slot_length_m", r.scene().slotLengthM());
  out.set("ideal_gap_m", m.ideal_gap_m);
  out.set("collisions", r.collisions());
  out.set("contact_time_s", r.contactS());
  out.set("final_pose", std::vector<double>{r.x(), r.y(), r.yawRad()});
  out.set("ideal_pose", std::vector<double>{r.scene().ideal_x_m, r.scene().ideal_y_m, r.scene().ideal_yaw_rad});
  out.set("score_angle", s.angle);
  out.set("score_time", s.time);
  out.set("score_distance", s.distance);
  out.set("score_collision", s.collision);
  out.set("rubric", rubric_);
  // The raw measures `aula grade` shows beside the mark.
  out.set("measures", std::vector<std::string>{"park_time_s", "front_gap_m", "rear_gap_m", "curb_gap_m"});
  outcome_.addTo(out);
  return out;
}

std::string ParkingRefereeNode::summary() const {
  const ParkingReferee& r = *referee_;
  const ParkingScores s = r.scores();
  const ParkingMeasures& m = r.measures();
  char text[768];
  std::snprintf(text, sizeof text,
                "Autopark mark: %.2f / 10 = 0.025 x (angle %.0f + time %.0f + distances %.1f + collisions %.0f)\n"
                "  %s after %.1f s sim; %.2f m from the ideal pose, yaw error %.1f deg\n"
                "  gaps: front %.2f m, rear %.2f m (a centred car: %.2f m), curb %.2f m; collisions %lld (%.1f s in contact)\n"
                "  rubric %s: %s\n",
                s.mark, s.angle, s.time, s.distance, s.collision, r.parked() ? "parked" : "NOT parked", r.elapsedS(),
                m.position_error_m, m.yaw_error_deg, m.front_gap_m, m.rear_gap_m, m.ideal_gap_m, m.curb_gap_m, r.collisions(),
                r.contactS(), r.settings().rubric.c_str(), gapRuleText(r.settings()).c_str());
  return std::string(text) + outcome_.summary();
}

void ParkingRefereeNode::writePicture(const std::string& png_path) const {
  const ParkingReferee& r = *referee_;
  ParkingRunSummary run;
  run.scene = r.scene();
  run.settings = r.settings();
  run.measures = r.measures();
  run.scores = r.scores();
  run.finished = r.finished();
  run.parked = r.parked();
  run.park_time_s = r.elapsedS();
  run.collisions = r.collisions();
  run.have_pose = r.hasPose();
  run.x_m = r.x();
  run.y_m = r.y();
  run.yaw_rad = r.yawRad();
  run.trail = r.trail().points();
  run.notes = outcome_.pictureNotes(world_file_, static_cast<long long>(clock_->lastTick().seed));
  const geometry::MapTransform view = parkingView(run);
  // Everything a car can touch, kerbs included (the ground plane is not drawn).
  const cv::Mat street = world::rasterizeOccupancy(world_, view, 0.01, 100.0);
  referee::writePngAtomically(parkingPicture(street, view, run), png_path);
}

void ParkingRefereeNode::abort(const std::string& reason) {
  outcome_.abort(reason);
  outcome_.announceOnce(finished(), on_finished_);
  status_->send(clock_->simTimeUs(), status());
}

}  // namespace aula::autopark
