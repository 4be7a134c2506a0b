#include "aula/image/png.hpp"

#include <png.h>

#include <fstream>
#include <stdexcept>

namespace aula::image {

std::vector<uint8_t> encodePng(const cv::Mat& image) {
  if (image.empty() || image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3)) {
    throw std::runtime_error("encodePng: expected a non-empty 8-bit gray or BGR image");
  }
  const cv::Mat pixels = image.isContinuous() ? image : image.clone();
  png_image description{};
  description.version = PNG_IMAGE_VERSION;
  description.width = static_cast<png_uint_32>(pixels.cols);
  description.height = static_cast<png_uint_32>(pixels.rows);
  description.format = pixels.channels() == 1 ? PNG_FORMAT_GRAY : PNG_FORMAT_BGR;
  png_alloc_size_t size = 0;
  // First the size, then the bytes.
  if (!png_image_write_to_memory(&description, nullptr, &size, 0, pixels.data, 0, nullptr)) {
    throw std::runtime_error(std::string("encodePng: ") + description.message);
  }
  std::vector<uint8_t> bytes(size);
  if (!png_image_write_to_memory(&description, bytes.data(), &size, 0, pixels.data, 0, nullptr)) {
    throw std::runtime_error(std::string("encodePng: ") + description.message);
  }
  bytes.resize(size);
  return bytes;
}

bool writePng(const std::string& path, const cv::Mat& image) {
  const std::vector<uint8_t> bytes = encodePng(image);
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(out.flush());
}

cv::Mat readGrayPng(const std::string& path) {
  png_image description{};
  description.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&description, path.c_str())) return {};
  description.format = PNG_FORMAT_GRAY;
  cv::Mat image(static_cast<int>(description.height), static_cast<int>(description.width), CV_8UC1);
  if (!png_image_finish_read(&description, nullptr, image.data, 0, nullptr)) {
    png_image_free(&description);
    return {};
  }
  return image;
}

}  // namespace aula::image
