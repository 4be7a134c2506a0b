// Aula's plain WorldSpec of a Gazebo-style SDF world: from the parsed-world cache, else read by
// Aula's SDF reader (world_sdf.cpp).
#include "aula/world/world_spec.hpp"

#include "world_cache.hpp"
#include "world_sdf.hpp"

#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>
#include <aula/config/settings.hpp>

#include <cerrno>
#include <cmath>
#include <limits>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <set>
#include <stdexcept>
#include <algorithm>
#include <sstream>

namespace aula::world {

namespace {
std::string joined(const std::vector<std::string>& problems) {
  std::string text;
  for (const auto& p : problems) text += (text.empty() ? "" : "\n") + p;
  return text;
}
}  // namespace

WorldError::WorldError(const std::vector<std::string>& problems) : std::runtime_error(joined(problems)), problems_(problems) {}

std::string settingValue(const Destination& destination) {
  std::ostringstream value;
  value << destination.x_m << ", " << destination.y_m;
  return value.str();
}

const std::map<std::string, std::set<std::string>>& pluginKeys() {
  static const std::map<std::string, std::set<std::string>> keys = {
      {"pose3d", {"channel", "rate_hz"}},
      {"motors", {"channel", "max_v", "max_w", "holonomic", "watchdog_s", "kinematics", "wheelbase", "max_steer_rad",
                  "rear_axle_x"}},
      {"laser", {"channel", "pose", "samples", "min_angle", "max_angle", "min_range", "max_range", "rate_hz",
                 "noise_stddev"}},
      {"bumper", {"channel", "rate_hz", "side_threshold_rad"}},
  };
  return keys;
}

// Each plugin's type and keys are declared (pluginKeys): a misspelt <max_vel> is named with the
// key it is closest to, not silently left at its default.
void checkPluginKeys(const WorldSpec& spec, std::vector<std::string>& problems) {
  for (const auto& robot : spec.robots) {
    for (const auto& plugin : robot.plugins) {
      const std::string where = spec.source_path + ": model '" + robot.name + "', plugin '" + plugin.name + "': ";
      const auto declared = pluginKeys().find(plugin.type);
      if (declared == pluginKeys().end()) {
        std::string known;
        for (const auto& [type, keys] : pluginKeys()) known += (known.empty() ? "" : ", ") + type;
        problems.push_back(where + "unknown driver filename '" + plugin.type + "' (known: " + known + ")");
        continue;
      }
      for (const auto& [key, value] : plugin.params) {
        if (declared->second.count(key) != 0) continue;
        std::string best, keys;
        size_t best_distance = std::max<size_t>(3, key.size() / 3) + 1;
        for (const auto& k : declared->second) {
          keys += (keys.empty() ? "" : ", ") + k;
          if (config::editDistance(key, k) < best_distance) best_distance = config::editDistance(key, k), best = k;
        }
        problems.push_back(where + "unknown key <" + key + ">" + (best.empty() ? "" : " (did you mean <" + best + ">?)") +
                           "; a " + plugin.type + " plugin reads " + keys);
      }
    }
  }
}

namespace {
void checkPluginKeys(const WorldSpec& spec) {
  std::vector<std::string> problems;
  checkPluginKeys(spec, problems);
  if (!problems.empty()) throw WorldError(problems);
}
}  // namespace

namespace {
void requireDeclaredKey(const std::string& type, const std::string& key) {
  const auto declared = pluginKeys().find(type);
  if (declared != pluginKeys().end() && declared->second.count(key) == 0) {
    throw std::logic_error("plugin type '" + type + "' reads undeclared key '" + key + "' (world::pluginKeys)");
  }
}
}  // namespace

std::string PluginSpec::getString(const std::string& key, const std::string& fallback) const {
  requireDeclaredKey(type, key);
  const auto it = params.find(key);
  return it == params.end() ? fallback : it->second;
}

namespace {
[[noreturn]] void badParam(const PluginSpec& p, const std::string& key, const std::string& what) {
  throw WorldError("robot '" + p.owner + "', plugin '" + p.name + "': <" + key + ">" +
                   p.getString(key, "") + "</" + key + "> " + what);
}
}  // namespace

double PluginSpec::getDouble(const std::string& key, double fallback) const {
  requireDeclaredKey(type, key);
  if (!has(key)) return fallback;
  const std::string text = getString(key, "");
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || errno != 0 || end != text.c_str() + text.size() || !std::isfinite(v)) {
    badParam(*this, key, "is not a finite number");
  }
  return v;
}

