#pragma once
// A run's trace (`--trace=FILE.json`), written by the referee beside its report, for the player
// in the grading page (tools/grade: run_page). It holds what the referee graded, on its clock:
//   - the true pose sampled on sim time every period_s (10 Hz) from the graded episode's start
//     to its end, in integer mm and mrad, each column delta-encoded (the first value absolute);
//   - the referee's events, each with its time (s since the episode started), place, what
//     happened and its effect on the mark;
//   - the exercise's own state and the mark's breakdown (the exercise node adds them);
//   - the map the player draws on, its occupancy run-length encoded.
// Written from the run's data only (no clock, no random), so the same run, and `aula regrade` of
// its log, give a byte-identical trace.

#include <aula/geometry/map_transform.hpp>
#include <aula/referee/report.hpp>

#include <opencv2/core.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace aula::referee {

struct TraceEvent {
  double t_s = 0;            // since the episode started
  std::string kind;          // "bump", "contact", "stuck", "end", "fault", ...
  std::string text;          // what happened, for people
  std::string effect;        // its effect on the mark, for people ("" when none)
  bool placed = false;       // x_m, y_m say where
  double x_m = 0, y_m = 0;
  double duration_s = -1;    // for what lasts (a contact, time stuck); -1: an instant
  double points = 0;         // points this event earned (>0) or cost (<0), when it is a rubric term's moment
};

// One row of the mark, in the rubric's order: a term (what was measured, the points it earned of
// the most it could), added; or a rule that scales what the rows above it add up to (`factor`
// >= 0: contacts that cost a share of the mark). Read top to bottom, the rows make the report's
// mark: the page shows them and their total, and computes nothing of its own.
struct MarkTerm {
  std::string term, measure;
  double points = 0, of = 0;
  double factor = -1;  // >= 0: this row multiplies the total so far (points and of unused)
};

class RunTrace {
 public:
  explicit RunTrace(double period_s = 0.1);

  // The graded episode starts (times count from `origin_utime`); anything traced before is dropped.
  void start(int64_t origin_utime);
  void clear();  // a hot reload: nothing of the last episode stays
  // The graded episode ended at sim time `utime`: no more samples (the events after it still
  // count: a fault...).
  void stop(int64_t utime) {
    stopped_ = true;
    stop_utime_ = utime;
  }
  int64_t originUtime() const { return origin_utime_; }
  // Stamped before the stop (or no stop yet): what the trace's layers keep.
  bool beforeStop(int64_t utime) const { return !stopped_ || utime < stop_utime_; }
  bool started() const { return started_; }
  bool sampling() const { return started_ && !stopped_; }
  double timeS(int64_t utime) const;  // since the start, never negative

  // A true pose of the graded episode. Returns how many samples it added: each sample is the
  // latest pose at or before its time.
  int onPose(int64_t utime, double x_m, double y_m, double yaw_rad);
  size_t samples() const { return x_mm_.size(); }
  bool hasPose() const { return have_pose_; }
  double x() const { return x_m_; }
  double y() const { return y_m_; }
  double yawRad() const { return yaw_rad_; }

  // An event now (at `utime`), placed at the latest pose when there is one.
  TraceEvent& addEvent(int64_t utime, const std::string& kind, const std::string& text, const std::string& effect = "");
  std::vector<TraceEvent>& events() { return events_; }
  const std::vector<TraceEvent>& events() const { return events_; }

  // The trace's "samples" (period_s, count and the delta-encoded columns), "events" and
  // "final" (the last pose traced) into `out`.
  void addTo(Report& out) const;

 private:
  int64_t period_us_;
  bool started_ = false, stopped_ = false;
  int64_t origin_utime_ = 0, next_sample_us_ = 0, stop_utime_ = 0;
  bool have_pose_ = false;
  int64_t pose_utime_ = 0;
  double x_m_ = 0, y_m_ = 0, yaw_rad_ = 0;
  std::vector<int64_t> x_mm_, y_mm_, yaw_mrad_;
  std::vector<TraceEvent> events_;
};

// [v0, v1 - v0, v2 - v1, ...] as a compact JSON array.
std::string deltaArray(const std::vector<int64_t>& values);
// Metres to integer millimetres (radians to milliradians), rounded half away from zero.
int64_t milli(double value);
// The map the player draws: {"resolution_m", "origin_m" (world x, y of the top-left corner),
// "size_px", "rle"}: `occupancy` (CV_8UC1, 0 obstacle) row by row, top row first, as the lengths
// of alternating runs of free and obstacle pixels, starting with free (a first run may be 0).
Report traceMap(const cv::Mat& occupancy, const geometry::MapTransform& transform);
// The footprint the player draws: a disc, or a box length x width (along the heading).
Report traceDisc(double radius_m);
Report traceBox(double length_m, double width_m);
// [{"term", "measure", "points", "of"} or {"term", "measure", "factor"}, ...]
std::string breakdownJson(const std::vector<MarkTerm>& terms);
// The rows' total as the page shows it: the terms added, each rule's factor applied in order.
double breakdownTotal(const std::vector<MarkTerm>& terms);

}  // namespace aula::referee
