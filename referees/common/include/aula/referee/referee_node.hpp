#pragma once
// What every referee process is, whatever its exercise: it hears the truth the simulator
// asserts (the robot's pose and bumper, signed in a graded run), the component's episode
// messages and the clock, in lockstep; it tells the windows the episode's status; and at the end
// it writes the report (its header, the exercise's grading, the rubric, the run's outcome), the
// printed summary and the picture. An exercise derives from it and says how it grades (the
// hooks below). The settings it reads are the same keys under every exercise's prefix: Robot,
// Episode.Channel, RefereeStatus.Channel, Referee.Period and Referee.Rubric.

#include <aula/auth/run_key.hpp>
#include <aula/bumper_t.hpp>
#include <aula/config/config.hpp>
#include <aula/episode_t.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/lcm/lockstep_client.hpp>
#include <aula/pose3d_t.hpp>
#include <aula/referee/report.hpp>
#include <aula/referee/run_outcome.hpp>
#include <aula/referee/run_trace.hpp>
#include <aula/referee/status_sender.hpp>
#include <aula/referee/trace_layers.hpp>
#include <aula/world/world_spec.hpp>

#include <opencv2/core.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace aula::referee {

class RefereeNode {
 public:
  virtual ~RefereeNode();
  RefereeNode(const RefereeNode&) = delete;
  RefereeNode& operator=(const RefereeNode&) = delete;

  // Graded to the end of the episode, or ended early (a fault, an abort).
  bool finished() const { return gradedToEnd() || outcome_.ended(); }
  bool endedEarly() const { return outcome_.ended(); }
  // The launcher says the run cannot go on (a process died...): grade what there is, and end.
  void abort(const std::string& reason);
  // The launcher tells the algorithm's fault the component could not (it crashed: the line).
  void algorithmFailed(const std::string& fault);
  // The launcher's "escape WHAT": the student's code tried to get out of the run (TruthGate's
  // escapeAttempt). Not graded; counted, traced once per kind, and the run is flagged.
  void escapeAttempt(const std::string& what);
  bool aborted() const { return !outcome_.aborted().empty(); }
  // The student's algorithm failed (at its import, its first call, or later) before the robot
  // moved: the run earns 0, whatever the exercise's rubric gives a robot that stayed still
  // (Autopark's NotParkedMark). The report's mark and the window's end say so.
  bool failedBeforeMoving() const { return !outcome_.fault().empty() && !moved_; }
  // The run's mark: the exercise's (mark()), or 0 when failedBeforeMoving().
  double gradedMark() const { return failedBeforeMoving() ? 0.0 : mark(); }
  Report report() const;
  std::string summary() const;  // for the terminal: the exercise's, and how the run ended
  void writePicture(const std::string& png_path) const;                        // --picture
  // --trace: the run as the referee graded it, for the player (aula/referee/run_trace.hpp).
  std::string traceJson() const;
  void writeTrace(const std::string& json_path) const;
  void poll() { clock_->poll(); }
  // Alone (three terminals, no launcher): why the run cannot go on, or "". The component, once
  // listed in the simulator's ticks, is no longer (it left, or its process ended and the
  // simulator ended the run), or the simulator is gone (LockstepClient::simulatorGone).
  std::string peersGone();
  // Headless: the simulator's truth (pose, bumper) no longer wakes this process at every tick; it
  // is read, in order, when the referee's own tick (or anything else) wakes it (Bus::deferWakeUps).
  void deferSensorWakeUps(lcmbus::Bus& bus) const;
  // A headless run without --trace: what only the trace's layers read (the lasers, the belief,
  // the plans, the printed lines) is not read at all (a vacuum run's 18,000 scans).
  void leaveOutTraceLayers(lcmbus::Bus& bus) { layers_->leave(bus); }
  void leave() { clock_->leave(); }
  int64_t simTimeUs() const { return clock_->simTimeUs(); }
  int episode() const { return outcome_.generation(); }  // counts hot reloads
  void setOnFinished(std::function<void()> hook) { on_finished_ = std::move(hook); }
  // What the windows are told (referee_status_t): the time left, and how the episode ended.
  virtual EpisodeStatus status() const = 0;
  // status() as the windows get it: with why the run is not its seed's graded run, when it is not.
  EpisodeStatus statusForWindows() const;
  // The current episode's end as the referee's window shows it, kept as it was when the episode
  // ended (graded to its end, or stopped by a fault or an abort: the grading stopped there, the
  // simulator did not): the sim time graded, the final mark (the report's) and how it ended.
  struct EpisodeEnd {
    double graded_s = 0;
    double mark = 0;
    std::string how;  // "Time's up", "Arrived", "Parked", "Stopped"
    std::string why;  // for "Stopped": the fault or the abort
  };
  // nullopt while the episode runs (a hot reload starts a new one: nullopt again).
  const std::optional<EpisodeEnd>& episodeEnd() const { return end_; }
  // The window's line for it: "Stopped at 19.62 s of sim time", "Time's up at 900.00 s of sim time".
  static std::string endedAt(const EpisodeEnd& end);
  // A window's episode clock: "01:05.3" of `elapsed_s` while it runs, endedAt once it ended.
  std::string clockText(double elapsed_s) const;

