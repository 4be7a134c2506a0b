#include "aula/scoring/coverage_grid.hpp"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <stdexcept>

namespace aula::scoring {

CoverageGrid::CoverageGrid(const cv::Mat& map, const geometry::MapTransform& transform, double start_x_m,
                           double start_y_m)
    : transform_(transform) {
  if (map.empty() || map.type() != CV_8UC1) throw std::invalid_argument("CoverageGrid: the map must be 8-bit grey");
  const int col = transform.worldToCol(start_x_m), row = transform.worldToRow(start_y_m);
  if (!transform.contains(col, row) || map.at<uint8_t>(row, col) == 0) {
    throw std::invalid_argument("CoverageGrid: the start point is not on the floor");
  }
  cv::Mat fill = map.clone();
  cv::floodFill(fill, cv::Point(col, row), cv::Scalar(128), nullptr, 0, 0, 4);
  floor_ = fill == 128;
  floor_pixels_ = cv::countNonZero(floor_);
  cleaned_ = cv::Mat::zeros(map.size(), CV_8UC1);
}

void CoverageGrid::clear() {
  cleaned_.setTo(0);
  cleaned_pixels_ = 0;
}

void CoverageGrid::markDisc(double x_m, double y_m, double radius_m) {
  const double r_px = radius_m / transform_.resolution_m;
  const double cx = transform_.worldToColF(x_m), cy = transform_.worldToRowF(y_m);
  const int row0 = std::max(0, static_cast<int>(std::floor(cy - r_px)));
  const int row1 = std::min(cleaned_.rows - 1, static_cast<int>(std::ceil(cy + r_px)));
  const int col0 = std::max(0, static_cast<int>(std::floor(cx - r_px)));
  const int col1 = std::min(cleaned_.cols - 1, static_cast<int>(std::ceil(cx + r_px)));
  for (int row = row0; row <= row1; ++row) {
    const double dy = row + 0.5 - cy;
    const uint8_t* floor = floor_.ptr<uint8_t>(row);
    uint8_t* cleaned = cleaned_.ptr<uint8_t>(row);
    for (int col = col0; col <= col1; ++col) {
      const double dx = col + 0.5 - cx;
      if (dx * dx + dy * dy > r_px * r_px || !floor[col] || cleaned[col]) continue;
      cleaned[col] = 255;
      ++cleaned_pixels_;
    }
  }
}

}  // namespace aula::scoring
