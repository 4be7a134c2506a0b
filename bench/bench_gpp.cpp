// Gradient Path Planning: the full navigation field (wavefront + obstacle penalty) on the
// generated 400 x 400 city map and on a procedural 4000 x 4000 city.
#include <aula/teletaxi/gradient_field.hpp>

#include <benchmark/benchmark.h>
#include <aula/image/png.hpp>
#include <opencv2/imgproc.hpp>

namespace {

cv::Mat cityMap() {
  cv::Mat map = aula::image::readGrayPng(std::string(AULA_MAPS_DIR) + "/cityLarge.png");
  if (map.empty()) throw std::runtime_error("build the maps first (target aula_maps)");
  return map;
}

// A city of blocks: 40 px blocks with 12 px roads, as dense as the real map, at any size.
cv::Mat proceduralCity(int size) {
  cv::Mat map(size, size, CV_8UC1, cv::Scalar(255));
  for (int y = 12; y + 40 < size; y += 52) {
    for (int x = 12; x + 40 < size; x += 52) cv::rectangle(map, cv::Rect(x, y, 40, 40), cv::Scalar(0), cv::FILLED);
  }
  cv::rectangle(map, cv::Rect(0, 0, size, size), cv::Scalar(0), 2);
  return map;
}

aula::teletaxi::Cell freeCorner(const aula::teletaxi::GradientField& f) {
  for (int d = 0; d < f.width(); ++d) {
    for (int y = 0; y <= d; ++y) {
      if (f.traversable(d, y)) return {d, y};
    }
  }
  return {0, 0};
}

void BM_GppField400City(benchmark::State& state) {
  aula::teletaxi::GradientField field(cityMap());
  const auto goal = freeCorner(field);  // a corner goal: the wavefront covers the whole city
  for (auto _ : state) benchmark::DoNotOptimize(field.compute(goal));
}
BENCHMARK(BM_GppField400City)->Unit(benchmark::kMillisecond);

void BM_GppPenalty400City(benchmark::State& state) {
  const cv::Mat map = cityMap();
  for (auto _ : state) {
    aula::teletaxi::GradientField field(map);
    benchmark::DoNotOptimize(field.width());
  }
}
BENCHMARK(BM_GppPenalty400City)->Unit(benchmark::kMillisecond);

void BM_GppField4000(benchmark::State& state) {
  aula::teletaxi::GradientField field(proceduralCity(4000));
  const auto goal = freeCorner(field);
  for (auto _ : state) benchmark::DoNotOptimize(field.compute(goal));
}
BENCHMARK(BM_GppField4000)->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace

BENCHMARK_MAIN();
