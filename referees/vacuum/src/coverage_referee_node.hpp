#pragma once
// The vacuum referee's LCM side: true pose and bumper feed the CoverageReferee; the clock ends
// the run at 900 s of sim time; the report is built at the end.

#include <aula/bumper_t.hpp>
#include <aula/config/config.hpp>
#include <aula/episode_t.hpp>
#include <aula/lcm/lockstep_client.hpp>
#include <aula/pose3d_t.hpp>
#include <aula/referee/report.hpp>
#include <aula/referee/run_outcome.hpp>
#include <aula/referee/status_sender.hpp>
#include <aula/vacuum/coverage_referee.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include <functional>
#include <memory>
#include <optional>

namespace aula::vacuum {

class CoverageRefereeNode {
 public:
  // `run_key`: a graded run's key (--key-fd): only the truth the simulator signed is graded.
  CoverageRefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                      const std::optional<auth::Key>& run_key = std::nullopt);
  const CoverageReferee& referee() const { return *referee_; }
  bool finished() const { return referee_->finished() || outcome_.ended(); }
  // The launcher says the run cannot go on (a process died...): grade what there is, and end.
  void abort(const std::string& reason);
  bool endedEarly() const { return outcome_.ended(); }
  referee::Report report() const;
  std::string summary() const;
  void writePicture(const std::string& png_path) const;  // --picture
  void poll() { clock_->poll(); }
  void leave() { clock_->leave(); }
  void setOnFinished(std::function<void()> hook) { on_finished_ = std::move(hook); }
  // Called for every pose (GUI painting).
  void setOnPose(std::function<void(double, double, double)> hook) { on_pose_ = std::move(hook); }
  const world::OccupancyMap& map() const { return map_; }
  int episode() const { return outcome_.generation(); }  // counts hot reloads
  bool started() const { return started_; }  // the episode's clock runs (after Run)
  // What the windows are told (referee_status_t): the time left, and how the episode ended.
  referee::EpisodeStatus status() const;

 private:
  void onPose(const lcm::ReceiveBuffer*, const std::string&, const aula::pose3d_t* msg);
  void onBumper(const lcm::ReceiveBuffer*, const std::string&, const aula::bumper_t* msg);
  void onEpisode(const lcm::ReceiveBuffer*, const std::string&, const aula::episode_t* msg);

  std::unique_ptr<CoverageReferee> newReferee(int64_t origin_utime) const;
  void start(int64_t utime);

  struct TimedPoint {
    int64_t utime;
    double x_m, y_m;
  };
  bool started_ = false;
  std::optional<TimedPoint> waiting_pose_;  // the last pose before the episode started

  CoverageSettings settings_;
  referee::Report rubric_;  // the report's "rubric": the preset and its numbers
  double start_x_m_ = 0, start_y_m_ = 0;
  int64_t episode_from_utime_ = -1;  // truth at or before this sim time is the last episode's
  std::unique_ptr<CoverageReferee> referee_;
  std::unique_ptr<lcmbus::LockstepClient> clock_;
  aula::referee::RunOutcome outcome_;
  std::unique_ptr<referee::StatusSender> status_;
  std::string world_file_, world_sha256_;  // the file name and its content's hash
  world::OccupancyMap map_;
  std::function<void()> on_finished_;
  std::function<void(double, double, double)> on_pose_;
  long long pose_messages_ = 0;
  bool have_pose_ = false;  // the last true pose of this episode, for the picture
  double x_m_ = 0, y_m_ = 0, yaw_rad_ = 0;
};

}  // namespace aula::vacuum
