#pragma once
// The vacuum referee's picture of a run (`--picture`): the house map with the floor the robot
// cleaned in blue (the referee's own CoverageGrid), the floor it missed in white, walls black,
// its final footprint, and a caption with the mark and the coverage.

#include <aula/scoring/coverage_grid.hpp>

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace aula::vacuum {

// The referee's own coverage measure (libs/scoring), by its name here.
using scoring::CoverageGrid;

// BGR colours of the map's pixels in the picture.
inline const cv::Scalar kCleanedColour(240, 175, 90), kNotFloorColour(200, 200, 200);

struct CoverageRunSummary {
  double mark = 0, coverage_percent = 0, elapsed_s = 0;
  std::string scale;  // "rubric default: a 5 at 40 %, a 10 at 60 %"
  long long bumps = 0;
  bool have_pose = false;
  double x_m = 0, y_m = 0, yaw_rad = 0, robot_radius_m = 0.165;
  std::vector<std::string> notes;  // more caption lines (the world, why the run ended early)
};

// `occupancy`: the map the grid was built on (CV_8UC1, 0 = wall or furniture).
cv::Mat coveragePicture(const cv::Mat& occupancy, const CoverageGrid& grid, const CoverageRunSummary& run);

}  // namespace aula::vacuum
