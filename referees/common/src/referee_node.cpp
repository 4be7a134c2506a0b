#include "aula/referee/referee_node.hpp"

#include <aula/config/paths.hpp>
#include <aula/version.hpp>

#include <aula/referee/rubric.hpp>
#include <aula/referee/run_picture.hpp>
#include <aula/settings/tables.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace aula::referee {
namespace {
const char* const kFailedBeforeMoving =
    "0: the student's algorithm failed before the robot moved (algorithm_error says why), whatever the rubric gives a "
    "robot that stayed still";
}  // namespace

RefereeNode::RefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                         const std::optional<auth::Key>& run_key, const std::string& exercise)
    : exercise_(exercise),
      world_file_(std::filesystem::path(world.source_path).filename().string()),
      world_sha256_(world.sha256) {
  const settings::Exercise& names = settings::requireExercise(exercise);
  const std::string& p = names.section;
  component_client_ = names.component;
  outcome_.truth() = TruthGate(run_key);
  rubric_ = rubricReport(cfg, *names.referee_settings, p + ".Referee.Rubric");
  const world::RobotSpec& robot = world::requireRobot(world, cfg.getString(p + ".Robot"));
  robot_name_ = robot.name;
  pose_channel_ = world::channelOf(robot, "pose3d");
  bumper_channel_ = world::channelOf(robot, "bumper");
  bus.subscribe(pose_channel_, &RefereeNode::onPoseMessage, this);
  bus.subscribe(bumper_channel_, &RefereeNode::onBumperMessage, this);
  bus.subscribe(cfg.getString(p + ".Episode.Channel"), &RefereeNode::onEpisodeMessage, this);
  layers_ = std::make_unique<TraceLayers>(bus, cfg, robot, p, trace_);
  status_ = std::make_unique<StatusSender>(bus, cfg.getString(p + ".RefereeStatus.Channel"), exercise);
  const double period_s = cfg.getDouble(p + ".Referee.Period");
  const std::string client = exercise + "-referee";
  std::optional<auth::Key> client_key;  // a graded run's simulator follows only its own run's clients
  if (run_key) client_key = auth::clientKey(*run_key, client);
  clock_ = std::make_unique<lcmbus::LockstepClient>(
      bus, client, static_cast<int64_t>(std::llround(period_s * 1e6)),
      [this](int64_t utime) {
        onClockTick(utime);
        announce(utime);
      },
      client_key);
  clock_->expectWorld(world.sha256, world.source_path);
  clock_->setTickFilter([this](const std::string& channel, const aula::sim_clock_t& tick) {
    return outcome_.truth().acceptTick(channel, tick);
  });
}

RefereeNode::~RefereeNode() = default;

void RefereeNode::deferSensorWakeUps(lcmbus::Bus& bus) const {
  bus.deferWakeUps(pose_channel_);
  bus.deferWakeUps(bumper_channel_);
  layers_->deferWakeUps(bus);
}

void RefereeNode::onPoseMessage(const lcm::ReceiveBuffer*, const std::string& channel, const aula::pose3d_t* msg) {
  if (!outcome_.truth().accept(channel, *msg)) return;  // forged: counted, not graded
  if (msg->utime <= episode_from_utime_) return;
  if (!first_pose_) first_pose_ = *msg;
  moved_ = moved_ || std::hypot(msg->x - first_pose_->x, msg->y - first_pose_->y) > kStillWithinM ||
           std::abs(std::remainder(msg->yaw - first_pose_->yaw, 2 * M_PI)) > kStillWithinRad;
  onTruePose(*msg);
}

void RefereeNode::onBumperMessage(const lcm::ReceiveBuffer*, const std::string& channel, const aula::bumper_t* msg) {
  if (!outcome_.truth().accept(channel, *msg)) return;  // forged: counted, not graded
  if (msg->utime <= episode_from_utime_) return;
  onContact(msg->utime, msg->state == aula::bumper_t::PRESSED);
}

void RefereeNode::onEpisodeMessage(const lcm::ReceiveBuffer*, const std::string& channel, const aula::episode_t* msg) {
  if (outcome_.truth().contradictsEpisode(channel, *msg)) return;  // counted, not followed
  const bool had_fault = !outcome_.fault().empty();
  if (outcome_.onEpisode(msg->algorithm, msg->fault, msg->non_finite_commands, msg->generation, msg->status, msg->not_the_seeds_run)) {
    // Hot reload: the robot is back at its start, and a new episode is graded from scratch.
    episode_from_utime_ = msg->utime;
    end_.reset();
    first_pose_.reset();
    moved_ = false;
    non_finite_event_ = -1;
    startNewEpisode(msg->utime);
  }
  onEpisode(*msg);
  if (!had_fault && !outcome_.fault().empty()) traceFault(msg->utime);
  traceNonFinite(msg->utime);
  announce(msg->utime);
}

void RefereeNode::announceEnd() {
  outcome_.announceOnce(finished(), [this] {
    const EpisodeStatus s = status();
    end_ = EpisodeEnd{gradedTimeS(), gradedMark(), s.finished ? s.ending : "Stopped",
                      outcome_.fault().empty() ? outcome_.aborted() : outcome_.fault()};
    if (on_finished_) on_finished_();
  });
}

std::string RefereeNode::endedAt(const EpisodeEnd& end) {
  char text[96];
  std::snprintf(text, sizeof text, "%s at %.2f s of sim time", end.how.c_str(), end.graded_s);
  return text;
}

