#include "aula/vacuum/coverage_picture.hpp"

#include <aula/referee/run_picture.hpp>

#include <opencv2/imgproc.hpp>

#include <cstdio>

namespace aula::vacuum {

cv::Mat coveragePicture(const cv::Mat& occupancy, const CoverageGrid& grid, const CoverageRunSummary& run) {
  namespace colour = referee::colour;
  // Free space that is not the floor (outside the walls, sealed pockets) is grey: it never counts.
  cv::Mat map(occupancy.size(), CV_8UC3, kNotFloorColour);
  map.setTo(colour::kWhite, grid.floor());
  map.setTo(kCleanedColour, grid.cleaned());
  map.setTo(colour::kBlack, occupancy == 0);
  referee::RunPicture picture(map, grid.transform());
  if (run.have_pose) {
    picture.disc(run.x_m, run.y_m, run.robot_radius_m, colour::kOrange, cv::FILLED);
    picture.disc(run.x_m, run.y_m, run.robot_radius_m, colour::kBlack, 2);
    picture.heading(run.x_m, run.y_m, run.yaw_rad, run.robot_radius_m, colour::kBlack, 2);
  }
  picture.addLegend(kCleanedColour, "cleaned");
  picture.addLegend(colour::kWhite, "floor not cleaned");
  picture.addLegend(colour::kBlack, "walls, furniture");
  picture.addLegend(kNotFloorColour, "not floor");
  picture.addLegend(colour::kOrange, "robot at the end");
  char title[160], line[256];
  std::snprintf(title, sizeof title, "Vacuum: mark %.2f / 10, %.1f %% of the floor cleaned", run.mark,
                run.coverage_percent);
  std::snprintf(line, sizeof line, "%.1f of %.1f m2 cleaned in %.0f s sim (%s); %lld bumps",
                grid.cleanedPixels() * grid.transform().resolution_m * grid.transform().resolution_m, grid.floorAreaM2(),
                run.elapsed_s, run.scale.c_str(), run.bumps);
  std::vector<std::string> lines = {line};
  lines.insert(lines.end(), run.notes.begin(), run.notes.end());
  return picture.compose(title, lines);
}

}  // namespace aula::vacuum
