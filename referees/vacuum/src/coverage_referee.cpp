#include "aula/vacuum/coverage_referee.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aula::vacuum {

double coverageMark(double coverage_percent, double half_mark_coverage_percent, double full_mark_coverage_percent) {
  const double half = half_mark_coverage_percent, full = full_mark_coverage_percent;
  if (!(half > 0 && half < full) || !std::isfinite(coverage_percent)) return 0.0;
  const double mark = coverage_percent <= half ? 5.0 * coverage_percent / half
                                               : 5.0 + 5.0 * (coverage_percent - half) / (full - half);
  return std::clamp(mark, 0.0, 10.0);
}

CoverageSettings coverageSettings(const config::Config& cfg) {
  CoverageSettings s;
  s.rubric = cfg.getString("Vacuum.Referee.Rubric");
  s.duration_s = cfg.getDouble("Vacuum.Referee.Duration");
  s.robot_radius_m = cfg.getDouble("Vacuum.Referee.RobotRadius");
  s.half_mark_coverage_percent = cfg.getDouble("Vacuum.Referee.HalfMarkCoverage");
  s.full_mark_coverage_percent = cfg.getDouble("Vacuum.Referee.FullMarkCoverage");
  // Each number's range is declared (aula_settings); their order is checked here.
  if (!(s.half_mark_coverage_percent < s.full_mark_coverage_percent)) {
    throw config::ConfigError(cfg.origin("Vacuum.Referee.FullMarkCoverage") + ": Vacuum.Referee.FullMarkCoverage = " +
                              cfg.getString("Vacuum.Referee.FullMarkCoverage") + " % must be above Vacuum.Referee.HalfMarkCoverage = " +
                              cfg.getString("Vacuum.Referee.HalfMarkCoverage") + " % (" +
                              cfg.origin("Vacuum.Referee.HalfMarkCoverage") + ")");
  }
  return s;
}

std::string scaleText(const CoverageSettings& s) {
  char text[128];
  std::snprintf(text, sizeof text, "rubric %s: a 5 at %.4g %%, a 10 at %.4g %%", s.rubric.c_str(),
                s.half_mark_coverage_percent, s.full_mark_coverage_percent);
  return text;
}

CoverageReferee::CoverageReferee(CoverageGrid grid, CoverageSettings settings, int64_t origin_utime)
    : grid_(std::move(grid)), settings_(settings), origin_utime_(origin_utime) {}

void CoverageReferee::onPose(int64_t sim_utime, double x_m, double y_m) {
  const int64_t utime = sim_utime - origin_utime_;
  if (utime < 0) return;
  if (finished_ || utime > static_cast<int64_t>(std::llround(settings_.duration_s * 1e6))) return;
  grid_.markDisc(x_m, y_m, settings_.robot_radius_m);
  const int64_t window_us = static_cast<int64_t>(settings_.stuck_window_s * 1e6);
  if (window_start_utime_ < 0) {
    window_start_utime_ = utime;
    window_x_ = x_m;
    window_y_ = y_m;
  } else if (utime - window_start_utime_ >= window_us) {
    const double window_s = (utime - window_start_utime_) / 1e6;
    if (std::hypot(x_m - window_x_, y_m - window_y_) < settings_.stuck_distance_m) {
      stuck_s_ += window_s;
      stuck_at_end_s_ += window_s;  // consecutive stuck windows are one stretch
    } else {
      stuck_at_end_s_ = 0;
    }
    window_start_utime_ = utime;
    window_x_ = x_m;
    window_y_ = y_m;
  }
}

bool CoverageReferee::wedged() const {
  // A robot pressed in a corner for the episode's last fifth (180 s of 900) has given up: its
  // coverage is what it reached before, and a calibration must not take such a run as its anchor.
  // A shorter stop at the end (a bump, a turn in place) is still a cleaner at work.
  return stuck_at_end_s_ >= settings_.wedged_fraction * settings_.duration_s;
}

void CoverageReferee::onBump(int64_t, bool pressed) {
  if (finished_) return;
  if (pressed && !pressed_) ++bumps_;
  pressed_ = pressed;
}

void CoverageReferee::onTick(int64_t sim_utime) {
  const int64_t utime = sim_utime - origin_utime_;
  if (finished_ || utime < 0) return;
  now_utime_ = utime;
  // Coverage gain in each finished 100 s slice.
  while (utime >= static_cast<int64_t>(per_100s_.size() + 1) * 100'000'000 &&
         static_cast<double>(per_100s_.size() + 1) * 100.0 <= settings_.duration_s + 1e-9) {
    per_100s_.push_back(grid_.coveragePercent() - coverage_at_last_boundary_);
    coverage_at_last_boundary_ = grid_.coveragePercent();
  }
  if (utime >= static_cast<int64_t>(std::llround(settings_.duration_s * 1e6))) {
    finished_ = true;
    end_utime_ = static_cast<int64_t>(std::llround(settings_.duration_s * 1e6));
  }
}

}  // namespace aula::vacuum
