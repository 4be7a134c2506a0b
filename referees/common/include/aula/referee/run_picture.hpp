#pragma once
// A referee's picture of a run (`--picture=FILE.png`), for the teacher's grading report: a map,
// north-up on the world's MapTransform grid, what the referee saw drawn over it in world
// coordinates, and a caption bar with the mark. Drawn with OpenCV only (headless, no Qt), from
// the run's data only (no clock, no random), so the same run gives a byte-identical PNG.

#include <aula/geometry/map_transform.hpp>
#include <aula/geometry/oriented_box.hpp>

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace aula::referee {

struct PicturePoint {
  double x_m = 0, y_m = 0;
};

// The path a robot drove, bounded: a pose is kept only when it is at least min_step_m from the
// last kept one (a long run at 50 Hz would otherwise keep every pose).
class Trail {
 public:
  explicit Trail(double min_step_m) : min_step_m_(min_step_m) {}
  void add(double x_m, double y_m);
  const std::vector<PicturePoint>& points() const { return points_; }

 private:
  double min_step_m_;
  std::vector<PicturePoint> points_;
};

// Colours (OpenCV's BGR order), the same in every referee's picture.
namespace colour {
inline const cv::Scalar kBlack(0, 0, 0), kWhite(255, 255, 255), kGrey(150, 150, 150), kLightGrey(222, 222, 222);
inline const cv::Scalar kBlue(215, 120, 30), kOrange(0, 130, 255), kGreen(60, 160, 40), kRed(40, 40, 210);
}  // namespace colour

class RunPicture {
 public:
  // `map`: CV_8UC3 (BGR) or CV_8UC1 (grey) on the grid `transform`. It is scaled by nearest
  // neighbour (map pixels stay sharp squares) to fit max_side_px x max_side_px.
  RunPicture(const cv::Mat& map, const geometry::MapTransform& transform, int max_side_px = 800);
  // An occupancy image (CV_8UC1, 0 obstacle) in two colours.
  static cv::Mat occupancyInColour(const cv::Mat& occupancy, const cv::Scalar& obstacle, const cv::Scalar& free);

  const geometry::MapTransform& transform() const { return transform_; }  // of the canvas' pixels
  const cv::Mat& canvas() const { return canvas_; }
  cv::Point pixel(double x_m, double y_m) const;
  int pixels(double length_m) const;  // a length on the canvas, at least 1 px

  // Thickness in pixels; a negative thickness fills.
  void polyline(const std::vector<PicturePoint>& points, const cv::Scalar& colour, int thickness_px);
  void polygon(const std::vector<PicturePoint>& corners, const cv::Scalar& colour, int thickness_px);
  void translucentPolygon(const std::vector<PicturePoint>& corners, const cv::Scalar& colour, double opacity);
  void box(const geometry::OrientedBox& box, const cv::Scalar& colour, int thickness_px);
  static std::vector<PicturePoint> corners(const geometry::OrientedBox& box);
  void disc(double x_m, double y_m, double radius_m, const cv::Scalar& colour, int thickness_px);
  // A heading tick from the centre of a footprint to its edge.
  void heading(double x_m, double y_m, double yaw_rad, double length_m, const cv::Scalar& colour, int thickness_px);
  // A dot of a fixed size (readable at any scale) with an outline, and its label beside it.
  void marker(double x_m, double y_m, const cv::Scalar& colour, const std::string& label, int radius_px = 8);
  // Text on the map with a white halo, its left end at (x_m, y_m), nudged inside the canvas.
  // beside_px > 0: beside a mark at the point, starting that far right of it, or ending that far
  // left of it when the canvas ends first.
  void label(double x_m, double y_m, const std::string& text, const cv::Scalar& colour, int beside_px = 0);
  // The same, centred on (x_m, y_m).
  void centredLabel(double x_m, double y_m, const std::string& text, const cv::Scalar& colour);

  // A colour swatch and what it means, in the legend row of the caption.
  void addLegend(const cv::Scalar& colour, const std::string& meaning);
  // The picture: a caption bar (the title in bold, then one line each) above the canvas, the
  // legend row at its bottom.
  cv::Mat compose(const std::string& title, const std::vector<std::string>& lines) const;

 private:
  geometry::MapTransform transform_;
  cv::Mat canvas_;  // CV_8UC3
  std::vector<std::pair<cv::Scalar, std::string>> legend_;
};

// Writes `image` as a PNG through a temporary file and a rename, so a reader never sees half a
// picture. Throws std::runtime_error naming the path.
void writePngAtomically(const cv::Mat& image, const std::string& path);

}  // namespace aula::referee
