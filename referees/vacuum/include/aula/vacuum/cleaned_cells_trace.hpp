#pragma once
// The vacuum's state in a run's trace: the floor cleaned as it happened, compactly. The trace's
// cells are squares of cell_px x cell_px map pixels (about 6 cm); a cell counts as cleaned at the
// first sample at which the referee's CoverageGrid has cleaned at least half of its floor pixels.
// Each sample lists its newly cleaned cells, one sample after another separated by a space, each
// cell as two characters: its column and row offsets from the cell listed before it (the first
// from cell 0, 0), in -31..30, as kCellDigits[offset + 31]; a cell farther away is '~' and its
// absolute column and row, three such digits each. Integers only: a reader decodes exactly. The referee's exact coverage at each sample is kept beside it
// (hundredths of a percent, delta-encoded), so the player shows the report's figure.

#include <aula/scoring/coverage_grid.hpp>

#include <opencv2/core.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace aula::vacuum {

// The referee's own coverage measure (libs/scoring), by its name here.
using scoring::CoverageGrid;

inline constexpr const char* kCellDigits = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";

class CleanedCellsTrace {
 public:
  // `cell_size_m`: the side of a trace cell, rounded to whole map pixels of `grid`.
  CleanedCellsTrace(const CoverageGrid& grid, double robot_radius_m, double cell_size_m = 0.06);

  // The grid was painted with the robot's disc at (x_m, y_m): its cells may have changed.
  void touched(double x_m, double y_m);
  // A sample of the trace: the cells cleaned since the last sample.
  void sample();

  int cellPx() const { return cell_px_; }
  size_t samples() const { return coverage_cp_.size(); }
  long long cellsCleaned() const { return cells_cleaned_; }
  const std::string& cells() const { return cells_; }
  const std::vector<int64_t>& coverageCentiPercent() const { return coverage_cp_; }

 private:
  const CoverageGrid& grid_;
  double reach_m_;      // how far from a touched point cells can change
  int cell_px_;
  cv::Mat reported_;    // CV_8UC1 per cell: 1 once listed
  cv::Mat floor_px_;    // CV_32SC1 per cell: its floor pixels
  bool dirty_ = false;  // touched since the last sample: the box below
  int col_min_ = 0, col_max_ = -1, row_min_ = 0, row_max_ = -1;
  std::string cells_;
  std::vector<int64_t> coverage_cp_;
  long long cells_cleaned_ = 0;
  int last_col_ = 0, last_row_ = 0;  // the cell listed last
};

}  // namespace aula::vacuum
