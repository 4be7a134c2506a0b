#pragma once
// A world as Aula sees it once the SDF is read: static primitives, robots and the drivers
// declared on them. Plain data, no sdformat or DART types, so that the simulator, the map
// generator, the laser caster and the referees all share one description.

#include <aula/config/no_dangling.hpp>
#include <aula/geometry/oriented_box.hpp>
#include <aula/world/mesh.hpp>

#include <Eigen/Geometry>

#include <map>
#include <set>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace aula::world {

// Malformed or unreadable world: the message names the file (and element) and what is wrong.
// A world read in one pass may have several problems: what() lists them one per line, and
// problems() gives them one by one.
class WorldError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  explicit WorldError(const std::vector<std::string>& problems);
  std::vector<std::string> problems() const { return problems_.empty() ? std::vector<std::string>{what()} : problems_; }

 private:
  std::vector<std::string> problems_;
};

enum class ShapeKind { Box, Cylinder, Mesh };

struct Shape {
  ShapeKind kind = ShapeKind::Box;
  Eigen::Vector3d box_size_m = Eigen::Vector3d::Zero();  // Box: full extents along local x, y, z
  double radius_m = 0.0;                                 // Cylinder: axis along local z
  double length_m = 0.0;                                 // Cylinder
  MeshSource mesh_source;                                // Mesh: what the <mesh> says
  std::shared_ptr<const TriangleMesh> mesh;              // Mesh: its triangles, in the shape's frame

  // The heights (world z) the shape spans at `pose` (a tilted box or cylinder: those of its
  // upright self; a mesh: its vertices').
  std::pair<double, double> zRange(const Eigen::Isometry3d& pose) const;
};

// One collision primitive of a static model, already in world coordinates.
struct StaticObject {
  std::string name;                                // "model::link::collision"
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // world pose of the shape centre (a mesh: its frame)
  Shape shape;
};

// The rectangle a static object covers seen from above, turned by its yaw: a box's footprint, a
// cylinder's bounding square, a mesh's bounding rectangle in its own frame (a parked-car mesh).
geometry::OrientedBox footprintOf(const StaticObject& object);

// A driver declared on a robot with <plugin name="..." filename="TYPE">, Gazebo style.
// Every child element of <plugin> is kept as text in params (e.g. "channel" -> "ROOMBA_LASER").
struct PluginSpec {
  std::string name;   // instance name, unique on the robot
  std::string type;   // driver type: pose3d, motors, laser, bumper
  std::map<std::string, std::string> params;

  bool has(const std::string& key) const { return params.count(key) != 0; }
  // Typed reads; throw WorldError naming robot/plugin/key when a value does not parse.
  std::string getString(const std::string& key, const std::string& fallback) const;
  double getDouble(const std::string& key, double fallback) const;
  int getInt(const std::string& key, int fallback) const;
  bool getBool(const std::string& key, bool fallback) const;
  // "x y z roll pitch yaw" (SDF pose syntax), relative to the robot body frame.
  Eigen::Isometry3d getPose(const std::string& key) const;

  std::string owner;  // robot name, for error messages
};

// The one registry of driver types, by <plugin filename="TYPE">, and the SDF keys each reads
// (drivers/ makes a driver of each type; each documents its keys at the top of its file).
// loadWorld refuses any other type or key, naming it; reading an undeclared key is a
// std::logic_error (a driver and this table disagree).
const std::map<std::string, std::set<std::string>>& pluginKeys();

// A mobile robot: one rigid body moving in the plane, driven by its motors plugin.
struct RobotSpec {
  std::string name;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // initial world pose of the body frame
  double mass_kg = 1.0;
  Shape shape;                                             // collision shape of the body
  Eigen::Isometry3d shape_offset = Eigen::Isometry3d::Identity();  // shape pose in body frame
  std::vector<PluginSpec> plugins;

  const PluginSpec* findPlugin(const std::string& type) const;
  const PluginSpec* findPluginNamed(const std::string& name) const;
};

