// One 180-beam, 180-degree laser scan with the analytic ray caster, as the laser driver casts it.
#include <aula/geometry/raycaster2d.hpp>
#include <aula/world/obstacle_slice.hpp>
#include <aula/world/world_spec.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

namespace {

void scanWorld(benchmark::State& state, const std::string& world_file, double z_m, double range_m,
               Eigen::Vector2d origin, double cell_m) {
  const auto spec = aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/" + world_file);
  const aula::geometry::Raycaster2D caster(aula::world::sliceAtHeight(spec, z_m), cell_m);
  aula::geometry::ScanRequest req;
  req.origin_m = origin;
  req.num_beams = 180;
  req.min_angle_rad = -M_PI / 2;
  req.angle_increment_rad = M_PI / 179;
  req.min_range_m = 0.08;
  req.max_range_m = range_m;
  float ranges[180];
  int i = 0;
  for (auto _ : state) {
    req.yaw_rad = 0.1 * (i++ % 63);  // sweep headings so the scan is not one lucky direction
    caster.scan(req, ranges);
    benchmark::DoNotOptimize(ranges);
  }
  state.counters["obstacles"] = static_cast<double>(caster.statics().rects.size() + caster.statics().circles.size());
}

// The roomba's laser at its start pose in the house.
void BM_LaserHouse(benchmark::State& state) {
  scanWorld(state, "vacuum.world", 0.075, 10.0, {-0.861, 1.5}, state.range(0) / 100.0);
}
BENCHMARK(BM_LaserHouse)->Arg(25)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);

// The same scans beam by beam through cast(): the cell walk each beam's range must equal (tests/unit/geometry,
// Raycaster2DScan), for comparison.
void BM_LaserHouseWalk(benchmark::State& state) {
  const auto spec = aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world");
  const aula::geometry::Raycaster2D caster(aula::world::sliceAtHeight(spec, 0.075));
  const Eigen::Vector2d origin(-0.861, 1.5);
  float ranges[180];
  int i = 0;
  for (auto _ : state) {
    const double yaw_rad = 0.1 * (i++ % 63);
    for (int b = 0; b < 180; ++b) {
      const double angle = yaw_rad + -M_PI / 2 + b * (M_PI / 179);
      ranges[b] = static_cast<float>(std::clamp(caster.cast(origin, angle, 10.0), 0.08, 10.0));
    }
    benchmark::DoNotOptimize(ranges);
  }
}
BENCHMARK(BM_LaserHouseWalk)->Unit(benchmark::kMicrosecond);

// Brute force over every primitive, for comparison.
void BM_LaserHouseBruteForce(benchmark::State& state) {
  const auto spec = aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world");
  const auto obstacles = aula::world::sliceAtHeight(spec, 0.075);
  const aula::geometry::Raycaster2D empty;
  aula::geometry::ScanRequest req;
  req.origin_m = {-0.861, 1.5};
  req.num_beams = 180;
  req.min_angle_rad = -M_PI / 2;
  req.angle_increment_rad = M_PI / 179;
  req.min_range_m = 0.08;
  req.max_range_m = 10.0;
  float ranges[180];
  for (auto _ : state) {
    empty.scan(req, ranges, &obstacles);
    benchmark::DoNotOptimize(ranges);
  }
}
BENCHMARK(BM_LaserHouseBruteForce)->Unit(benchmark::kMicrosecond);

// The city from the taxi's start, 10 m and 80 m range.
void BM_LaserCity(benchmark::State& state) {
  scanWorld(state, "cityLarge.world", 0.5, static_cast<double>(state.range(0)), {0.0, 0.0}, 4.0);
}
BENCHMARK(BM_LaserCity)->Arg(10)->Arg(80)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
