#include "aula/referee/run_trace.hpp"

#include <cmath>
#include <stdexcept>

namespace aula::referee {

int64_t milli(double value) { return std::isfinite(value) ? static_cast<int64_t>(std::llround(value * 1000.0)) : 0; }

std::string deltaArray(const std::vector<int64_t>& values) {
  std::string out = "[";
  int64_t previous = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    out += (i ? "," : "") + std::to_string(values[i] - previous);
    previous = values[i];
  }
  return out + "]";
}

RunTrace::RunTrace(double period_s) : period_us_(static_cast<int64_t>(std::llround(period_s * 1e6))) {
  if (period_us_ <= 0) throw std::logic_error("RunTrace: the period must be positive");
}

void RunTrace::clear() {
  started_ = stopped_ = have_pose_ = false;
  next_sample_us_ = 0;
  x_mm_.clear();
  y_mm_.clear();
  yaw_mrad_.clear();
  events_.clear();
}

void RunTrace::start(int64_t origin_utime) {
  clear();
  started_ = true;
  origin_utime_ = origin_utime;
}

double RunTrace::timeS(int64_t utime) const {
  if (!started_ || utime <= origin_utime_) return 0.0;
  return (utime - origin_utime_) / 1e6;
}

int RunTrace::onPose(int64_t utime, double x_m, double y_m, double yaw_rad) {
  if (!sampling() || utime < origin_utime_) return 0;
  const int64_t t_us = utime - origin_utime_;
  int added = 0;
  while (next_sample_us_ <= t_us) {
    // The latest pose at or before the sample's time: this one when it is exactly there (or the
    // first), else the one before it.
    const bool now = t_us == next_sample_us_ || !have_pose_;
    x_mm_.push_back(milli(now ? x_m : x_m_));
    y_mm_.push_back(milli(now ? y_m : y_m_));
    yaw_mrad_.push_back(milli(now ? yaw_rad : yaw_rad_));
    next_sample_us_ += period_us_;
    ++added;
  }
  have_pose_ = true;
  pose_utime_ = utime;
  x_m_ = x_m;
  y_m_ = y_m;
  yaw_rad_ = yaw_rad;
  return added;
}

TraceEvent& RunTrace::addEvent(int64_t utime, const std::string& kind, const std::string& text, const std::string& effect) {
  TraceEvent e;
  e.t_s = timeS(utime);
  e.kind = kind;
  e.text = text;
  e.effect = effect;
  if (have_pose_) {
    e.placed = true;
    e.x_m = x_m_;
    e.y_m = y_m_;
  }
  events_.push_back(e);
  return events_.back();
}

void RunTrace::addTo(Report& out) const {
  Report samples;
  samples.set("period_s", period_us_ / 1e6);
  samples.set("count", static_cast<long long>(x_mm_.size()));
  samples.setJson("x_mm", deltaArray(x_mm_));
  samples.setJson("y_mm", deltaArray(y_mm_));
  samples.setJson("yaw_mrad", deltaArray(yaw_mrad_));
  out.set("samples", samples);
  std::string events = "[";
  for (size_t i = 0; i < events_.size(); ++i) {
    const TraceEvent& e = events_[i];
    events += i ? ",\n " : "\n ";
    events += "{\"t_s\": " + formatNumber(e.t_s) + ", \"kind\": " + jsonString(e.kind);
    if (e.placed) events += ", \"x_mm\": " + std::to_string(milli(e.x_m)) + ", \"y_mm\": " + std::to_string(milli(e.y_m));
    if (e.duration_s >= 0) events += ", \"duration_s\": " + formatNumber(e.duration_s);
    if (e.points != 0) events += ", \"points\": " + formatNumber(e.points);
    events += ", \"text\": " + jsonString(e.text) + ", \"effect\": " + jsonString(e.effect) + "}";
  }
  out.setJson("events", events + (events_.empty() ? "]" : "\n]"));
  Report final_pose;
  final_pose.set("traced", have_pose_);
  final_pose.set("t_s", timeS(pose_utime_));
  final_pose.set("pose", std::vector<double>{x_m_, y_m_, yaw_rad_});
  out.set("final", final_pose);
}

Report traceMap(const cv::Mat& occupancy, const geometry::MapTransform& transform) {
  if (occupancy.type() != CV_8UC1) throw std::logic_error("traceMap: the occupancy must be CV_8UC1");
  std::string rle = "[";
  bool free = true;
  long long run = 0;
  bool first = true;
  auto flush = [&] {
    rle += (first ? "" : ",") + std::to_string(run);
    first = false;
    run = 0;
    free = !free;
  };
  for (int row = 0; row < occupancy.rows; ++row) {
    const uint8_t* pixel = occupancy.ptr<uint8_t>(row);
    for (int col = 0; col < occupancy.cols; ++col) {
      if ((pixel[col] != 0) != free) flush();
      ++run;
    }
  }
  flush();
  Report map;
  map.set("resolution_m", transform.resolution_m);
  map.set("origin_m", std::vector<double>{transform.origin_x_m, transform.origin_y_m});
  map.setJson("size_px", "[" + std::to_string(occupancy.cols) + ", " + std::to_string(occupancy.rows) + "]");
  map.setJson("rle", rle + "]");
  return map;
}

Report traceDisc(double radius_m) {
  Report robot;
  robot.set("shape", "disc");
  robot.set("radius_m", radius_m);
  return robot;
}

Report traceBox(double length_m, double width_m) {
  Report robot;
  robot.set("shape", "box");
  robot.set("length_m", length_m);
  robot.set("width_m", width_m);
  return robot;
}

std::string breakdownJson(const std::vector<MarkTerm>& terms) {
  std::string out = "[";
  for (size_t i = 0; i < terms.size(); ++i) {
    const MarkTerm& t = terms[i];
    out += (i ? ",\n " : "\n ") + std::string("{\"term\": ") + jsonString(t.term) + ", \"measure\": " + jsonString(t.measure);
    out += t.factor >= 0 ? ", \"factor\": " + formatNumber(t.factor) + "}"
                         : ", \"points\": " + formatNumber(t.points) + ", \"of\": " + formatNumber(t.of) + "}";
  }
  return out + (terms.empty() ? "]" : "\n]");
}

double breakdownTotal(const std::vector<MarkTerm>& terms) {
  double total = 0;
  for (const MarkTerm& t : terms) total = t.factor >= 0 ? total * t.factor : total + t.points;
  return total;
}

}  // namespace aula::referee
