// Reading a world's SDF, three ways (docs/performance.md, "Reading SDF"): Aula's reader on
// tinyxml2 (what loadWorld does on a cache miss), the parsed-world cache's hit (what every other
// start does: the entry read and each input file's SHA-256 checked), and, where libsdformat 12 is
// (Debian 12), the libsdformat reader Aula had before (tests/unit/world/sdformat_oracle.cpp).
//   build/bin/bench_sdf_reader --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "world_sdf.hpp"

#include <aula/world/world_spec.hpp>
#ifdef AULA_BENCH_SDFORMAT
#include "sdformat_oracle.hpp"
#endif

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>

#include <unistd.h>

namespace {

std::string worldPath(const char* file) { return std::string(AULA_SOURCE_DIR) + "/worlds/" + file; }

using Parse = void (*)(const std::string&, const std::vector<std::string>&, aula::world::WorldSpec&,
                      std::vector<std::string>&);

// A parse of the world file with no cache: Aula's reader, or libsdformat's.
void BM_Parse(benchmark::State& state, Parse parse, const char* file) {
  const std::string path = worldPath(file);
  const auto folders = aula::world::modelSearchPath(path);
  for (auto _ : state) {
    aula::world::WorldSpec spec;
    std::vector<std::string> inputs;
    parse(path, folders, spec, inputs);
    benchmark::DoNotOptimize(spec);
  }
}

void BM_CacheHit(benchmark::State& state, const char* file) {
  const std::string cache = std::filesystem::temp_directory_path() / ("aula-bench-sdf-" + std::to_string(::getpid()));
  setenv("XDG_CACHE_HOME", cache.c_str(), 1);
  const std::string path = worldPath(file);
  aula::world::loadWorld(path);  // the entry
  for (auto _ : state) benchmark::DoNotOptimize(aula::world::loadWorld(path));
  std::filesystem::remove_all(cache);
}

}  // namespace

BENCHMARK_CAPTURE(BM_Parse, aula_city, &aula::world::parseSdfWorld, "cityLarge.world")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Parse, aula_house, &aula::world::parseSdfWorld, "vacuum.world")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Parse, aula_street, &aula::world::parseSdfWorld, "autopark.world")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_CacheHit, city, "cityLarge.world")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_CacheHit, house, "vacuum.world")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_CacheHit, street, "autopark.world")->Unit(benchmark::kMillisecond);
#ifdef AULA_BENCH_SDFORMAT
BENCHMARK_CAPTURE(BM_Parse, sdformat_city, &aula::world::oracle::parseWithSdformat, "cityLarge.world")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Parse, sdformat_house, &aula::world::oracle::parseWithSdformat, "vacuum.world")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Parse, sdformat_street, &aula::world::oracle::parseWithSdformat, "autopark.world")->Unit(benchmark::kMillisecond);
#endif
BENCHMARK_MAIN();
