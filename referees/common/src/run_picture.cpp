#include "aula/referee/run_picture.hpp"

#include <aula/config/paths.hpp>

#include <aula/referee/report.hpp>

#include <aula/image/png.hpp>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace aula::referee {
namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kTitleScale = 0.75, kLineScale = 0.55, kLabelScale = 0.5;
constexpr int kMarginPx = 10;
constexpr int kMinWidthPx = 640;  // room for the caption, whatever the map's shape
const cv::Scalar kCaptionBackground(245, 245, 245);

int textWidth(const std::string& text, double scale, int thickness) {
  int baseline = 0;
  return cv::getTextSize(text, kFont, scale, thickness, &baseline).width;
}

// Words onto lines no wider than width_px (a word longer than that gets a line of its own).
std::vector<std::string> wrap(const std::string& text, double scale, int thickness, int width_px) {
  std::vector<std::string> out;
  std::istringstream words(text);
  std::string word, line;
  while (words >> word) {
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && textWidth(longer, scale, thickness) > width_px) {
      out.push_back(line);
      line = word;
    } else {
      line = longer;
    }
  }
  if (!line.empty()) out.push_back(line);
  return out;
}

std::vector<cv::Point> toPixels(const RunPicture& picture, const std::vector<PicturePoint>& points) {
  std::vector<cv::Point> out;
  out.reserve(points.size());
  for (const auto& p : points) out.push_back(picture.pixel(p.x_m, p.y_m));
  return out;
}

}  // namespace

void Trail::add(double x_m, double y_m) {
  if (!points_.empty() && std::hypot(x_m - points_.back().x_m, y_m - points_.back().y_m) < min_step_m_) return;
  points_.push_back({x_m, y_m});
}

RunPicture::RunPicture(const cv::Mat& map, const geometry::MapTransform& transform, int max_side_px) {
  if (map.empty()) throw std::invalid_argument("RunPicture: empty map");
  const double scale = std::min(static_cast<double>(max_side_px) / map.cols, static_cast<double>(max_side_px) / map.rows);
  const int width_px = std::max(1, static_cast<int>(std::lround(map.cols * scale)));
  const int height_px = std::max(1, static_cast<int>(std::lround(map.rows * scale)));
  cv::Mat bgr;
  if (map.type() == CV_8UC1) cv::cvtColor(map, bgr, cv::COLOR_GRAY2BGR);
  else if (map.type() == CV_8UC3) bgr = map;
  else throw std::invalid_argument("RunPicture: the map must be CV_8UC1 or CV_8UC3");
  cv::resize(bgr, canvas_, cv::Size(width_px, height_px), 0, 0, cv::INTER_NEAREST);
  // The same world window, in canvas pixels.
  transform_ = transform;
  transform_.resolution_m = transform.resolution_m * map.cols / width_px;
  transform_.width_px = width_px;
  transform_.height_px = height_px;
}

cv::Mat RunPicture::occupancyInColour(const cv::Mat& occupancy, const cv::Scalar& obstacle, const cv::Scalar& free) {
  cv::Mat out(occupancy.size(), CV_8UC3, free);
  out.setTo(obstacle, occupancy == 0);
  return out;
}

cv::Point RunPicture::pixel(double x_m, double y_m) const {
  return {static_cast<int>(std::lround(transform_.worldToColF(x_m))),
          static_cast<int>(std::lround(transform_.worldToRowF(y_m)))};
}

int RunPicture::pixels(double length_m) const {
  return std::max(1, static_cast<int>(std::lround(length_m / transform_.resolution_m)));
}

void RunPicture::polyline(const std::vector<PicturePoint>& points, const cv::Scalar& colour, int thickness_px) {
  if (points.size() < 2) return;
  cv::polylines(canvas_, toPixels(*this, points), false, colour, thickness_px, cv::LINE_AA);
}

void RunPicture::polygon(const std::vector<PicturePoint>& corners, const cv::Scalar& colour, int thickness_px) {
  const std::vector<cv::Point> pts = toPixels(*this, corners);
  if (thickness_px < 0) cv::fillPoly(canvas_, std::vector<std::vector<cv::Point>>{pts}, colour, cv::LINE_AA);
  else cv::polylines(canvas_, pts, true, colour, thickness_px, cv::LINE_AA);
}

void RunPicture::translucentPolygon(const std::vector<PicturePoint>& corners, const cv::Scalar& colour, double opacity) {
  cv::Mat layer = canvas_.clone();
  cv::fillPoly(layer, std::vector<std::vector<cv::Point>>{toPixels(*this, corners)}, colour, cv::LINE_AA);
  cv::addWeighted(layer, opacity, canvas_, 1.0 - opacity, 0.0, canvas_);
}

std::vector<PicturePoint> RunPicture::corners(const geometry::OrientedBox& box) {
  std::vector<PicturePoint> out;
  for (const auto& c : box.corners()) out.push_back({c.x(), c.y()});
  return out;
}

void RunPicture::box(const geometry::OrientedBox& box, const cv::Scalar& colour, int thickness_px) {
  polygon(corners(box), colour, thickness_px);
}

void RunPicture::disc(double x_m, double y_m, double radius_m, const cv::Scalar& colour, int thickness_px) {
  cv::circle(canvas_, pixel(x_m, y_m), std::max(3, pixels(radius_m)), colour, thickness_px, cv::LINE_AA);
}

