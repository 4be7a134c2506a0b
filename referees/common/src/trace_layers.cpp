#include "aula/referee/trace_layers.hpp"

#include <algorithm>
#include <cmath>

namespace aula::referee {
namespace {

int64_t periodUs(double period_s) { return static_cast<int64_t>(std::llround(period_s * 1e6)); }

std::string intArray(const std::vector<int32_t>& values) {
  std::string out = "[";
  for (size_t i = 0; i < values.size(); ++i) out += (i ? "," : "") + std::to_string(values[i]);
  return out + "]";
}

// A picture's cells as [value, run length, value, run length, ...] in the cells' own order.
template <typename Level>
std::string levelRuns(const std::vector<uint8_t>& cells, Level level) {
  std::string out = "[";
  size_t i = 0;
  bool first = true;
  while (i < cells.size()) {
    const int value = level(cells[i]);
    size_t run = 1;
    while (i + run < cells.size() && level(cells[i + run]) == value) ++run;
    out += (first ? "" : ",") + std::to_string(value) + "," + std::to_string(run);
    first = false;
    i += run;
  }
  return out + "]";
}

std::string gridJson(double resolution_m, double origin_x_m, double origin_y_m, int width, int height) {
  return "\"resolution_m\": " + formatNumber(resolution_m) + ", \"origin_m\": [" + formatNumber(origin_x_m) + ", " +
         formatNumber(origin_y_m) + "], \"size_px\": [" + std::to_string(width) + ", " + std::to_string(height) + "]";
}

}  // namespace

TraceLayers::TraceLayers(lcmbus::Bus& bus, const config::Config& cfg, const world::RobotSpec& robot,
                         const std::string& section, const RunTrace& trace)
    : trace_(trace) {
  for (const world::PluginSpec& plugin : robot.plugins) {
    if (plugin.type != "laser") continue;
    Laser laser;
    laser.name = plugin.name;
    laser.channel = world::channelOf(robot, "laser", plugin.name);
    const Eigen::Isometry3d mount = plugin.has("pose") ? plugin.getPose("pose") : Eigen::Isometry3d::Identity();
    laser.mount_x_m = mount.translation().x();
    laser.mount_y_m = mount.translation().y();
    laser.mount_yaw_rad = world::yawOf(mount);
    lasers_.push_back(laser);
  }
  for (const Laser& laser : lasers_) {
    subscriptions_.push_back(bus.subscribe(laser.channel, &TraceLayers::onLaserMessage, this));
    deferred_.push_back(laser.channel);
  }
  subscriptions_.push_back(bus.subscribe(cfg.getString(section + ".Console.Channel"), &TraceLayers::onConsoleMessage, this));
  if (cfg.has(section + ".Belief.Channel")) {
    deferred_.push_back(cfg.getString(section + ".Belief.Channel"));
    subscriptions_.push_back(bus.subscribe(deferred_.back(), &TraceLayers::onBeliefMessage, this));
  }
  if (cfg.has(section + ".Plan.Channel")) {
    subscriptions_.push_back(bus.subscribe(cfg.getString(section + ".Plan.Channel"), &TraceLayers::onPlanMessage, this));
  }
}

void TraceLayers::leave(lcmbus::Bus& bus) {
  for (lcm::Subscription* subscription : subscriptions_) bus.unsubscribe(subscription);
  subscriptions_.clear();
  deferred_.clear();
}

void TraceLayers::onLaserMessage(const lcm::ReceiveBuffer*, const std::string& channel, const aula::laser_t* msg) {
  for (size_t i = 0; i < lasers_.size(); ++i) {
    if (lasers_[i].channel == channel) onLaser(i, *msg);
  }
}
void TraceLayers::onConsoleMessage(const lcm::ReceiveBuffer*, const std::string&, const aula::console_t* msg) { onConsole(*msg); }
void TraceLayers::onBeliefMessage(const lcm::ReceiveBuffer*, const std::string&, const aula::belief_t* msg) { onBelief(*msg); }
void TraceLayers::onPlanMessage(const lcm::ReceiveBuffer*, const std::string&, const aula::plan_t* msg) { onPlan(*msg); }

void TraceLayers::deferWakeUps(lcmbus::Bus& bus) const {
  for (const std::string& channel : deferred_) bus.deferWakeUps(channel);
}

void TraceLayers::followEpisode() {
  if (!trace_.started() || trace_.originUtime() == episode_origin_) return;
  episode_origin_ = trace_.originUtime();
  for (Laser& laser : lasers_) {
    laser.utimes.clear();
    laser.ranges_steps.clear();
    laser.next_us = 0;
  }
  belief_placed_ = false;
  belief_utimes_.clear();
  belief_x_mm_.clear();
  belief_y_mm_.clear();
  belief_yaw_mrad_.clear();
  belief_next_us_ = 0;
  belief_maps_.clear();
  belief_map_version_ = 0;
  console_head_.clear();
  console_tail_.clear();
  console_head_bytes_ = console_tail_bytes_ = 0;
  console_dropped_bytes_ = console_dropped_lines_ = 0;
}

void TraceLayers::onLaser(size_t index, const aula::laser_t& msg) {
  followEpisode();
  if (!inEpisode(msg.utime) || index >= lasers_.size()) return;
  Laser& laser = lasers_[index];
  const int64_t t_us = msg.utime - trace_.originUtime();
  if (t_us < laser.next_us) return;
  laser.next_us = (t_us / periodUs(kScanPeriodS) + 1) * periodUs(kScanPeriodS);
  laser.min_angle_rad = msg.min_angle;
  laser.increment_rad = msg.angle_increment * kBeamStep;
  laser.max_range_m = msg.max_range;
  std::vector<int64_t> ranges;
  for (size_t i = 0; i < msg.ranges.size(); i += kBeamStep) {
    const double range_m = std::isfinite(msg.ranges[i]) ? std::min<double>(msg.ranges[i], msg.max_range) : msg.max_range;
    ranges.push_back(std::llround(range_m * (1.0 / kRangeStepM)));  // 1 / 0.02 is 50 exactly: no drift at halves
  }
  laser.utimes.push_back(msg.utime);
  laser.ranges_steps.push_back(std::move(ranges));
}

void TraceLayers::keepLine(Line line) {
  const size_t bytes = line.text.size() + 1;
  if (console_head_bytes_ + bytes <= kConsoleHalfBytes && console_tail_.empty()) {
    console_head_bytes_ += bytes;
    console_head_.push_back(std::move(line));
    return;
  }
  console_tail_bytes_ += bytes;
  console_tail_.push_back(std::move(line));
  while (console_tail_bytes_ > kConsoleHalfBytes && !console_tail_.empty()) {
    console_tail_bytes_ -= console_tail_.front().text.size() + 1;
    console_dropped_bytes_ += console_tail_.front().text.size() + 1;
    ++console_dropped_lines_;
    console_tail_.pop_front();
  }
}

void TraceLayers::onConsole(const aula::console_t& msg) {
  followEpisode();
  if (!inEpisode(msg.utime)) return;
  const std::string text = validUtf8(msg.text);
  size_t from = 0;
  while (from < text.size()) {
    size_t end = text.find('\n', from);
    if (end == std::string::npos) end = text.size();
    keepLine({msg.utime, text.substr(from, end - from)});
    from = end + 1;
  }
}

void TraceLayers::onBelief(const aula::belief_t& msg) {
  followEpisode();
  if (!inEpisode(msg.utime)) return;
  if (!belief_placed_) {  // its frame put where the truth is when it first speaks (as its window does)
    if (!trace_.hasPose()) return;
    belief_placed_ = true;
    belief_dx_m_ = trace_.x() - msg.x_m;
    belief_dy_m_ = trace_.y() - msg.y_m;
  }
  const int64_t t_us = msg.utime - trace_.originUtime();
  if (t_us >= belief_next_us_) {
    belief_next_us_ = (t_us / periodUs(kBeliefPeriodS) + 1) * periodUs(kBeliefPeriodS);
    belief_utimes_.push_back(msg.utime);
    belief_x_mm_.push_back(milli(msg.x_m + belief_dx_m_));
    belief_y_mm_.push_back(milli(msg.y_m + belief_dy_m_));
    belief_yaw_mrad_.push_back(milli(msg.yaw_rad));
  }
  const bool has_map = msg.map_cells_count > 0 && msg.map_width > 0 && msg.map_height > 0 &&
                       static_cast<int64_t>(msg.map_width) * msg.map_height == msg.map_cells_count;
  if (!has_map || msg.map_version == belief_map_version_) return;
  // One map a period, and the latest always (it replaces the last one that was not a period's).
  const bool periodic = belief_maps_.empty() || msg.utime - belief_map_periodic_utime_ >= periodUs(kBeliefMapPeriodS);
  if (!belief_maps_.empty() && !belief_maps_.back().periodic) belief_maps_.pop_back();
  if (periodic) belief_map_periodic_utime_ = msg.utime;
  belief_map_version_ = msg.map_version;
  // Three levels, as the window draws them: 0 free (<= 64), 1 unknown, 2 occupied (>= 192); row 0 at the bottom.
  const std::string runs = levelRuns(msg.map_cells, [](uint8_t cell) { return cell >= 192 ? 2 : cell <= 64 ? 0 : 1; });
  belief_maps_.push_back({msg.utime, periodic, gridJson(msg.map_resolution_m, msg.map_origin_x_m + belief_dx_m_,
                                              msg.map_origin_y_m + belief_dy_m_, msg.map_width, msg.map_height) +
                                         ", \"runs\": " + runs});
}

void TraceLayers::onPlan(const aula::plan_t& msg) {
  if (msg.width <= 0 || msg.height <= 0) return;
  std::string json = gridJson(msg.resolution_m, msg.origin_x_m, msg.origin_y_m, msg.width, msg.height);
  if (msg.field_count > 0 && static_cast<int64_t>(msg.width) * msg.height == msg.field_count) {
    // 16 grey levels (the field's picture: 0 an obstacle, dark near the destination, 255 far or unreached), row 0 at the top.
    json += ", \"field\": " + levelRuns(msg.field, [](uint8_t grey) { return grey >> 4; });
  }
  std::vector<int32_t> path;
  for (int32_t i = 0; i < msg.path_count && i < static_cast<int32_t>(msg.path_col.size()); ++i) {
    path.push_back(msg.path_col[i]);
    path.push_back(msg.path_row[i]);
  }
  plans_.push_back({msg.utime, json + ", \"path\": " + intArray(path)});
}

void TraceLayers::addTo(Report& trace) const {
  if (!trace_.started()) return;
  Report layers;
  auto t_of = [this](int64_t utime) { return formatNumber(trace_.timeS(utime)); };
  std::string lasers = "[";
  for (size_t i = 0; i < lasers_.size(); ++i) {
    const Laser& l = lasers_[i];
    lasers += std::string(i ? ",\n " : "\n ") + "{\"name\": " + jsonString(l.name) + ", \"mount\": [" + formatNumber(l.mount_x_m) +
              ", " + formatNumber(l.mount_y_m) + ", " + formatNumber(l.mount_yaw_rad) + "], \"min_angle_rad\": " +
              formatNumber(l.min_angle_rad) + ", \"increment_rad\": " + formatNumber(l.increment_rad) +
              ", \"max_range_m\": " + formatNumber(l.max_range_m) + ", \"range_step_m\": " + formatNumber(kRangeStepM) +
              ", \"period_s\": " + formatNumber(kScanPeriodS) + ", \"scans\": [";
    bool first = true;
    for (size_t k = 0; k < l.utimes.size(); ++k) {
      if (!inEpisode(l.utimes[k])) continue;
      lasers += std::string(first ? "" : ",") + "\n  {\"t_s\": " + t_of(l.utimes[k]) + ", \"ranges\": " +
                deltaArray(l.ranges_steps[k]) + "}";
      first = false;
    }
    lasers += "]}";
  }
  if (!lasers_.empty()) layers.setJson("lasers", lasers + "\n]");
  if (!belief_utimes_.empty() || !belief_maps_.empty()) {
    std::vector<int64_t> t_ms, x, y, yaw;
    for (size_t k = 0; k < belief_utimes_.size(); ++k) {
      if (!inEpisode(belief_utimes_[k])) continue;
      t_ms.push_back(milli(trace_.timeS(belief_utimes_[k])));
      x.push_back(belief_x_mm_[k]);
      y.push_back(belief_y_mm_[k]);
      yaw.push_back(belief_yaw_mrad_[k]);
    }
    Report belief;
    belief.setJson("t_ms", deltaArray(t_ms));
    belief.setJson("x_mm", deltaArray(x));
    belief.setJson("y_mm", deltaArray(y));
    belief.setJson("yaw_mrad", deltaArray(yaw));
    std::string maps = "[";
    bool first = true;
    for (const BeliefMapShot& shot : belief_maps_) {
      if (!inEpisode(shot.utime)) continue;
      maps += std::string(first ? "\n " : ",\n ") + "{\"t_s\": " + t_of(shot.utime) + ", " + shot.json + "}";
      first = false;
    }
    belief.setJson("maps", maps + "]");
    layers.set("belief", belief);
  }
  // The plans of the episode, and the last one made before it started (shown from its start).
  std::string plans = "[";
  bool first = true;
  for (size_t k = 0; k < plans_.size(); ++k) {
    const Plan& plan = plans_[k];
    const bool before = plan.utime < trace_.originUtime();
    const bool last_before = before && (k + 1 == plans_.size() || plans_[k + 1].utime >= trace_.originUtime());
    if ((before && !last_before) || !trace_.beforeStop(plan.utime)) continue;
    plans += std::string(first ? "\n " : ",\n ") + "{\"t_s\": " + t_of(plan.utime) + ", " + plan.json + "}";
    first = false;
  }
  if (!first) layers.setJson("plans", plans + "]");
  Report console;
  console.set("cap_bytes", static_cast<long long>(2 * kConsoleHalfBytes));
  console.set("dropped_lines", static_cast<long long>(console_dropped_lines_));
  console.set("dropped_bytes", static_cast<long long>(console_dropped_bytes_));
  std::string lines = "[";
  first = true;
  auto add = [&](const Line& line) {
    if (!inEpisode(line.utime)) return;
    lines += std::string(first ? "\n " : ",\n ") + "{\"t_s\": " + t_of(line.utime) + ", \"text\": " + jsonString(line.text) + "}";
    first = false;
  };
  for (const Line& line : console_head_) add(line);
  for (const Line& line : console_tail_) add(line);
  console.setJson("lines", lines + "]");
  layers.set("console", console);
  trace.set("layers", layers);
}

}  // namespace aula::referee
