#include "aula/autopark/parking_picture.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aula::autopark {
namespace {

namespace colour = referee::colour;

cv::Scalar scoreColour(double score) {
  return score >= 100 ? colour::kGreen : score >= 50 ? colour::kOrange : colour::kRed;
}

std::string metres(const char* what, double value_m) {
  char text[64];
  std::snprintf(text, sizeof text, "%s %.2f m", what, value_m);
  return text;
}

using geometry::OrientedBox;
using referee::RunPicture;

// The gaps as dimension lines coloured by their score: along the lane at the car's centre to the
// two parked cars, and straight down from its lowest corner to the curb.
void drawGaps(RunPicture& picture, const ParkingRunSummary& run, const OrientedBox& car) {
  const ParkingScene& s = run.scene;
  double front_m = -1e9, rear_m = 1e9;
  referee::PicturePoint lowest{0, 1e9};
  for (const auto& c : RunPicture::corners(car)) {
    front_m = std::max(front_m, c.x_m);
    rear_m = std::min(rear_m, c.x_m);
    if (c.y_m < lowest.y_m) lowest = c;
  }
  const ParkingMeasures& m = run.measures;
  const double lane_y_m = run.y_m;
  const double front_car_m = s.front_car.centre.x_m - s.front_car.length_m / 2;
  const double rear_car_m = s.rear_car.centre.x_m + s.rear_car.length_m / 2;
  const cv::Scalar front = scoreColour(gapScore(m.front_gap_m, m.ideal_gap_m, run.settings));
  const cv::Scalar rear = scoreColour(gapScore(m.rear_gap_m, m.ideal_gap_m, run.settings));
  const cv::Scalar curb = scoreColour(curbScore(m.curb_gap_m, run.settings));
  picture.polyline({{front_m, lane_y_m}, {front_car_m, lane_y_m}}, front, 2);
  picture.polyline({{rear_car_m, lane_y_m}, {rear_m, lane_y_m}}, rear, 2);
  picture.polyline({lowest, {lowest.x_m, s.curb_y_m}}, curb, 2);
  const double text_up_m = 0.45 * s.car_width_m + 0.4;  // above the car, out of the way of the lines
  picture.centredLabel((front_m + front_car_m) / 2, lane_y_m + text_up_m, metres("front", m.front_gap_m), front);
  picture.centredLabel((rear_m + rear_car_m) / 2, lane_y_m + text_up_m, metres("rear", m.rear_gap_m), rear);
  picture.centredLabel(lowest.x_m, s.curb_y_m - 0.8, metres("curb", m.curb_gap_m), curb);
}

}  // namespace

geometry::MapTransform parkingView(const ParkingRunSummary& run, int width_px) {
  const ParkingScene& s = run.scene;
  double x_min = s.rear_car.centre.x_m - s.rear_car.length_m, x_max = s.front_car.centre.x_m + s.front_car.length_m;
  double y_min = s.curb_y_m - 2.0, y_max = s.ideal_y_m + s.car_width_m;
  auto include = [&](double x, double y) {
    x_min = std::min(x_min, x);
    x_max = std::max(x_max, x);
    y_min = std::min(y_min, y);
    y_max = std::max(y_max, y);
  };
  const double reach_m = std::hypot(s.car_length_m, s.car_width_m) / 2;  // a footprint around its centre
  for (const auto& p : run.trail) {
    include(p.x_m - reach_m, p.y_m - reach_m);
    include(p.x_m + reach_m, p.y_m + reach_m);
  }
  if (run.have_pose) {
    include(run.x_m - reach_m, run.y_m - reach_m);
    include(run.x_m + reach_m, run.y_m + reach_m);
  }
  constexpr double kMarginM = 1.5;
  x_min -= kMarginM;
  x_max += kMarginM;
  y_max += kMarginM;
  geometry::MapTransform view;
  view.resolution_m = (x_max - x_min) / width_px;
  view.origin_x_m = x_min;
  view.origin_y_m = y_max;
  view.width_px = width_px;
  view.height_px = static_cast<int>(std::ceil((y_max - y_min) / view.resolution_m));
  return view;
}