// A place a world declares for its exercise to drive to (TeleTaxi), under <world>:
//   <aula:destination name="plaza">-40 40</aula:destination>   (x y, m)
struct Destination {
  std::string name;
  double x_m = 0.0, y_m = 0.0;
};

// The destination as a setting's value ("-40, 40": <Section>.Destination).
std::string settingValue(const Destination& destination);

struct WorldSpec {
  std::string name;
  std::string source_path;
  std::string sha256;           // of every file the world is read from (worldSha256): reports name exactly what ran
  double physics_step_s = 0.0;  // <physics><max_step_size>; 0 when the world does not say
  std::vector<StaticObject> statics;
  std::vector<RobotSpec> robots;
  std::vector<Destination> destinations;  // in the file's order; names unique
  // What the files say that Aula does not simulate (lights, sky, GUI, world plugins, visuals...),
  // one line per kind: "<light> x2 (world.sdf:5, ...): Aula draws no lights". Listed, never silent.
  std::vector<std::string> skipped;

  const RobotSpec* findRobot(const std::string& name) const;
};

// Where `model://NAME` includes are looked for, in order: the folders of $AULA_MODEL_PATH, then
// Gazebo's $GAZEBO_MODEL_PATH, $GZ_SIM_RESOURCE_PATH and $SDF_PATH (each colon-separated), the
// "models" folder beside the world file, <data folder>/worlds/models.
std::vector<std::string> modelSearchPath(const std::string& world_path);

// Reads an SDF world with Aula's reader (world_sdf.cpp). `model://NAME` includes resolve through
// `model_path` (default: modelSearchPath(path)). Throws WorldError listing every problem found.
// Static models: every box, cylinder and mesh collision becomes a StaticObject (nested models
// flattened; <plane> collisions, i.e. a Gazebo ground plane, are skipped; any other geometry is
// a problem). Non-static models with Aula's drivers are robots: one link, one box/cylinder
// collision, mass > 0, plugins whose filename is a known driver type (pose3d, motors, laser,
// bumper); with a Gazebo drive plugin (planar move, diff drive, Ackermann...), Aula's robot of that
// kind (world_sdf.cpp); with neither, static geometry kept still. Poses are raw SDF poses composed
// parent * child; `relative_to` is read inside a model only. physics_step_s is set only when the
// file states <physics><max_step_size>. What is not simulated is listed in `skipped`.
WorldSpec loadWorld(const std::string& path, const std::vector<std::string>& model_path = {});

// What a process that loads the world at `path` reads: the world file and every model file it
// includes (`inputs`, as the parsed-world cache lists them) and that cache's entry for it
// (`cache_entry`, relative to the cache folder: "worlds/<key>.txt"). Loads the world first, so
// the entry exists. A sandbox binds exactly these (aula_supervision). Throws WorldError.
struct WorldFiles {
  std::vector<std::string> inputs;
  std::string cache_entry;
};
WorldFiles worldFilesOf(const std::string& path);

// SHA-256 in lowercase hex, of bytes and of a file's content (WorldError if unreadable).
std::string sha256Hex(const std::string& bytes);
std::string sha256OfFile(const std::string& path);
// A world's identity: the SHA-256 of the world file alone when it includes nothing, else of the
// world file's hash followed by every included file's (model.config, model.sdf, ...), sorted, so
// that a fixed model changes the hash wherever the files lie. `inputs`: every file read.
std::string worldSha256(const std::string& world_path, const std::vector<std::string>& inputs);

// The robot `name` of a world, or a WorldError naming the world and the robots it has (a reference
// into `world`, never into `name`).
AULA_NO_DANGLING const RobotSpec& requireRobot(const WorldSpec& world, const std::string& name);
// The channel of the robot's plugin of `type` (and instance name, when given), or a WorldError
// saying what the exercise needs from the robot. Robot channels are named here, in the world.
std::string channelOf(const RobotSpec& robot, const std::string& type, const std::string& name = "");

// Extracts the yaw of a pose (rotation about world z).
double yawOf(const Eigen::Isometry3d& pose);

}  // namespace aula::world
