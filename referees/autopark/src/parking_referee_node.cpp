#include "parking_referee_node.hpp"

#include <aula/geometry/angles.hpp>
#include <aula/geometry/oriented_box.hpp>
#include <aula/autopark/parking_picture.hpp>
#include <aula/world/occupancy_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace aula::autopark {

ParkingRefereeNode::ParkingRefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                                       const std::optional<auth::Key>& run_key)
    : RefereeNode(bus, cfg, world, run_key, "autopark"),
      world_(world) {
  scene_ = ParkingScene::fromWorld(world, robotName(), sceneNamesOf(cfg));
  settings_ = parkingRefereeSettings(cfg);
  referee_ = std::make_unique<ParkingReferee>(scene_, settings_);
}

void ParkingRefereeNode::onTruePose(const aula::pose3d_t& msg) {
  const bool graded = referee_->started() && !referee_->finished();
  referee_->onPose(msg.utime, msg.x, msg.y, msg.yaw);
  if (graded) trace().onPose(msg.utime, msg.x, msg.y, msg.yaw);
}

void ParkingRefereeNode::onClockTick(int64_t utime) {
  const bool was_finished = referee_->finished();
  referee_->onTick(utime);
  if (referee_->finished() && !was_finished) traceEnd(utime);
}

namespace {

// What the car at (x, y, yaw) touches, as far as the referee can tell (the bumper says only that
// it touches something): the nearest static model of the world, named as the scene knows it.
std::string touched(const world::WorldSpec& world, const ParkingScene& scene, double x_m, double y_m, double yaw_rad) {
  const geometry::OrientedBox car{{x_m, y_m, yaw_rad}, scene.car_length_m, scene.car_width_m};
  double nearest_m = std::numeric_limits<double>::infinity();
  std::string name = "nothing the referee knows of";
  for (const world::StaticObject& object : world.statics) {
    if (object.shape.zRange(object.pose).second < 0.01) continue;  // the ground
    const geometry::OrientedBox footprint = world::footprintOf(object);
    const Eigen::Vector2d at(footprint.centre.x_m, footprint.centre.y_m);
    const double d = geometry::distance(car, footprint);
    if (d >= nearest_m) continue;
    nearest_m = d;
    name = object.name.substr(0, object.name.find("::"));
    if (object.name == scene.curb_name) name = "the curb";
    // A named array, not a braced list of make_pair temporaries (GCC 14's -Wdangling-reference).
    const std::pair<const geometry::OrientedBox*, const char*> neighbours[] = {
        {&scene.rear_car, "the car behind the slot"}, {&scene.front_car, "the car in front of the slot"}};
    for (const auto& [parked, what] : neighbours) {
      if (std::hypot(parked->centre.x_m - at.x(), parked->centre.y_m - at.y()) < 0.05) name = what;
    }
  }
  return name;
}

// What a contact costs, by the rubric's scale (the breakdown's "contacts" row has the total).
std::string contactEffect(long long before, const ParkingRefereeSettings& s) {
  if (s.thesis_scale) return before == 0 ? "the collision term's 2.5 points are lost" : "already lost: no more points off";
  char text[160];
  std::snprintf(text, sizeof text, "costs %.0f %% of the mark, and %.0f %% more a second in contact, %.0f %% a cm deep",
                100 * s.contact_share, 100 * s.contact_share_per_s, 100 * s.contact_share_per_cm);
  return text;
}

}  // namespace

void ParkingRefereeNode::onContact(int64_t utime, bool pressed) {
  const long long before = referee_->collisions();
  const bool counting = referee_->started() && !referee_->finished();
  referee_->onContact(utime, pressed);
  if (!pressed && open_contact_ >= 0 && counting) {
    referee::TraceEvent& e = trace().events()[open_contact_];
    e.duration_s = std::max(0.0, trace().timeS(utime) - e.t_s);
    open_contact_ = -1;
  }
  if (referee_->collisions() > before) {
    char text[128];
    std::snprintf(text, sizeof text, "collision %lld: touching %s", referee_->collisions(), touched(world_, scene_, referee_->x(), referee_->y(), referee_->yawRad()).c_str());
    trace().addEvent(utime, "contact", text, contactEffect(before, referee_->settings()));
    if (before == 0 && referee_->settings().thesis_scale) trace().events().back().points = -2.5;
    open_contact_ = static_cast<long>(trace().events().size()) - 1;
    // Say where, so a student can see which part of the manoeuvre touched something.
    std::fprintf(stderr, "autopark-referee [%.2f s]: collision %lld, car at x %.2f y %.2f yaw %.1f deg\n",
                 referee_->elapsedS(), referee_->collisions(), referee_->x(), referee_->y(),
                 geometry::headingDeg(referee_->yawRad()));
  }
}

