#include "aula/teletaxi/taxi_picture.hpp"

#include <algorithm>
#include <cstdio>

namespace aula::teletaxi {

cv::Mat taxiPicture(const cv::Mat& occupancy, const geometry::MapTransform& transform, const TaxiRunSummary& run) {
  namespace colour = referee::colour;
  const cv::Scalar building(110, 110, 110);
  referee::RunPicture picture(referee::RunPicture::occupancyInColour(occupancy, building, colour::kWhite), transform);
  // The destination: its arrival circle, at least 12 px across so it shows around the taxi.
  const double ring_m = std::max(run.arrival_radius_m, 12 * picture.transform().resolution_m);
  if (run.have_goal) picture.disc(run.goal_x_m, run.goal_y_m, ring_m, colour::kRed, 3);
  picture.polyline(run.path, kTaxiPathColour, 3);
  // The last stretch: the path keeps a point per 25 cm, the end is the last true pose.
  if (!run.path.empty() && run.have_pose) picture.polyline({run.path.back(), {run.x_m, run.y_m}}, kTaxiPathColour, 3);
  if (!run.path.empty()) picture.marker(run.path.front().x_m, run.path.front().y_m, colour::kGreen, "start");
  if (run.have_goal) picture.label(run.goal_x_m, run.goal_y_m, "destination", colour::kRed, picture.pixels(ring_m) + 5);
  if (run.have_pose) picture.marker(run.x_m, run.y_m, colour::kBlue, run.path.empty() ? "taxi (never left)" : "", 6);
  picture.addLegend(kTaxiPathColour, "path from GO!");
  picture.addLegend(colour::kGreen, "start");
  picture.addLegend(colour::kRed, "destination (arrival circle)");
  picture.addLegend(colour::kBlue, "taxi at the end");
  picture.addLegend(building, "buildings");
  char title[200], line[320];
  std::snprintf(title, sizeof title, "TeleTaxi: mark %.2f / 10, %s", run.grade.mark,
                run.finished ? (run.grade.reached ? "reached the destination" : "did not reach the destination")
                             : "not finished");
  std::snprintf(line, sizeof line,
                "%.1f s sim from GO!, %.1f m driven (straight line %.1f m), %lld bumps against walls",
                run.driving_time_s, run.path_length_m, run.straight_distance_m, run.bumps);
  std::vector<std::string> lines = {line};
  if (!run.grade.verdict.empty()) lines.push_back(run.grade.verdict);
  lines.insert(lines.end(), run.notes.begin(), run.notes.end());
  return picture.compose(title, lines);
}

}  // namespace aula::teletaxi
