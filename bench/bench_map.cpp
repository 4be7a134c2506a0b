// What a process pays at start for its world: reading the SDF (cached per user) and drawing the
// occupancy map from it (aula_world), for the city and the house. Maps are cached per user,
// so the raster is paid once per world content; the SDF read every start.
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include <benchmark/benchmark.h>

namespace {

void BM_LoadWorld(benchmark::State& state, const char* file) {
  const std::string path = std::string(AULA_SOURCE_DIR) + "/worlds/" + file;
  for (auto _ : state) benchmark::DoNotOptimize(aula::world::loadWorld(path));
}

void BM_RasterizeMap(benchmark::State& state, const char* file, double resolution_m, double z_min_m, double z_max_m) {
  const auto spec = aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/" + file);
  const auto transform = aula::world::fitTransform(spec, resolution_m);
  for (auto _ : state) benchmark::DoNotOptimize(aula::world::rasterizeOccupancy(spec, transform, z_min_m, z_max_m));
  state.counters["pixels"] = static_cast<double>(transform.width_px) * transform.height_px;
}

}  // namespace

BENCHMARK_CAPTURE(BM_LoadWorld, city, "cityLarge.world")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadWorld, house, "vacuum.world")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RasterizeMap, city, "cityLarge.world", 1.25, 0.01, 100.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RasterizeMap, house, "vacuum.world", 0.02, 0.005, 0.09)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