void RunPicture::heading(double x_m, double y_m, double yaw_rad, double length_m, const cv::Scalar& colour,
                         int thickness_px) {
  const double reach_m = std::max(length_m, 3 * transform_.resolution_m);
  cv::line(canvas_, pixel(x_m, y_m), pixel(x_m + reach_m * std::cos(yaw_rad), y_m + reach_m * std::sin(yaw_rad)), colour,
           thickness_px, cv::LINE_AA);
}

void RunPicture::marker(double x_m, double y_m, const cv::Scalar& colour, const std::string& text, int radius_px) {
  const cv::Point at = pixel(x_m, y_m);
  cv::circle(canvas_, at, radius_px, colour, cv::FILLED, cv::LINE_AA);
  cv::circle(canvas_, at, radius_px, colour::kBlack, 2, cv::LINE_AA);
  if (!text.empty()) label(x_m, y_m, text, colour, radius_px + 4);
}

void RunPicture::label(double x_m, double y_m, const std::string& text, const cv::Scalar& colour, int beside_px) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, kFont, kLabelScale, 2, &baseline);
  cv::Point at = pixel(x_m, y_m) + cv::Point(beside_px, size.height / 2);
  if (beside_px > 0 && at.x + size.width > canvas_.cols - 3) at.x -= 2 * beside_px + size.width;
  at.x = std::clamp(at.x, 3, std::max(3, canvas_.cols - size.width - 3));
  at.y = std::clamp(at.y, size.height + 3, std::max(size.height + 3, canvas_.rows - baseline - 3));
  cv::putText(canvas_, text, at, kFont, kLabelScale, colour::kWhite, 5, cv::LINE_AA);
  cv::putText(canvas_, text, at, kFont, kLabelScale, colour, 2, cv::LINE_AA);
}

void RunPicture::centredLabel(double x_m, double y_m, const std::string& text, const cv::Scalar& colour) {
  label(x_m - textWidth(text, kLabelScale, 2) / 2.0 * transform_.resolution_m, y_m, text, colour);
}

void RunPicture::addLegend(const cv::Scalar& colour, const std::string& meaning) { legend_.emplace_back(colour, meaning); }

cv::Mat RunPicture::compose(const std::string& title, const std::vector<std::string>& lines) const {
  const int width_px = std::max(kMinWidthPx, canvas_.cols);
  const int text_width_px = width_px - 2 * kMarginPx;
  // What goes in the caption, each line already wrapped: (text, is_title).
  std::vector<std::pair<std::string, bool>> rows;
  for (const auto& t : wrap(title, kTitleScale, 2, text_width_px)) rows.emplace_back(t, true);
  for (const auto& line : lines) {
    for (const auto& t : wrap(line, kLineScale, 1, text_width_px)) rows.emplace_back(t, false);
  }
  // The legend: swatch + text entries, flowing onto as many rows as they need.
  constexpr int kSwatchPx = 16, kLegendRowPx = 24;
  std::vector<std::vector<size_t>> legend_rows;
  int x = kMarginPx;
  for (size_t i = 0; i < legend_.size(); ++i) {
    const int entry_px = kSwatchPx + 6 + textWidth(legend_[i].second, kLabelScale, 1) + 18;
    if (legend_rows.empty() || (x + entry_px > width_px - kMarginPx && x > kMarginPx)) {
      legend_rows.emplace_back();
      x = kMarginPx;
    }
    legend_rows.back().push_back(i);
    x += entry_px;
  }
  int caption_px = kMarginPx;
  for (const auto& row : rows) caption_px += row.second ? 32 : 24;
  caption_px += static_cast<int>(legend_rows.size()) * kLegendRowPx + kMarginPx;

  cv::Mat out(caption_px + canvas_.rows, width_px, CV_8UC3, kCaptionBackground);
  int y = kMarginPx;
  for (const auto& [text, is_title] : rows) {
    y += is_title ? 32 : 24;
    cv::putText(out, text, {kMarginPx, y - 8}, kFont, is_title ? kTitleScale : kLineScale, colour::kBlack,
                is_title ? 2 : 1, cv::LINE_AA);
  }
  for (const auto& row : legend_rows) {
    x = kMarginPx;
    for (size_t i : row) {
      const cv::Rect swatch(x, y + 4, kSwatchPx, kSwatchPx);
      cv::rectangle(out, swatch, legend_[i].first, cv::FILLED);
      cv::rectangle(out, swatch, colour::kBlack, 1);
      cv::putText(out, legend_[i].second, {x + kSwatchPx + 6, y + 4 + kSwatchPx - 2}, kFont, kLabelScale, colour::kBlack,
                  1, cv::LINE_AA);
      x += kSwatchPx + 6 + textWidth(legend_[i].second, kLabelScale, 1) + 18;
    }
    y += kLegendRowPx;
  }
  cv::line(out, {0, caption_px - 1}, {width_px - 1, caption_px - 1}, colour::kGrey, 1);
  canvas_.copyTo(out(cv::Rect((width_px - canvas_.cols) / 2, caption_px, canvas_.cols, canvas_.rows)));
  return out;
}

void writePngAtomically(const cv::Mat& image, const std::string& path) {
  if (image.empty()) throw std::runtime_error(path + ": cannot encode an empty picture");
  const std::vector<uint8_t> png = image::encodePng(image);
  config::writeFileAtomically(path, std::string(png.begin(), png.end()), "picture");
}

}  // namespace aula::referee
