#include "aula/desktop/window_layout.hpp"

#include <algorithm>
#include <limits>
#include <sstream>
#include <tuple>

namespace aula::desktop {
namespace {

constexpr const char* kSize = ".Size";
constexpr const char* kPosition = ".Position";

Rect frameAt(const Point& corner, const Size& window) {
  return {corner.x_px, corner.y_px, window.width_px + kFrameAllowance.width_px,
          window.height_px + kFrameAllowance.height_px};
}

long long overlapWith(const Rect& frame, const std::vector<Rect>& placed) {
  long long area = 0;
  for (const Rect& other : placed) area += frame.overlapArea(other);
  return area;
}

// Where a frame may go: the work area's corner and every edge of those placed, combined.
std::vector<Point> candidates(const Rect& work_area, const std::vector<Rect>& placed) {
  std::vector<int> xs = {work_area.x_px}, ys = {work_area.y_px};
  for (const Rect& r : placed) {
    xs.push_back(r.right());
    ys.push_back(r.bottom());
  }
  std::vector<Point> out;
  for (int y : ys) {
    for (int x : xs) out.push_back({x, y});
  }
  return out;
}

// The frame moved (not resized) into the work area, as far as it goes.
Point keptOn(const Rect& work_area, const Point& corner, const Rect& frame) {
  return {std::max(work_area.x_px, std::min(corner.x_px, work_area.right() - frame.width_px)),
          std::max(work_area.y_px, std::min(corner.y_px, work_area.bottom() - frame.height_px))};
}

}  // namespace

long long Rect::overlapArea(const Rect& other) const {
  const long long w = std::min(right(), other.right()) - std::max(x_px, other.x_px);
  const long long h = std::min(bottom(), other.bottom()) - std::max(y_px, other.y_px);
  return w > 0 && h > 0 ? w * h : 0;
}

bool Rect::contains(const Rect& other) const {
  return other.x_px >= x_px && other.y_px >= y_px && other.right() <= right() && other.bottom() <= bottom();
}

std::vector<Point> layOut(const Rect& work_area, const std::vector<Size>& windows) {
  std::vector<Rect> placed;
  std::vector<Point> corners;
  for (const Size& window : windows) {
    // Topmost, then leftmost, then (when nothing fits) the least overlap.
    auto best_key = std::make_tuple(std::numeric_limits<long long>::max(), 0, 0);
    Point best{work_area.x_px, work_area.y_px};
    for (const Point& candidate : candidates(work_area, placed)) {
      const Point corner = keptOn(work_area, candidate, frameAt(candidate, window));
      const auto key = std::make_tuple(overlapWith(frameAt(corner, window), placed), corner.y_px, corner.x_px);
      if (key < best_key) {
        best_key = key;
        best = corner;
      }
    }
    placed.push_back(frameAt(best, window));
    corners.push_back(best);
  }
  return corners;
}

std::vector<std::string> windowsOf(const config::SettingsTable& table) {
  std::vector<std::string> prefixes;
  const std::string size = kSize;
  for (const config::SettingSpec& spec : table.specs()) {
    const std::string& key = spec.key;
    if (key.size() <= size.size() || key.compare(key.size() - size.size(), size.size(), size) != 0) continue;
    const std::string prefix = key.substr(0, key.size() - size.size());
    if (table.declares(prefix + kPosition)) prefixes.push_back(prefix);
  }
  return prefixes;
}

Placement placementOf(const config::Config& settings, const std::string& prefix) {
  const auto size = settings.getDoubleList(prefix + kSize);
  const auto corner = settings.getDoubleList(prefix + kPosition);
  Placement placement;
  placement.size = {static_cast<int>(size.at(0)), static_cast<int>(size.at(1))};
  if (corner.at(0) >= 0 && corner.at(1) >= 0) placement.frame_corner = Point{static_cast<int>(corner[0]), static_cast<int>(corner[1])};
  return placement;
}

RunLayout layOutRun(const Rect& work_area, const std::vector<WindowedProcess>& processes, const std::vector<Size>& extras) {
  std::vector<std::pair<size_t, std::string>> windows;  // (process, window), in layout order
  std::vector<Size> sizes;
  for (size_t process = 0; process < processes.size(); ++process) {
    for (const std::string& window : windowsOf(*processes[process].table)) {
      const Placement placement = placementOf(processes[process].settings, window);
      if (placement.frame_corner) continue;
      windows.emplace_back(process, window);
      sizes.push_back(placement.size);
    }
  }
  sizes.insert(sizes.end(), extras.begin(), extras.end());
  const std::vector<Point> corners = layOut(work_area, sizes);
  RunLayout layout;
  layout.arguments.resize(processes.size());
  for (size_t i = 0; i < windows.size(); ++i) {
    layout.arguments[windows[i].first].push_back(positionArgument(windows[i].second, corners[i]));
  }
  layout.extras.assign(corners.begin() + static_cast<std::ptrdiff_t>(windows.size()), corners.end());
  return layout;
}

std::string positionArgument(const std::string& prefix, const Point& frame_corner) {
  std::ostringstream out;
  out << "--" << prefix << kPosition << "=" << frame_corner.x_px << ", " << frame_corner.y_px;
  return out.str();
}

}  // namespace aula::desktop
