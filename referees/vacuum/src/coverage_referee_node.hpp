#pragma once
// The vacuum referee on every exercise's RefereeNode: the true pose and the bumper feed the
// CoverageReferee from Run on; its clock ends the episode at 900 s of sim time.

#include <aula/config/config.hpp>
#include <aula/referee/referee_node.hpp>
#include <aula/vacuum/cleaned_cells_trace.hpp>
#include <aula/vacuum/coverage_referee.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include <functional>
#include <memory>
#include <optional>

namespace aula::vacuum {

class CoverageRefereeNode : public referee::RefereeNode {
 public:
  // `run_key`: a graded run's key (--key-fd): only the truth the simulator signed is graded.
  CoverageRefereeNode(lcmbus::Bus& bus, const config::Config& cfg, const world::WorldSpec& world,
                      const std::optional<auth::Key>& run_key = std::nullopt);
  const CoverageReferee& referee() const { return *referee_; }
  // Called for every pose (GUI painting).
  void setOnPose(std::function<void(double, double, double)> hook) { on_pose_ = std::move(hook); }
  const world::OccupancyMap& map() const { return map_; }
  bool started() const { return started_; }  // the episode's clock runs (after Run)
  referee::EpisodeStatus status() const override;

 private:
  bool gradedToEnd() const override { return referee_->finished(); }
  void onTruePose(const aula::pose3d_t& msg) override;
  void onContact(int64_t utime, bool pressed) override;
  void startNewEpisode(int64_t utime) override;
  void onEpisode(const aula::episode_t& msg) override;
  void onClockTick(int64_t utime) override;
  double mark() const override { return referee_->mark(); }
  double gradedTimeS() const override { return referee_->elapsedS(); }
  void addGrading(referee::Report& report) const override;
  std::vector<std::string> measures() const override { return {"coverage_percent"}; }
  std::string gradeSummary() const override;
  cv::Mat picture(const std::vector<std::string>& notes) const override;
  void addTrace(referee::Report& trace) const override;
  // The trace's events of one graded pose or bump: stuck, the mark's thresholds, the end.
  void traceProgress(int64_t utime, double stuck_before_s);

  std::unique_ptr<CoverageReferee> newReferee(int64_t origin_utime) const;
  void start(int64_t utime);

  struct TimedPoint {
    int64_t utime;
    double x_m, y_m, yaw_rad;
  };
  bool started_ = false;
  std::optional<TimedPoint> waiting_pose_;  // the last pose before the episode started

  CoverageSettings settings_;
  double start_x_m_ = 0, start_y_m_ = 0;
  std::unique_ptr<CoverageReferee> referee_;
  std::unique_ptr<CleanedCellsTrace> cells_;  // the trace's cleaned floor, on referee_'s grid
  int thresholds_passed_ = 0;                 // of the half and the full mark's coverage
  world::OccupancyMap map_;
  std::function<void(double, double, double)> on_pose_;
  long long pose_messages_ = 0;
  bool have_pose_ = false;  // the last true pose of this episode, for the picture
  double x_m_ = 0, y_m_ = 0, yaw_rad_ = 0;
};

}  // namespace aula::vacuum
