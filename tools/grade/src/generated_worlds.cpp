#include "aula/grade/generated_worlds.hpp"

#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>
#include <aula/process/child_process.hpp>
#include <aula/settings/tables.hpp>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace aula::grade {
namespace fs = std::filesystem;
using config::ConfigError;

namespace {

// SplitMix64: the parameters of world `index` of seed `seed`, the same on every machine (no
// standard distribution, whose results the library may choose).
uint64_t mix(uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// A number in [low, high] on a grid of `steps`, from the draw's bits.
double within(uint64_t draw, double low, double high, int steps) {
  return low + (high - low) * static_cast<double>(draw % static_cast<uint64_t>(steps + 1)) / steps;
}

std::string decimal(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

// The exercise's own way of generating worlds (its declaration's WorldGenerator); nullptr if none.
const settings::WorldGenerator* generatorOfExercise(const std::string& exercise) {
  const settings::Exercise* ex = settings::exerciseNamed(exercise);
  return ex != nullptr && ex->generator ? &*ex->generator : nullptr;
}


void runTool(const std::vector<std::string>& argv, const std::string& log, const std::string& what) {
  process::ChildProcess child(argv, log, log);
  const auto code = child.wait(std::chrono::seconds(120));
  if (code != 0) {
    std::ifstream in(log);
    const std::string said((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    throw std::runtime_error(what + " failed (" + (code ? "exit " + std::to_string(*code) : std::string("timed out")) +
                             "): " + said);
  }
}

}  // namespace

std::string generatedWorldKinds() {
  std::string out;
  for (const auto& ex : settings::exercises()) {
    if (ex.generator) out += (out.empty() ? "" : ", ") + ex.generator->kind + " for " + ex.name;
  }
  return out;
}

bool isGenerateItem(const std::string& item) { return item.rfind("generate:", 0) == 0; }

WorldsToGenerate parseGenerate(const std::string& item, const std::string& seed_item, const std::string& exercise) {
  const std::string usage = "--worlds=" + item + (seed_item.empty() ? "" : "," + seed_item) +
                            ": expected generate:KIND:N[,seed=S] (" + generatedWorldKinds() + "; N from 1 to 100)";
  WorldsToGenerate what;
  const std::string rest = item.substr(std::string("generate:").size());
  const auto colon = rest.find(':');
  if (colon == std::string::npos) throw ConfigError(usage);
  what.kind = rest.substr(0, colon);
  try {
    size_t used = 0;
    what.count = std::stoi(rest.substr(colon + 1), &used);
    if (used != rest.size() - colon - 1) what.count = 0;
    if (!seed_item.empty()) {
      if (seed_item.rfind("seed=", 0) != 0) throw ConfigError(usage);
      what.seed = std::stoll(seed_item.substr(5), &used);
      if (used != seed_item.size() - 5) throw ConfigError(usage);
    }
  } catch (const std::logic_error&) {
    throw ConfigError(usage);
  }
  if (what.count < 1 || what.count > 100) throw ConfigError(usage);
  const settings::WorldGenerator* own = generatorOfExercise(exercise);
  if (own == nullptr || own->kind != what.kind) {
    for (const auto& ex : settings::exercises()) {  // another exercise's kind: say whose
      if (ex.generator && ex.generator->kind == what.kind) {
        throw ConfigError("--worlds=" + item + ": a " + what.kind + " is a world of " + ex.name + ", not of " + exercise);
      }
    }
    throw ConfigError(usage);
  }
  what.script = own->script;
  what.map_resolution_m = own->map_resolution_m;
  return what;
}

std::vector<std::string> generatorArguments(const WorldsToGenerate& what, int index) {
  const uint64_t base = mix(static_cast<uint64_t>(what.seed) * 1000003ull + static_cast<uint64_t>(index));
  auto draw = [&](int k) { return mix(base + static_cast<uint64_t>(k)); };
  const std::string generator_seed = std::to_string(1 + draw(0) % 1000000);
  if (what.kind == "house") {
    const int rooms_x = 2 + static_cast<int>(draw(1) % 3), rooms_y = 1 + static_cast<int>(draw(2) % 3);
    const int room_i = static_cast<int>(draw(3) % rooms_x), room_j = static_cast<int>(draw(4) % rooms_y);
    const double yaw = within(draw(5), -3.14, 3.14, 8);
    return {"--seed", generator_seed, "--rooms-x", std::to_string(rooms_x), "--rooms-y", std::to_string(rooms_y),
            "--furniture", std::to_string(1 + draw(6) % 3), "--start-room",
            std::to_string(room_i) + "," + std::to_string(room_j) + "," + decimal(yaw)};
  }
  if (what.kind == "city") {  // graded over the two crossings it declares as destinations
    const int blocks = 2 + static_cast<int>(draw(1) % 3);
    return {"--seed", generator_seed, "--blocks", std::to_string(blocks), "--road-width", decimal(within(draw(2), 10.0, 16.0, 6)),
            "--size", decimal(within(draw(3), 200.0, 320.0, 6)), "--destinations", "2"};
  }
  const char* neighbours[] = {"car", "van", "small"};
  const double car_length_m = 4.0;  // the car that parks (4 x 2 m)
  return {"--slot-length", decimal(car_length_m * within(draw(1), 1.3, 2.0, 14)),
          "--curb-offset", decimal(within(draw(2), -1.0, 1.0, 8)),
          "--rear-neighbour", neighbours[draw(3) % 3], "--front-neighbour", neighbours[draw(4) % 3],
          "--start", decimal(within(draw(5), -9.0, -5.0, 8)) + "," + decimal(within(draw(6), 2.0, 3.0, 4)) + ",0"};
}

std::vector<std::string> generateWorlds(const WorldsToGenerate& what, const std::string& out_dir, const std::string& python,
                                        const std::string& mapgen) {
  const fs::path folder = fs::path(out_dir) / "worlds";
  fs::create_directories(folder);
  const std::string generator = config::dataDir() + "/worlds/tools/" + what.script;
  std::vector<std::string> worlds;
  for (int index = 1; index <= what.count; ++index) {
    const std::string name = what.kind + "-seed" + std::to_string(what.seed) + "-" + std::to_string(index);
    const std::string world = (folder / (name + ".world")).string();
    std::vector<std::string> argv = {python, generator, "--out", world};
    for (const std::string& argument : generatorArguments(what, index)) argv.push_back(argument);
    const std::string log = (folder / (name + ".log")).string();
    runTool(argv, log, what.script + " for " + name);
    runTool({mapgen, world, "--out", (folder / (name + ".png")).string(), "--resolution", decimal(what.map_resolution_m)},
            log, "aula-mapgen for " + name);
    fs::remove(log);
    worlds.push_back(world);
  }
  return worlds;
}

}  // namespace aula::grade