std::string RefereeNode::clockText(double elapsed_s) const {
  if (end_) return endedAt(*end_);
  char text[32];
  std::snprintf(text, sizeof text, "%02d:%04.1f", static_cast<int>(elapsed_s) / 60, std::fmod(elapsed_s, 60.0));
  return text;
}

void RefereeNode::traceFault(int64_t utime) {
  trace_.addEvent(utime, "fault", "the student's algorithm failed: " + outcome_.fault(),
                  moved_ ? "grading stops here: the mark is what was earned so far"
                         : "grading stops here, before the robot moved: the mark is 0");
}

void RefereeNode::traceNonFinite(int64_t utime) {
  if (non_finite_event_ >= 0 || outcome_.nonFiniteCommands() <= 0 || !trace_.started()) return;
  trace_.addEvent(utime, "non-finite", "a motor command that is not a finite number (NaN or infinite)",
                  "refused: the robot was sent 0 instead; no points off, but the robot does not move");
  non_finite_event_ = static_cast<long>(trace_.events().size()) - 1;
}

void RefereeNode::algorithmFailed(const std::string& fault) {
  if (!outcome_.fault().empty()) return;
  outcome_.algorithmFailed(fault);
  traceFault(simTimeUs());
}

void RefereeNode::escapeAttempt(const std::string& what) {
  if (outcome_.truth().escapeAttempts().count(what) == 0) {  // traced once per kind: a loop is one event
    trace_.addEvent(simTimeUs(), "tampering", "the algorithm tried to get out of the run: " + what,
                    "it went nowhere: the mark is the true behaviour's; the run is flagged").placed = false;
  }
  outcome_.truth().escapeAttempt(what);
}

EpisodeStatus RefereeNode::statusForWindows() const {
  EpisodeStatus s = status();
  const std::string& why = outcome_.notTheSeedsRun();
  if (!why.empty()) s.summary += (s.summary.empty() ? "" : " - ") + std::string("not its seed's graded run: ") + validUtf8(why);
  return s;
}

void RefereeNode::announce(int64_t utime) {
  announceEnd();
  status_->tick(utime, statusForWindows());
}

std::string RefereeNode::peersGone() {
  const aula::sim_clock_t& tick = clock_->lastTick();
  const bool listed = std::find(tick.clients.begin(), tick.clients.end(), component_client_) != tick.clients.end();
  component_listed_ = component_listed_ || (listed && clock_->instanceLocked());
  if (component_listed_ && !listed) {
    return "the component '" + component_client_ + "' " +
           (tick.ended.empty() ? "left the run" : "is gone; the simulator ended the run: " + tick.ended);
  }
  return clock_->simulatorGone();
}

void RefereeNode::abort(const std::string& reason) {
  if (outcome_.aborted().empty()) {
    trace_.addEvent(simTimeUs(), "aborted", "the run was aborted: " + reason,
                    "grading stops here: the mark is what was earned so far");
  }
  outcome_.abort(reason);
  announceEnd();
  status_->send(simTimeUs(), statusForWindows());
}

Report RefereeNode::report() const {
  Report out;
  out.set("exercise", exercise_);
  out.set("aula_version", kVersion);
  out.set("mark", gradedMark());
  out.set("sim_time_s", gradedTimeS());
  out.set("seed", static_cast<long long>(clock_->lastTick().seed));
  out.set("world", world_file_);
  out.set("world_sha256", world_sha256_);
  out.set("finished", gradedToEnd());
  addGrading(out);
  if (failedBeforeMoving()) out.set("mark_note", std::string(kFailedBeforeMoving));
  out.set("rubric", rubric_);
  out.set("measures", measures());
  outcome_.addTo(out);
  return out;
}

std::string RefereeNode::summary() const {
  const std::string zero = failedBeforeMoving() ? std::string("  the mark is ") + kFailedBeforeMoving + "\n" : "";
  return gradeSummary() + zero + outcome_.summary();
}

void RefereeNode::writePicture(const std::string& png_path) const {
  writePngAtomically(picture(outcome_.pictureNotes(world_file_, static_cast<long long>(clock_->lastTick().seed))), png_path);
}

std::string RefereeNode::traceJson() const {
  Report out;
  out.set("trace", 1LL);
  out.set("exercise", exercise_);
  out.set("world", world_file_);
  out.set("seed", static_cast<long long>(clock_->lastTick().seed));
  out.set("algorithm", outcome_.algorithm());
  out.set("mark", gradedMark());
  out.set("sim_time_s", gradedTimeS());
  addTrace(out);
  RunTrace whole = trace_;
  if (non_finite_event_ >= 0 && non_finite_event_ < static_cast<long>(whole.events().size())) {
    whole.events()[non_finite_event_].text = "motor commands that are not finite numbers (NaN or infinite) from here: " +
                                             std::to_string(outcome_.nonFiniteCommands()) + " in all";
  }
  // What the gate refused or lost, known at the end: flagged at the end.
  const int64_t end_utime = clock_->simTimeUs();
  for (const auto& [channel, count] : outcome_.truth().tampering()) {
    whole.addEvent(end_utime, "tampering", std::to_string(count) + " forged or refused messages on " + channel,
                   "not graded: the mark is the true behaviour's; the run is flagged").placed = false;
  }
  for (const auto& [channel, count] : outcome_.truth().gaps()) {
    whole.addEvent(end_utime, "lost", std::to_string(count) + " messages lost on " + channel,
                   "the referee graded without them").placed = false;
  }
  whole.addTo(out);
  layers_->addTo(out);
  return out.toJson();
}

void RefereeNode::writeTrace(const std::string& json_path) const { config::writeFileAtomically(json_path, traceJson(), "trace"); }

}  // namespace aula::referee
