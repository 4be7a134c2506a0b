#pragma once
// The Autopark referee's picture of a run (`--picture`): the street around the slot (the parked
// cars, the curb), the ideal parking rectangle, the car's final footprint and its trail, and the
// measured gaps to the car in front, the car behind and the curb as dimension lines coloured by
// their score (green full, orange half, red none); a caption with the mark and its terms.

#include <aula/autopark/parking_referee.hpp>
#include <aula/referee/run_picture.hpp>
#include <aula/geometry/map_transform.hpp>

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace aula::autopark {

inline const cv::Scalar kCarColour = referee::colour::kBlue, kTrailColour = referee::colour::kOrange;

struct ParkingRunSummary {
  ParkingScene scene;
  ParkingRefereeSettings settings;
  ParkingMeasures measures;
  ParkingScores scores;
  bool finished = false, parked = false;
  double park_time_s = 0;
  long long collisions = 0;
  ParkingCase parking_case = ParkingCase::GaveUp;
  double contact_cost = 0;  // the share of the mark the contacts cost (scale parked)
  bool have_pose = false;
  double x_m = 0, y_m = 0, yaw_rad = 0;
  std::vector<referee::PicturePoint> trail;
  std::vector<std::string> notes;  // more caption lines (the world, why the run ended early)
};

// The window of the street the picture shows: the slot's two cars, the curb, the car and its
// trail, with a margin; width_px pixels across.
geometry::MapTransform parkingView(const ParkingRunSummary& run, int width_px = 800);

// `street`: the world's static geometry rasterised on `view` (CV_8UC1, 0 = obstacle).
cv::Mat parkingPicture(const cv::Mat& street, const geometry::MapTransform& view, const ParkingRunSummary& run);

}  // namespace aula::autopark
