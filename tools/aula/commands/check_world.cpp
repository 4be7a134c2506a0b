// aula check-world FILE: what a teacher runs on a new world: its facts, and what each exercise
// would miss in it.
#include "commands.hpp"
#include "run_settings.hpp"

#include <aula/config/paths.hpp>
#include <aula/image/png.hpp>
#include <aula/scoring/parking_geometry.hpp>
#include <aula/settings/tables.hpp>
#include <aula/world/car_kinematics.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include <algorithm>
#include <iostream>
#include <sstream>

namespace aula::commands {
namespace {
using config::Config;

std::string shapeText(const world::Shape& shape) {
  std::ostringstream text;
  if (shape.kind == world::ShapeKind::Cylinder) {
    text << "cylinder, radius " << shape.radius_m << " m, " << shape.length_m << " m high";
  } else {
    text << "box " << shape.box_size_m.x() << " x " << shape.box_size_m.y() << " x " << shape.box_size_m.z() << " m";
  }
  return text.str();
}

void printWorld(const world::WorldSpec& spec) {
  std::cout << "world '" << spec.name << "': " << spec.source_path << "\n  sha256 " << spec.sha256 << "\n";
  if (spec.physics_step_s > 0) {
    std::cout << "  <physics><max_step_size> " << spec.physics_step_s * 1e3
              << " ms: not used; each exercise steps at its own (Simulator.PhysicsStep)\n";
  }
  if (!spec.statics.empty()) {
    const Eigen::Vector4d b = world::staticBounds(spec);
    std::cout << "  " << spec.statics.size() << " static primitives, x [" << b[0] << ", " << b[2] << "] y [" << b[1]
              << ", " << b[3] << "] m\n";
    for (const auto& o : spec.statics) {
      if (o.shape.kind != world::ShapeKind::Mesh) continue;
      const auto [z0, z1] = o.shape.zRange(o.pose);
      std::cout << "  mesh '" << o.name << "': " << o.shape.mesh_source.file << ", " << o.shape.mesh->triangles.size()
                << " triangles, z [" << z0 << ", " << z1 << "] m\n";
    }
  }
  if (!spec.skipped.empty()) {
    std::cout << "  read as Gazebo would, but not simulated by Aula (skipped):\n";
    for (const auto& line : spec.skipped) std::cout << "    " << line << "\n";
  }
  for (const auto& robot : spec.robots) {
    const Eigen::Vector3d p = robot.pose.translation();
    std::cout << "robot '" << robot.name << "' at (" << p.x() << ", " << p.y() << "), yaw " << world::yawOf(robot.pose)
              << " rad, " << robot.mass_kg << " kg\n";
    const Eigen::Vector3d c = robot.shape_offset.translation();
    std::cout << "  shape: " << shapeText(robot.shape) << ", centre (" << c.x() << ", " << c.y() << ", " << c.z() << ") in its frame\n";
    for (const auto& plugin : robot.plugins) {
      std::cout << "  " << plugin.type << " '" << plugin.name << "' on " << plugin.getString("channel", "(no channel)");
      if (plugin.type == "motors" && plugin.getString("kinematics", "diff") == "ackermann") {
        const world::CarKinematics car = world::readCarKinematics(plugin);
        std::cout << ": a car, wheelbase " << car.wheelbase_m << " m, max steer " << car.max_steer_rad << " rad (turning radius "
                  << car.min_turn_radius_m << " m), rear axle at x " << car.rear_axle_x_m << " m";
      }
      std::cout << "\n";
    }
  }
}

// What `ex` would miss in `spec` with its default settings: its robot, the plugins it needs,
// a start on free floor of its map.
std::vector<std::string> exerciseProblems(const settings::Exercise& ex, const world::WorldSpec& spec) {
  const Config cfg = ex.component_settings->resolve(Config());
  const std::string robot_key = ex.section + ".Robot";
  const world::RobotSpec* robot = exerciseRobot(ex, spec, cfg.getString(robot_key));
  if (robot == nullptr) return {"a robot named '" + cfg.getString(robot_key) + "' (" + robot_key + ")"};
  if (robot->name != cfg.getString(robot_key)) {
    std::cout << ex.name << ": the robot is '" << robot->name << "', the world's only one with the exercise's plugins ("
              << robot_key << " = " << cfg.getString(robot_key) << " is not in the world)\n";
  }
  std::vector<std::string> missing = missingPlugins(ex, *robot);
  if (ex.referee_scene == "parking_street") {  // the referee's street: its curb and parked cars
    try {
      scoring::ParkingScene::fromWorld(spec, robot->name, scoring::sceneNamesOf(ex.referee_settings->resolve(Config())));
    } catch (const world::WorldError& e) {
      missing.push_back(std::string("its street for the referee: ") + e.what());
    }
  }
  try {
    checkPointsOnTheMap(ex, cfg, spec);
  } catch (const config::ConfigError& e) {
    missing.push_back(std::string("its points on free floor: ") + e.what());
  }
  if (cfg.has(ex.section + ".Map.Resolution") && !spec.statics.empty()) {
    const auto z = cfg.getDoubleList(ex.section + ".Map.ZBand");
    const auto map = world::occupancyMapOf(spec, {cfg.getDouble(ex.section + ".Map.Resolution"), z[0], z[1]});
    const Eigen::Vector3d p = robot->pose.translation();
    if (const auto problem = world::pointProblem(map, p.x(), p.y())) missing.push_back("a start on free floor: " + *problem);
  }
  return missing;
}

void writeMap(const world::WorldSpec& spec, const std::string& png) {
  const Eigen::Vector4d b = world::staticBounds(spec);
  const double resolution_m = std::max(0.01, std::max(b[2] - b[0], b[3] - b[1]) / 1000.0);
  const auto map = world::occupancyMapOf(spec, {resolution_m, 0.01, 100.0});
  if (!image::writePng(png, map.image)) throw config::ConfigError("--map=" + png + ": cannot write");
  std::cout << "map: " << png << " (" << map.image.cols << " x " << map.image.rows << " px, " << resolution_m
            << " m/px; black = what a robot touches)\n";
}

// Exit 1 when the exercise asked for (--exercise), or every exercise, cannot run on the world:
// a teacher's script stops there.
int checkWorldFile(const cli::Arguments& args) {
  if (args.given("exercise")) {
    const settings::Exercise* asked = settings::exerciseNamed(args.text("exercise"));
    if (asked == nullptr || asked->referee_settings == nullptr) {
      throw config::ConfigError("aula check-world: --exercise=" + args.text("exercise") + ": " + settings::exerciseNames(false));
    }
  }
  const std::string path = config::resolveWorldPath(args.positional(0), "aula check-world FILE");
  world::WorldSpec spec;
  try {
    spec = world::loadWorld(path);
  } catch (const world::WorldError& e) {  // every problem of the world, each on its line, in one pass
    const auto problems = e.problems();
    std::cerr << "aula check-world: " << path << " cannot be read: " << problems.size() << " problem"
              << (problems.size() == 1 ? "" : "s") << "\n";
    for (const auto& problem : problems) std::cerr << "  " << problem << "\n";
    return 2;
  }
  printWorld(spec);
  bool asked_ok = !args.given("exercise"), any_ok = false;
  for (const auto& ex : settings::exercises()) {
    if (ex.referee_settings == nullptr) continue;
    if (args.given("exercise") && ex.name != args.text("exercise")) continue;
    const auto missing = exerciseProblems(ex, spec);
    any_ok = any_ok || missing.empty();
    if (args.given("exercise")) asked_ok = missing.empty();
    std::cout << ex.name << ": " << (missing.empty() ? "ok" : "cannot run; the world needs");
    for (size_t i = 0; i < missing.size(); ++i) std::cout << (i ? "; " : " ") << missing[i];
    std::cout << "\n";
  }
  if (args.given("map")) writeMap(spec, args.text("map"));
  return asked_ok && any_ok ? 0 : 1;
}

}  // namespace

cli::Command checkWorld() {
  cli::Command c("check-world", "load a world, list its robots, sensors and channels, and say what each exercise would miss");
  c.positionals = {{"FILE", "an SDF world file"}};
  c.options.add(cli::valueOption("map", "FILE.png", "also draw the world's map from above (black: what a robot touches)"))
      .add(cli::valueOption("exercise", "NAME", "check only this exercise (" + settings::exerciseNames(false) + ")"));
  c.details = "exit status: 0 when the world suits --exercise (without it: at least one exercise), 1 when it does not,\n"
              "2 when the world cannot be read\n";
  c.run = checkWorldFile;
  return c;
}

}  // namespace aula::commands
