#pragma once
// The vacuum cleaner's referee logic on simulated time: coverage of the floor by the robot's
// true disc footprint, its gain per 100 s, bumps and time stuck; the mark at the end, on two
// straight lines through (0 %, 0), (half, 5) and (full, 10), and 10 above full:
//   mark = 5 * c / half                          for c <= half
//        = 5 + 5 * (c - half) / (full - half)    for half < c < full
// The `original` rubric (half 15 %, full 30 %) is the thesis's min(10, 10 * c / 30).

#include <aula/config/config.hpp>
#include <aula/scoring/coverage_grid.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace aula::vacuum {

// The referee's own coverage measure (libs/scoring), by its name here.
using scoring::CoverageGrid;

struct CoverageSettings {
  std::string rubric = "default";  // the preset of Vacuum.Referee.Rubric, for the reports
  double duration_s = 900.0;
  double half_mark_coverage_percent = 40.0;  // worth a 5
  double full_mark_coverage_percent = 60.0;  // worth a 10
  double robot_radius_m = 0.165;
  double stuck_window_s = 2.0;     // stuck = moved less than stuck_distance_m over this window
  double stuck_distance_m = 0.05;
  double wedged_fraction = 0.2;    // wedged = the run ended stuck for this share of duration_s or more
};

// 0 for a NaN coverage or a scale without 0 < half < full.
double coverageMark(double coverage_percent, double half_mark_coverage_percent, double full_mark_coverage_percent);
// The referee's settings from its effective configuration; a scale without half < full is a
// ConfigError naming where the values came from.
CoverageSettings coverageSettings(const config::Config& cfg);
// "rubric default: a 5 at 40 %, a 10 at 60 %", for summaries and pictures.
std::string scaleText(const CoverageSettings& s);

class CoverageReferee {
 public:
  // `origin_utime`: the sim time the episode starts at (a hot reload starts a new one later).
  CoverageReferee(CoverageGrid grid, CoverageSettings settings, int64_t origin_utime = 0);

  void onPose(int64_t utime, double x_m, double y_m);
  void onBump(int64_t utime, bool pressed);
  void onTick(int64_t utime);

  bool finished() const { return finished_; }
  double elapsedS() const { return (end_utime_ >= 0 ? end_utime_ : now_utime_) / 1e6; }  // since the origin
  double remainingS() const { return std::max(0.0, settings_.duration_s - elapsedS()); }
  double coveragePercent() const { return grid_.coveragePercent(); }
  double mark() const {
    return coverageMark(coveragePercent(), settings_.half_mark_coverage_percent, settings_.full_mark_coverage_percent);
  }
  const std::vector<double>& coveragePer100s() const { return per_100s_; }  // gain in each 100 s
  long long bumps() const { return bumps_; }
  double stuckS() const { return stuck_s_; }
  // The length of the stuck stretch the run is in, or ended in: its consecutive stuck windows; 0
  // after a window in which it moved.
  double stuckAtEndS() const { return stuck_at_end_s_; }
  // The run ended stuck for settings().wedged_fraction of its episode or more (pressed in a
  // corner for good): the report's "wedged", which a calibration's anchor must not be.
  bool wedged() const;
  const CoverageGrid& grid() const { return grid_; }
  const CoverageSettings& settings() const { return settings_; }

 private:
  CoverageGrid grid_;
  CoverageSettings settings_;
  int64_t origin_utime_;
  bool finished_ = false;
  int64_t now_utime_ = 0;  // since the origin, like every time below
  int64_t end_utime_ = -1;
  bool pressed_ = false;
  long long bumps_ = 0;
  double stuck_s_ = 0;
  double stuck_at_end_s_ = 0;
  std::vector<double> per_100s_;
  double coverage_at_last_boundary_ = 0;
  // Stuck detection: the pose one window ago.
  int64_t window_start_utime_ = -1;
  double window_x_ = 0, window_y_ = 0;
};

}  // namespace aula::vacuum
