// The drivers of the types world::pluginKeys declares, by the name used in <plugin filename="...">.
#include "aula/drivers/driver.hpp"

#include "bumper_driver.hpp"
#include "laser_driver.hpp"
#include "motors_driver.hpp"
#include "pose3d_driver.hpp"

namespace aula::drivers {

std::vector<std::string> driverTypes() {
  std::vector<std::string> types;
  for (const auto& [type, keys] : world::pluginKeys()) types.push_back(type);
  return types;
}

uint64_t deviceSeed(uint64_t run_seed, const world::PluginSpec& plugin) {
  uint64_t h = 1469598103934665603ull ^ run_seed;  // FNV-1a over "robot/plugin"
  for (char c : plugin.owner + "/" + plugin.name) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  return h;
}

std::unique_ptr<Driver> makeDriver(const std::string& type) {
  if (type == "pose3d") return std::make_unique<Pose3dDriver>();
  if (type == "motors") return std::make_unique<MotorsDriver>();
  if (type == "laser") return std::make_unique<LaserDriver>();
  if (type == "bumper") return std::make_unique<BumperDriver>();
  std::string known;
  for (const auto& t : driverTypes()) known += (known.empty() ? "" : ", ") + t;
  throw world::WorldError("unknown driver type '" + type + "' (known: " + known + ")");
}

}  // namespace aula::drivers