int PluginSpec::getInt(const std::string& key, int fallback) const {
  requireDeclaredKey(type, key);
  if (!has(key)) return fallback;
  const std::string text = getString(key, "");
  errno = 0;
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || errno != 0 || end != text.c_str() + text.size() || v < -2147483647L || v > 2147483647L) {
    badParam(*this, key, "is not an integer");
  }
  return static_cast<int>(v);
}

bool PluginSpec::getBool(const std::string& key, bool fallback) const {
  requireDeclaredKey(type, key);
  if (!has(key)) return fallback;
  const std::string v = getString(key, "");
  if (v == "true" || v == "1") return true;
  if (v == "false" || v == "0") return false;
  badParam(*this, key, "is not a boolean (true/false)");
}

Eigen::Isometry3d PluginSpec::getPose(const std::string& key) const {
  requireDeclaredKey(type, key);
  std::istringstream in(getString(key, ""));
  double v[6];
  for (double& x : v) {
    if (!(in >> x) || !std::isfinite(x)) badParam(*this, key, "is not a pose 'x y z roll pitch yaw'");
  }
  std::string rest;
  if (in >> rest) badParam(*this, key, "is not a pose 'x y z roll pitch yaw'");
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
  pose.linear() = (Eigen::AngleAxisd(v[5], Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(v[4], Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(v[3], Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  return pose;
}

const PluginSpec* RobotSpec::findPlugin(const std::string& type) const {
  for (const auto& p : plugins) {
    if (p.type == type) return &p;
  }
  return nullptr;
}

const PluginSpec* RobotSpec::findPluginNamed(const std::string& plugin_name) const {
  for (const auto& p : plugins) {
    if (p.name == plugin_name) return &p;
  }
  return nullptr;
}

const RobotSpec* WorldSpec::findRobot(const std::string& robot) const {
  for (const auto& r : robots) {
    if (r.name == robot) return &r;
  }
  return nullptr;
}

std::pair<double, double> Shape::zRange(const Eigen::Isometry3d& pose) const {
  const double z = pose.translation().z();
  if (kind == ShapeKind::Mesh) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& v : mesh->vertices_m) {
      const double vz = (pose * v).z();
      lo = std::min(lo, vz);
      hi = std::max(hi, vz);
    }
    return {lo, hi};
  }
  const double half = kind == ShapeKind::Box ? box_size_m.z() / 2 : length_m / 2;
  return {z - half, z + half};
}

geometry::OrientedBox footprintOf(const StaticObject& o) {
  const Eigen::Vector3d c = o.pose.translation();
  const double yaw = yawOf(o.pose);
  switch (o.shape.kind) {
    case ShapeKind::Box:
      return {{c.x(), c.y(), yaw}, o.shape.box_size_m.x(), o.shape.box_size_m.y()};
    case ShapeKind::Cylinder:
      return {{c.x(), c.y(), yaw}, 2 * o.shape.radius_m, 2 * o.shape.radius_m};
    case ShapeKind::Mesh:
      break;
  }
  // The world vertices in the frame turned by the yaw about the origin: right for a mesh that is
  // rolled or pitched too (a y-up car turned upright).
  const double cs = std::cos(yaw), sn = std::sin(yaw);
  Eigen::AlignedBox2d box;
  for (const auto& v : o.shape.mesh->vertices_m) {
    const Eigen::Vector3d d = o.pose * v - c;
    box.extend(Eigen::Vector2d(cs * d.x() + sn * d.y(), -sn * d.x() + cs * d.y()));
  }
  const Eigen::Vector2d m = box.center();
  return {{c.x() + cs * m.x() - sn * m.y(), c.y() + sn * m.x() + cs * m.y(), yaw}, box.sizes().x(), box.sizes().y()};
}

double yawOf(const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d r = pose.linear();
  return std::atan2(r(1, 0), r(0, 0));
}


std::vector<std::string> modelSearchPath(const std::string& world_path) {
  std::vector<std::string> folders;
  // Aula's own first, then where Gazebo classic, Gazebo (gz-sim) and sdformat look: a teacher's
  // shell set up for Gazebo finds the same models.
  for (const char* variable : {"AULA_MODEL_PATH", "GAZEBO_MODEL_PATH", "GZ_SIM_RESOURCE_PATH", "SDF_PATH"}) {
    const char* env = std::getenv(variable);
    if (env == nullptr) continue;
    std::stringstream list(env);
    std::string folder;
    while (std::getline(list, folder, ':')) {
      if (!folder.empty() && std::find(folders.begin(), folders.end(), folder) == folders.end()) folders.push_back(folder);
    }
  }
  const auto slash = world_path.rfind('/');
  folders.push_back((slash == std::string::npos ? std::string(".") : world_path.substr(0, slash)) + "/models");
  try {
    folders.push_back(config::dataDir() + "/worlds/models");
  } catch (const config::ConfigError&) {
    // No installed data (a test binary with AULA_DATA_DIR unset): the other folders still count.
  }
  return folders;
}

WorldSpec loadWorld(const std::string& path, const std::vector<std::string>& model_path) {
  if (!std::ifstream(path).good()) throw WorldError(path + ": cannot open world file");
  const std::vector<std::string> folders = model_path.empty() ? modelSearchPath(path) : model_path;
  const std::string cache_key = worldCacheKey(path, folders);
  if (auto cached = readCachedWorld(cache_key)) {
    cached->source_path = path;  // as this caller named it
    checkPluginKeys(*cached);
    return *cached;
  }
  WorldSpec spec;
  std::vector<std::string> inputs, problems;
  readSdfWorld(path, folders, spec, inputs, problems);
  checkPluginKeys(spec, problems);  // every problem of the world at once, the reader's and the drivers'
  if (!problems.empty()) throw WorldError(problems);
  spec.sha256 = worldSha256(path, inputs);
  writeCachedWorld(cache_key, spec, inputs);
  return spec;
}

WorldFiles worldFilesOf(const std::string& path) {
  loadWorld(path);
  const std::string key = worldCacheKey(path, modelSearchPath(path));
  return {cachedInputs(key), entryName(key)};
}

const RobotSpec& requireRobot(const WorldSpec& world, const std::string& name) {
  if (const RobotSpec* robot = world.findRobot(name)) return *robot;
  std::string names;
  for (const auto& r : world.robots) names += (names.empty() ? "" : ", ") + r.name;
  throw WorldError(world.source_path + ": no robot named '" + name + "' (robots: " +
                          (names.empty() ? "none" : names) + ")");
}

std::string channelOf(const RobotSpec& robot, const std::string& type, const std::string& name) {
  for (const auto& plugin : robot.plugins) {
    if (plugin.type == type && (name.empty() || plugin.name == name)) {
      const std::string channel = plugin.getString("channel", "");
      if (channel.empty()) {
        throw WorldError("robot '" + robot.name + "', plugin '" + plugin.name + "': no <channel>");
      }
      return channel;
    }
  }
  throw WorldError("robot '" + robot.name + "' has no " + type + " plugin" +
                          (name.empty() ? "" : " named '" + name + "'") + ", which this exercise needs");
}

}  // namespace aula::world
