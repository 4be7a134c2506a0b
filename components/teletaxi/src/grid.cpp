#include "aula/teletaxi/grid.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace aula::teletaxi {

Grid::Grid(cv::Mat map, geometry::MapTransform transform) : map_(std::move(map)), transform_(transform) {
  if (map_.empty() || map_.type() != CV_8UC1) {
    throw std::invalid_argument("Grid: the map must be a non-empty 8-bit single-channel image");
  }
  if (transform_.width_px != map_.cols || transform_.height_px != map_.rows) {
    throw std::invalid_argument("Grid: the map metadata does not match the image size");
  }
  field_ = cv::Mat::zeros(map_.size(), CV_32FC1);
  path_ = cv::Mat::zeros(map_.size(), CV_32FC1);
}

bool Grid::isFree(int x, int y) const { return inside(x, y) && map_.at<uint8_t>(y, x) != 0; }

void Grid::setVal(int x, int y, float value) {
  if (inside(x, y)) field_.at<float>(y, x) = value;
}

float Grid::getVal(int x, int y) const {
  return inside(x, y) ? field_.at<float>(y, x) : std::numeric_limits<float>::infinity();
}

void Grid::setPathVal(int x, int y, float value) {
  if (inside(x, y)) path_.at<float>(y, x) = value;
}

float Grid::getPathVal(int x, int y) const { return inside(x, y) ? path_.at<float>(y, x) : 0.0f; }

void Grid::resetPath() {
  field_.setTo(0.0f);
  path_.setTo(0.0f);
  path_found_ = false;
}

cv::Mat Grid::fieldImage() const {
  float max_value = 0.0f;
  for (int y = 0; y < field_.rows; ++y) {
    for (int x = 0; x < field_.cols; ++x) {
      const float v = field_.at<float>(y, x);
      if (std::isfinite(v) && v > max_value) max_value = v;
    }
  }
  cv::Mat image(field_.size(), CV_8UC1);
  for (int y = 0; y < field_.rows; ++y) {
    for (int x = 0; x < field_.cols; ++x) {
      const float v = field_.at<float>(y, x);
      uint8_t g = 255;
      if (map_.at<uint8_t>(y, x) == 0) {
        g = 0;
      } else if (std::isfinite(v) && v > 0 && max_value > 0) {
        g = static_cast<uint8_t>(30 + 225.0f * std::sqrt(v / max_value));
      } else if (v == 0 && destiny_ == std::make_pair(x, y)) {
        g = 30;
      }
      image.at<uint8_t>(y, x) = g;
    }
  }
  return image;
}

std::pair<double, double> Grid::gridToWorld(int x, int y) const {
  return {transform_.colToWorldX(x), transform_.rowToWorldY(y)};
}

std::pair<int, int> Grid::worldToGrid(double x_m, double y_m) const {
  return {transform_.worldToCol(x_m), transform_.worldToRow(y_m)};
}

}  // namespace aula::teletaxi
