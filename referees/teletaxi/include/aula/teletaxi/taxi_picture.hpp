#pragma once
// The TeleTaxi referee's picture of a run (`--picture`): the city map with the taxi's path from
// GO! to the end, the start, the destination with its arrival circle, where the taxi ended, and
// a caption with the mark, the driving time and the distances.

#include <aula/referee/run_picture.hpp>
#include <aula/teletaxi/taxi_grade.hpp>
#include <aula/geometry/map_transform.hpp>

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace aula::teletaxi {

inline const cv::Scalar kTaxiPathColour = referee::colour::kOrange;

struct TaxiRunSummary {
  TaxiGrade grade;
  bool finished = false;
  double driving_time_s = 0, path_length_m = 0, straight_distance_m = 0;
  bool have_goal = false;
  double goal_x_m = 0, goal_y_m = 0, arrival_radius_m = 5;
  bool have_pose = false;
  double x_m = 0, y_m = 0, yaw_rad = 0;
  std::vector<referee::PicturePoint> path;  // from GO!; its first point is the start
  long long bumps = 0;
  std::vector<std::string> notes;  // more caption lines (the world, why the run ended early)
};

// `occupancy`: the city (CV_8UC1, 0 = building) on the grid `transform`.
cv::Mat taxiPicture(const cv::Mat& occupancy, const geometry::MapTransform& transform, const TaxiRunSummary& run);

}  // namespace aula::teletaxi