cv::Mat parkingPicture(const cv::Mat& street, const geometry::MapTransform& view, const ParkingRunSummary& run) {
  const ParkingScene& s = run.scene;
  const cv::Scalar obstacle(150, 150, 150), parked_car(90, 90, 90), slot(200, 235, 200);
  RunPicture picture(RunPicture::occupancyInColour(street, obstacle, colour::kWhite), view,
                              std::max(view.width_px, view.height_px));
  // The slot: between the two cars, from the curb to the far side of the parking lane.
  const double slot_from_m = s.rear_car.centre.x_m + s.rear_car.length_m / 2;
  const double slot_to_m = s.front_car.centre.x_m - s.front_car.length_m / 2;
  const double lane_top_m = s.ideal_y_m + std::max(s.rear_car.width_m, s.front_car.width_m) / 2;
  picture.polygon({{slot_from_m, s.curb_y_m}, {slot_to_m, s.curb_y_m}, {slot_to_m, lane_top_m}, {slot_from_m, lane_top_m}},
                  slot, cv::FILLED);
  for (const OrientedBox* car : {&s.rear_car, &s.front_car}) picture.box(*car, parked_car, cv::FILLED);
  picture.polyline({{view.origin_x_m, s.curb_y_m}, {view.origin_x_m + view.width_px * view.resolution_m, s.curb_y_m}},
                   colour::kBlack, 3);
  picture.box({{s.ideal_x_m, s.ideal_y_m, s.ideal_yaw_rad}, s.car_length_m, s.car_width_m}, colour::kGreen, 2);
  picture.polyline(run.trail, kTrailColour, 2);
  if (run.have_pose) {
    const OrientedBox car{{run.x_m, run.y_m, run.yaw_rad}, s.car_length_m, s.car_width_m};
    picture.translucentPolygon(RunPicture::corners(car), kCarColour, 0.45);
    picture.box(car, kCarColour, 2);
    picture.heading(run.x_m, run.y_m, run.yaw_rad, s.car_length_m / 2, colour::kBlack, 2);
    if (run.measures.inside_slot) drawGaps(picture, run, car);  // outside the slot no gap is graded
  }
  picture.label(s.rear_car.centre.x_m - s.rear_car.length_m / 2 + 0.2, s.rear_car.centre.y_m, "car behind",
                colour::kBlack);
  picture.label(s.front_car.centre.x_m - s.front_car.length_m / 2 + 0.2, s.front_car.centre.y_m, "car in front",
                colour::kBlack);
  picture.addLegend(kCarColour, "car at the end");
  picture.addLegend(kTrailColour, "its trail");
  picture.addLegend(colour::kGreen, "ideal pose");
  picture.addLegend(slot, "slot");
  picture.addLegend(parked_car, "parked cars");
  picture.addLegend(colour::kBlack, "curb");
  char title[200], terms[200], line[200];
  if (run.parked) {
    std::snprintf(title, sizeof title, "Autopark: mark %.2f / 10, PARKED in %.1f s", run.scores.mark, run.park_time_s);
  } else {
    std::snprintf(title, sizeof title, "Autopark: mark %.2f / 10, %s after %.1f s", run.scores.mark,
                  run.finished ? caseText(run.parking_case).c_str() : "not finished", run.park_time_s);
  }
  std::snprintf(terms, sizeof terms, "= %s",
                markFormula(run.scores, run.parking_case, run.contact_cost, run.settings).c_str());
  const ParkingMeasures& m = run.measures;
  std::snprintf(line, sizeof line, "gaps: front %.2f m, rear %.2f m, curb %.2f m%s; yaw error %.1f deg; %lld collisions",
                m.front_gap_m, m.rear_gap_m, m.curb_gap_m, m.inside_slot ? "" : " (not in the slot)", m.yaw_error_deg,
                run.collisions);
  std::vector<std::string> lines = {terms, line, "rubric " + run.settings.rubric + ": " + gapRuleText(run.settings)};
  lines.insert(lines.end(), run.notes.begin(), run.notes.end());
  return picture.compose(title, lines);
}

}  // namespace aula::autopark
