#include "aula/vacuum/cleaned_cells_trace.hpp"

#include <algorithm>
#include <cmath>

namespace aula::vacuum {
namespace {

constexpr int kNear = 31;  // offsets -31..30 take one digit each

void digits(std::string& out, int value, int count) {
  std::string text(count, '0');
  for (int i = count - 1; i >= 0; --i, value /= 62) text[i] = kCellDigits[value % 62];
  out += text;
}

}  // namespace

CleanedCellsTrace::CleanedCellsTrace(const CoverageGrid& grid, double robot_radius_m, double cell_size_m)
    : grid_(grid),
      reach_m_(robot_radius_m + grid.transform().resolution_m),
      cell_px_(std::max(1, static_cast<int>(std::lround(cell_size_m / grid.transform().resolution_m)))) {
  const cv::Mat& floor = grid_.floor();
  const int cols = (floor.cols + cell_px_ - 1) / cell_px_, rows = (floor.rows + cell_px_ - 1) / cell_px_;
  reported_ = cv::Mat::zeros(rows, cols, CV_8UC1);
  floor_px_ = cv::Mat::zeros(rows, cols, CV_32SC1);
  for (int r = 0; r < floor.rows; ++r) {
    for (int c = 0; c < floor.cols; ++c) {
      if (floor.at<uint8_t>(r, c) != 0) ++floor_px_.at<int32_t>(r / cell_px_, c / cell_px_);
    }
  }
}

void CleanedCellsTrace::touched(double x_m, double y_m) {
  const geometry::MapTransform& t = grid_.transform();
  const int c0 = static_cast<int>(std::floor(t.worldToColF(x_m - reach_m_))) / cell_px_;
  const int c1 = static_cast<int>(std::floor(t.worldToColF(x_m + reach_m_))) / cell_px_;
  const int r0 = static_cast<int>(std::floor(t.worldToRowF(y_m + reach_m_))) / cell_px_;
  const int r1 = static_cast<int>(std::floor(t.worldToRowF(y_m - reach_m_))) / cell_px_;
  if (!dirty_) {
    col_min_ = c0, col_max_ = c1, row_min_ = r0, row_max_ = r1;
    dirty_ = true;
    return;
  }
  col_min_ = std::min(col_min_, c0), col_max_ = std::max(col_max_, c1);
  row_min_ = std::min(row_min_, r0), row_max_ = std::max(row_max_, r1);
}

void CleanedCellsTrace::sample() {
  if (!coverage_cp_.empty()) cells_ += ' ';
  coverage_cp_.push_back(static_cast<int64_t>(std::llround(grid_.coveragePercent() * 100.0)));
  if (!dirty_) return;
  dirty_ = false;
  const cv::Mat& cleaned = grid_.cleaned();
  for (int row = std::max(0, row_min_); row <= std::min(reported_.rows - 1, row_max_); ++row) {
    for (int col = std::max(0, col_min_); col <= std::min(reported_.cols - 1, col_max_); ++col) {
      const int floor_px = floor_px_.at<int32_t>(row, col);
      if (reported_.at<uint8_t>(row, col) != 0 || floor_px == 0) continue;
      int cleaned_px = 0;
      for (int r = row * cell_px_; r < std::min(cleaned.rows, (row + 1) * cell_px_); ++r) {
        for (int c = col * cell_px_; c < std::min(cleaned.cols, (col + 1) * cell_px_); ++c) cleaned_px += cleaned.at<uint8_t>(r, c) != 0;
      }
      if (2 * cleaned_px < floor_px) continue;
      reported_.at<uint8_t>(row, col) = 1;
      ++cells_cleaned_;
      const int dc = col - last_col_, dr = row - last_row_;
      last_col_ = col;
      last_row_ = row;
      if (dc >= -kNear && dc < kNear && dr >= -kNear && dr < kNear) {
        cells_ += kCellDigits[dc + kNear];
        cells_ += kCellDigits[dr + kNear];
      } else {
        cells_ += '~';
        digits(cells_, col, 3);
        digits(cells_, row, 3);
      }
    }
  }
}

}  // namespace aula::vacuum
