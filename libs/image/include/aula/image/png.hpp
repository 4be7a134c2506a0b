#pragma once
// PNG files of OpenCV images (8-bit gray or BGR), with libpng: the occupancy-map cache, the
// referees' pictures, the map of `aula check-world --map` and aula-mapgen.

#include <opencv2/core.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace aula::image {

// A CV_8UC1 (gray) or CV_8UC3 (BGR) image as PNG bytes; throws std::runtime_error otherwise.
std::vector<uint8_t> encodePng(const cv::Mat& image);
// Writes encodePng(image) to `path`; false when it cannot.
bool writePng(const std::string& path, const cv::Mat& image);
// A PNG file as CV_8UC1 (gray); empty when the file is missing or not a PNG.
cv::Mat readGrayPng(const std::string& path);

}  // namespace aula::image
