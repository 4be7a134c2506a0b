#pragma once
// What the vacuum cleaner has cleaned: the robot's disc footprint painted on the generated
// house map (the same MapTransform as every GUI), counting free pixels only.
// The floor is the free pixels reachable from the robot's start (4-connected), so pockets
// sealed inside furniture or outside the walls never count.

#include <aula/geometry/map_transform.hpp>

#include <opencv2/core.hpp>

#include <cstdint>

namespace aula::scoring {

class CoverageGrid {
 public:
  // map: CV_8UC1, 0 = obstacle. start: a world point on the floor (the robot's start).
  CoverageGrid(const cv::Mat& map, const geometry::MapTransform& transform, double start_x_m, double start_y_m);

  // Marks every floor pixel whose centre lies within radius_m of (x_m, y_m).
  void markDisc(double x_m, double y_m, double radius_m);
  void clear();

  int64_t floorPixels() const { return floor_pixels_; }
  int64_t cleanedPixels() const { return cleaned_pixels_; }
  double floorAreaM2() const { return floor_pixels_ * transform_.resolution_m * transform_.resolution_m; }
  double coveragePercent() const {
    return floor_pixels_ > 0 ? 100.0 * static_cast<double>(cleaned_pixels_) / static_cast<double>(floor_pixels_) : 0.0;
  }
  const cv::Mat& cleaned() const { return cleaned_; }  // CV_8UC1: 255 cleaned floor
  const cv::Mat& floor() const { return floor_; }      // CV_8UC1: 255 floor
  const geometry::MapTransform& transform() const { return transform_; }

 private:
  geometry::MapTransform transform_;
  cv::Mat floor_;    // 255 = floor
  cv::Mat cleaned_;  // 255 = cleaned
  int64_t floor_pixels_ = 0;
  int64_t cleaned_pixels_ = 0;
};

}  // namespace aula::scoring