void ParkingRefereeNode::startNewEpisode(int64_t) {
  // Hot reload: the car is back at its start; the clock starts again at the next Run.
  referee_ = std::make_unique<ParkingReferee>(scene_, settings_);
  trace().clear();
  open_contact_ = -1;
}

void ParkingRefereeNode::onEpisode(const aula::episode_t& msg) {
  const bool was_started = referee_->started();
  if (msg.started_utime >= 0) referee_->start(msg.started_utime);
  if (referee_->started() && !was_started) {
    trace().start(msg.started_utime);
    if (referee_->hasPose()) trace().onPose(msg.started_utime, referee_->x(), referee_->y(), referee_->yawRad());
    trace().addEvent(msg.started_utime, "start", "Run: the clock starts", "");
  }
}

void ParkingRefereeNode::traceEnd(int64_t utime) {
  const ParkingReferee& r = *referee_;
  const ParkingScores s = r.scores();
  const ParkingMeasures& m = r.measures();
  if (open_contact_ >= 0) {
    // Still touching at the end: it lasted until now (ParkingReferee counted it so).
    referee::TraceEvent& e = trace().events()[open_contact_];
    e.duration_s = std::max(0.0, trace().timeS(utime) - e.t_s);
    open_contact_ = -1;
  }
  // The end, then each row of the mark (the breakdown's), at the moment the clock stopped (the car
  // at rest in the slot), not when the referee was sure.
  const auto rows = parkingMarkTerms(m, r.parkingCase(), r.elapsedS(), r.contacts(), r.settings());
  char text[200];
  std::snprintf(text, sizeof text, "%s after %.1f s", caseText(r.parkingCase()).c_str(), r.elapsedS());
  trace().addEvent(utime, r.parked() ? "parked" : "end", text, "").t_s = r.elapsedS();
  for (const referee::MarkTerm& row : rows) {
    char effect[96];
    if (row.factor >= 0) {
      std::snprintf(effect, sizeof effect, "the mark x %.2f", row.factor);
    } else {
      std::snprintf(effect, sizeof effect, "%.2f of %.3g points", row.points, row.of);
    }
    referee::TraceEvent& e = trace().addEvent(utime, "measure", row.term + ": " + row.measure, effect);
    if (row.factor < 0) e.points = row.points;
    e.t_s = r.elapsedS();  // graded where the car stopped
  }
  std::snprintf(text, sizeof text, "the mark: %s = %.2f", markFormula(s, r.parkingCase(), contactCost(r.contacts(), r.settings()),
                r.settings()).c_str(), s.mark);
  trace().addEvent(utime, "mark", text, "").t_s = r.elapsedS();
  trace().stop(utime);
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

void ParkingRefereeNode::addTrace(referee::Report& out) const {
  const ParkingReferee& r = *referee_;
  out.set("robot", referee::traceBox(scene_.car_length_m, scene_.car_width_m));
  ParkingRunSummary run;  // what the picture's view frames: the slot, the car and its drive
  run.scene = scene_;
  run.have_pose = r.hasPose();
  run.x_m = r.x();
  run.y_m = r.y();
  run.yaw_rad = r.yawRad();
  run.trail = r.trail().points();
  const geometry::MapTransform view = parkingView(run);
  out.set("map", referee::traceMap(world::rasterizeOccupancy(world_, view, 0.01, 100.0), view));
  auto box = [](const geometry::OrientedBox& b) {
    return std::vector<double>{b.centre.x_m, b.centre.y_m, b.centre.yaw_rad, b.length_m, b.width_m};
  };
  const ParkingMeasures& m = r.measures();
  referee::Report state;
  state.set("rear_car", box(scene_.rear_car));
  state.set("front_car", box(scene_.front_car));
  state.set("curb_y_m", scene_.curb_y_m);
  state.set("ideal_pose", std::vector<double>{scene_.ideal_x_m, scene_.ideal_y_m, scene_.ideal_yaw_rad});
  state.set("slot_length_m", scene_.slotLengthM());
  state.set("parked", r.parked());
  state.set("inside_slot", m.inside_slot);
  state.set("gaps_m", std::vector<double>{m.front_gap_m, m.rear_gap_m, m.curb_gap_m});
  state.set("ideal_gap_m", m.ideal_gap_m);
  state.set("yaw_error_deg", m.yaw_error_deg);
  state.set("collisions", r.collisions());
  state.set("contact_time_s", r.contactS());
  out.set("state", state);
  out.setJson("breakdown", referee::breakdownJson(parkingMarkTerms(m, r.parkingCase(), r.elapsedS(), r.contacts(), r.settings())));
}

}  // namespace aula::autopark
