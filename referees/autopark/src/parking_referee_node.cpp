#include "parking_referee_node.hpp"

#include <aula/geometry/angles.hpp>
#include <aula/autopark/parking_picture.hpp>
#include <aula/world/occupancy_map.hpp>

#include <cstdio>

namespace aula::autopark {

ParkingRefereeNode::ParkingRefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                                       const std::optional<auth::Key>& run_key)
    : RefereeNode(bus, cfg, world, run_key, "autopark"),
      world_(world) {
  scene_ = ParkingScene::fromWorld(world, robotName());
  settings_ = parkingRefereeSettings(cfg);
  referee_ = std::make_unique<ParkingReferee>(scene_, settings_);
}

void ParkingRefereeNode::onContact(int64_t utime, bool pressed) {
  const long long before = referee_->collisions();
  referee_->onContact(utime, pressed);
  if (referee_->collisions() > before) {
    // Say where, so a student can see which part of the manoeuvre touched something.
    std::fprintf(stderr, "autopark-referee [%.2f s]: collision %lld, car at x %.2f y %.2f yaw %.1f deg\n",
                 referee_->elapsedS(), referee_->collisions(), referee_->x(), referee_->y(),
                 geometry::headingDeg(referee_->yawRad()));
  }
}

void ParkingRefereeNode::startNewEpisode(int64_t) {
  // Hot reload: the car is back at its start; the clock starts again at the next Run.
  referee_ = std::make_unique<ParkingReferee>(scene_, settings_);
}

void ParkingRefereeNode::onEpisode(const aula::episode_t& msg) {
  if (msg.started_utime >= 0) referee_->start(msg.started_utime);
}

referee::EpisodeStatus ParkingRefereeNode::status() const {
  const ParkingReferee& r = *referee_;
  referee::EpisodeStatus s = outcome().episodeStatus(r.started(), r.elapsedS(), settings_.timeout_s, r.finished(),
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

void ParkingRefereeNode::addGrading(referee::Report& out) const {
  const ParkingReferee& r = *referee_;
  const ParkingScores s = r.scores();
  const ParkingMeasures& m = r.measures();
  out.set("parked", r.parked());
  // Which case it was: parked, parked_elsewhere, drove_off, stayed_still, gave_up.
  out.set("case", std::string(caseName(r.parkingCase())));
  out.set("left_street", r.leftStreet());
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
  out.set("deepest_contact_m", r.deepestContactM());
  out.set("contact_cost", contactCost(r.contacts(), r.settings()));
  out.set("final_pose", std::vector<double>{r.x(), r.y(), r.yawRad()});
  out.set("ideal_pose", std::vector<double>{r.scene().ideal_x_m, r.scene().ideal_y_m, r.scene().ideal_yaw_rad});
  out.set("score_angle", s.angle);
  out.set("score_time", s.time);
  out.set("score_distance", s.distance);
  out.set("score_collision", s.collision);
}

std::string ParkingRefereeNode::gradeSummary() const {
  const ParkingReferee& r = *referee_;
  const ParkingScores s = r.scores();
  const ParkingMeasures& m = r.measures();
  const ParkingRefereeSettings& settings = r.settings();
  const ParkingCase parking_case = r.parkingCase();
  char text[1024];
  std::snprintf(text, sizeof text,
                "Autopark mark: %.2f / 10 = %s\n"
                "  %s after %.1f s sim; %.2f m from the ideal pose, yaw error %.1f deg\n"
                "  gaps: front %.2f m, rear %.2f m (a centred car: %.2f m), curb %.2f m; collisions %lld (%.1f s in contact, "
                "%.1f mm deep)\n"
                "  rubric %s: %s\n",
                s.mark, markFormula(s, parking_case, contactCost(r.contacts(), settings), settings).c_str(),
                caseText(parking_case).c_str(), r.elapsedS(), m.position_error_m, m.yaw_error_deg,
                m.front_gap_m, m.rear_gap_m, m.ideal_gap_m, m.curb_gap_m, r.collisions(), r.contactS(),
                1e3 * r.deepestContactM(), settings.rubric.c_str(), gapRuleText(settings).c_str());
  return text;
}

cv::Mat ParkingRefereeNode::picture(const std::vector<std::string>& notes) const {
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
  run.parking_case = r.parkingCase();
  run.contact_cost = contactCost(r.contacts(), r.settings());
  run.have_pose = r.hasPose();
  run.x_m = r.x();
  run.y_m = r.y();
  run.yaw_rad = r.yawRad();
  run.trail = r.trail().points();
  run.notes = notes;
  const geometry::MapTransform view = parkingView(run);
  // Everything a car can touch, kerbs included (the ground plane is not drawn).
  const cv::Mat street = world::rasterizeOccupancy(world_, view, 0.01, 100.0);
  return parkingPicture(street, view, run);
}

}  // namespace aula::autopark