 protected:
  // `exercise`: its name in the settings' table of exercises ("vacuum"), which gives the keys'
  // section ("Vacuum") and the referee program's settings table; the lockstep client is
  // "<exercise>-referee". `run_key`: a graded run's key (--key-fd): only the truth the simulator
  // signed is graded.
  RefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
              const std::optional<auth::Key>& run_key, const std::string& exercise);

  // The exercise's grading. The truth and the bumper arrive only when signed (in a graded run)
  // and of the current episode.
  virtual bool gradedToEnd() const = 0;
  virtual void onTruePose(const aula::pose3d_t& msg) = 0;
  virtual void onContact(int64_t utime, bool pressed) = 0;
  virtual void startNewEpisode(int64_t utime) = 0;            // hot reload: grade from scratch
  virtual void onEpisode(const aula::episode_t& msg) = 0;  // its start, its goal
  virtual void onClockTick(int64_t utime) = 0;
  // The report: the header has these two; the exercise's own fields follow it.
  virtual double mark() const = 0;
  virtual double gradedTimeS() const { return simTimeUs() / 1e6; }
  virtual void addGrading(Report& report) const = 0;
  virtual std::vector<std::string> measures() const = 0;  // the raw measures `aula grade` shows
  virtual std::string gradeSummary() const = 0;
  // The picture of the run; `notes` are its caption's world, seed, algorithm and outcome lines.
  virtual cv::Mat picture(const std::vector<std::string>& notes) const = 0;
  // The trace's exercise part: "robot" (traceDisc/traceBox), "map" (traceMap), "state" (what
  // the exercise's player draws) and "breakdown" (breakdownJson of the mark's terms). The
  // exercise feeds trace() as it grades: start, poses, its events, stop.
  virtual void addTrace(Report& trace) const = 0;

  RunTrace& trace() { return trace_; }
  const RunTrace& trace() const { return trace_; }

  const RunOutcome& outcome() const { return outcome_; }
  const std::string& robotName() const { return robot_name_; }

 private:
  void onPoseMessage(const lcm::ReceiveBuffer*, const std::string& channel, const aula::pose3d_t* msg);
  void onBumperMessage(const lcm::ReceiveBuffer*, const std::string& channel, const aula::bumper_t* msg);
  void onEpisodeMessage(const lcm::ReceiveBuffer*, const std::string& channel, const aula::episode_t* msg);
  void announce(int64_t utime);  // the end once to the window, the status to the component
  void traceFault(int64_t utime);  // the fault just learnt, in the trace
  // The first motor command that was not a finite number, in the trace (its total at the end).
  void traceNonFinite(int64_t utime);
  void announceEnd();              // the end, once: kept (episodeEnd) and told to the window

  std::string exercise_, robot_name_;
  std::string component_client_;  // the component's lockstep client ("teletaxi")
  bool component_listed_ = false;  // seen in a tick's clients
  std::string pose_channel_, bumper_channel_;
  std::string world_file_, world_sha256_;  // the file name and its content's hash
  Report rubric_;                          // the report's "rubric": the preset and its numbers
  int64_t episode_from_utime_ = -1;        // truth at or before this sim time is the last episode's
  RunOutcome outcome_;
  RunTrace trace_;
  std::unique_ptr<TraceLayers> layers_;  // what the player may draw besides what was graded
  long non_finite_event_ = -1;  // the trace's event of the first non-finite command, -1: none
  std::unique_ptr<StatusSender> status_;
  std::unique_ptr<lcmbus::LockstepClient> clock_;
  std::function<void()> on_finished_;
  std::optional<EpisodeEnd> end_;
  // The episode's first true pose, and whether the robot has left it since (failedBeforeMoving):
  // farther than kStillWithinM or turned more than kStillWithinRad (a robot at rest settles by less).
  static constexpr double kStillWithinM = 0.01, kStillWithinRad = 0.02;
  std::optional<aula::pose3d_t> first_pose_;
  bool moved_ = false;
};

}  // namespace aula::referee
