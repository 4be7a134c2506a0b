// The SDF half of aula_world, a module of its own (libaula_world_sdf.so) that loadWorld opens
// only when the parsed-world cache has no entry: libsdformat 12 and ignition-math compile their
// std::regex globals when they are loaded, 115 ms of every process's start even when nothing is
// parsed (docs/performance.md). Reads Gazebo-style SDF worlds with libsdformat 12 into Aula's
// plain WorldSpec. Poses are composed as model * link * collision (raw poses; `relative_to` is
// not supported). Nested models of static models are flattened; <plane> collisions (ground) are
// ignored.
#include "world_sdf.hpp"

#include <sdf/Box.hh>
#include <sdf/Collision.hh>
#include <sdf/Cylinder.hh>
#include <sdf/Element.hh>
#include <sdf/Geometry.hh>
#include <sdf/Link.hh>
#include <sdf/Model.hh>
#include <sdf/ParserConfig.hh>
#include <sdf/Physics.hh>
#include <sdf/Root.hh>
#include <sdf/World.hh>
#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>

namespace aula::world {
namespace {

const std::set<std::string>& knownPluginTypes() {
  static const std::set<std::string> types = {"pose3d", "motors", "laser", "bumper"};
  return types;
}

Eigen::Isometry3d toEigen(const ignition::math::Pose3d& p) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translation() = Eigen::Vector3d(p.Pos().X(), p.Pos().Y(), p.Pos().Z());
  out.linear() = Eigen::Quaterniond(p.Rot().W(), p.Rot().X(), p.Rot().Y(), p.Rot().Z())
                     .normalized()
                     .toRotationMatrix();
  return out;
}

// Raw pose of a model, link or collision; `relative_to` frames are not supported (say so).
template <typename T>
Eigen::Isometry3d poseOf(const T& element, const std::string& where) {
  if (!element.PoseRelativeTo().empty()) {
    throw WorldError(where + ": <pose relative_to=\"" + element.PoseRelativeTo() +
                     "\"> is not supported; give poses relative to the parent element");
  }
  return toEigen(element.RawPose());
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// Box or cylinder collision geometry; WorldError for anything else.
Shape shapeOf(const sdf::Collision& collision, const std::string& where) {
  const sdf::Geometry* geom = collision.Geom();
  Shape shape;
  if (geom != nullptr && geom->Type() == sdf::GeometryType::BOX && geom->BoxShape() != nullptr) {
    const auto size = geom->BoxShape()->Size();
    shape.kind = ShapeKind::Box;
    shape.box_size_m = Eigen::Vector3d(size.X(), size.Y(), size.Z());
    if (!(shape.box_size_m.minCoeff() > 0)) throw WorldError(where + ": box <size> must be positive");
    return shape;
  }
  if (geom != nullptr && geom->Type() == sdf::GeometryType::CYLINDER && geom->CylinderShape() != nullptr) {
    shape.kind = ShapeKind::Cylinder;
    shape.radius_m = geom->CylinderShape()->Radius();
    shape.length_m = geom->CylinderShape()->Length();
    if (!(shape.radius_m > 0 && shape.length_m > 0)) {
      throw WorldError(where + ": cylinder <radius> and <length> must be positive");
    }
    return shape;
  }
  throw WorldError(where + ": only <box> and <cylinder> collision geometry is supported");
}

std::vector<PluginSpec> pluginsOf(const sdf::Model& model, const std::string& file) {
  std::vector<PluginSpec> plugins;
  sdf::ElementPtr element = model.Element();
  if (!element || !element->HasElement("plugin")) return plugins;
  for (sdf::ElementPtr p = element->GetElement("plugin"); p; p = p->GetNextElement("plugin")) {
    PluginSpec spec;
    spec.owner = model.Name();
    spec.name = p->Get<std::string>("name");
    spec.type = p->Get<std::string>("filename");
    const std::string where = file + ": model '" + model.Name() + "', plugin '" + spec.name + "'";
    if (knownPluginTypes().count(spec.type) == 0) {
      std::string known;
      for (const auto& t : knownPluginTypes()) known += (known.empty() ? "" : ", ") + t;
      throw WorldError(where + ": unknown driver filename '" + spec.type + "' (known: " + known + ")");
    }
    for (const auto& other : plugins) {
      if (other.name == spec.name) throw WorldError(where + ": duplicate plugin name");
    }
    for (sdf::ElementPtr child = p->GetFirstElement(); child; child = child->GetNextElement()) {
      std::string text = child->GetValue() ? child->GetValue()->GetAsString() : "";
      spec.params[child->GetName()] = trim(text);
    }
    plugins.push_back(std::move(spec));
  }
  return plugins;
}

}  // namespace

namespace {

// Static geometry of a static model (and of its nested models), in world coordinates.
// <plane> collisions (a Gazebo ground plane) are skipped: Aula's physics keeps robots on the
// ground with a planar joint, and a ground would be an obstacle in every map.
void addStatics(const sdf::Model& model, const Eigen::Isometry3d& model_pose, const std::string& prefix,
                const std::string& file, WorldSpec& spec) {
  const std::string name = prefix + model.Name();
  const std::string where = file + ": model '" + name + "'";
  if (!pluginsOf(model, file).empty()) throw WorldError(where + ": a static model cannot carry drivers");
  for (uint64_t l = 0; l < model.LinkCount(); ++l) {
    const sdf::Link* link = model.LinkByIndex(l);
    const Eigen::Isometry3d link_pose = model_pose * poseOf(*link, where + ", link '" + link->Name() + "'");
    for (uint64_t c = 0; c < link->CollisionCount(); ++c) {
      const sdf::Collision* collision = link->CollisionByIndex(c);
      if (collision->Geom() != nullptr && collision->Geom()->Type() == sdf::GeometryType::PLANE) continue;
      StaticObject o;
      o.name = name + "::" + link->Name() + "::" + collision->Name();
      o.shape = shapeOf(*collision, where + ", link '" + link->Name() + "', collision '" + collision->Name() + "'");
      o.pose = link_pose * poseOf(*collision, where + ", collision '" + collision->Name() + "'");
      spec.statics.push_back(o);
    }
  }
  for (uint64_t n = 0; n < model.ModelCount(); ++n) {
    const sdf::Model* nested = model.ModelByIndex(n);
    addStatics(*nested, model_pose * poseOf(*nested, where + ", model '" + nested->Name() + "'"), name + "::",
               file, spec);
  }
}

// Malformed XML: sdformat only says "Unable to read file"; tinyxml2 gives the line.
void checkXml(const std::string& path) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS) {
    const char* detail = doc.ErrorStr();
    throw WorldError(path + ":" + std::to_string(doc.ErrorLineNum()) + ": malformed XML: " +
                     (detail != nullptr ? detail : "parse error"));
  }
}

}  // namespace

}  // namespace aula::world

extern "C" __attribute__((visibility("default"))) void aula_world_parse_sdf(const std::string& path, const std::vector<std::string>& folders,
                                     aula::world::WorldSpec& spec, std::vector<std::string>& inputs) {
  using namespace aula::world;
  checkXml(path);
  // model://NAME -> the first FOLDER/NAME with a model.config, Gazebo style (GAZEBO_MODEL_PATH).
  sdf::ParserConfig config;
  auto unresolved = std::make_shared<std::vector<std::string>>();
  auto included = std::make_shared<std::vector<std::string>>();  // model folders used: the cache's inputs
  config.SetFindCallback([folders, unresolved, included](const std::string& uri) -> std::string {
    const std::string name = uri.rfind("model://", 0) == 0 ? uri.substr(8) : uri;
    for (const auto& folder : folders) {
      const std::string candidate = folder + "/" + name;
      if (std::ifstream(candidate + "/model.config").good()) {
        included->push_back(candidate);
        return candidate;
      }
    }
    unresolved->push_back(uri);
    return "";  // sdformat reports it; the message below says where we looked
  });
  sdf::Root root;
  const sdf::Errors errors = root.Load(path, config);
  if (!errors.empty()) {
    std::string text = path + ": cannot load world (" + std::to_string(errors.size()) + " error" +
                       (errors.size() == 1 ? "" : "s") + "):";
    for (const auto& e : errors) {
      text += "\n  " + e.Message();
      if (e.FilePath().has_value() && *e.FilePath() != path) text += " [" + *e.FilePath() + "]";
      if (e.LineNumber().has_value()) text += " (line " + std::to_string(*e.LineNumber()) + ")";
    }
    for (const auto& uri : *unresolved) {
      const std::string name = uri.rfind("model://", 0) == 0 ? uri.substr(8) : uri;
      text += "\n  model '" + name + "' not found: looked for " + name + "/model.config in";
      for (const auto& folder : folders) text += " " + folder;
      text += " (add a folder with AULA_MODEL_PATH)";
    }
    throw WorldError(text);
  }
  if (root.WorldCount() != 1) throw WorldError(path + ": expected exactly one <world>");
  const sdf::World* world = root.WorldByIndex(0);

  spec.name = world->Name();
  spec.source_path = path;
  // sdformat adds a default <physics> (1 ms) to every world: only a step the file states counts.
  const sdf::ElementPtr physics = world->Element()->HasElement("physics") ? world->Element()->GetElement("physics") : nullptr;
  if (physics != nullptr && physics->GetExplicitlySetInFile() && physics->HasElement("max_step_size") &&
      physics->GetElement("max_step_size")->GetExplicitlySetInFile() && world->PhysicsCount() > 0) {
    spec.physics_step_s = world->PhysicsByIndex(0)->MaxStepSize();
  }

  for (uint64_t m = 0; m < world->ModelCount(); ++m) {
    const sdf::Model* model = world->ModelByIndex(m);
    const std::string where = path + ": model '" + model->Name() + "'";
    const Eigen::Isometry3d model_pose = poseOf(*model, where);
    if (model->Static()) {
      addStatics(*model, model_pose, "", path, spec);
      continue;
    }
    // A robot: one link, one collision, drivers as plugins.
    if (model->ModelCount() > 0) throw WorldError(where + ": a robot (non-static model) cannot nest models");
    if (model->LinkCount() != 1) {
      throw WorldError(where + ": a robot (non-static model) must have exactly one <link>, it has " +
                       std::to_string(model->LinkCount()));
    }
    const sdf::Link* link = model->LinkByIndex(0);
    if (link->CollisionCount() != 1) {
      throw WorldError(where + ": a robot's link must have exactly one <collision>, it has " +
                       std::to_string(link->CollisionCount()));
    }
    RobotSpec robot;
    robot.name = model->Name();
    robot.pose = model_pose * poseOf(*link, where + ", link '" + link->Name() + "'");
    const sdf::Collision* collision = link->CollisionByIndex(0);
    robot.shape = shapeOf(*collision, where + ", collision '" + collision->Name() + "'");
    robot.shape_offset = poseOf(*collision, where + ", collision '" + collision->Name() + "'");
    robot.mass_kg = link->Inertial().MassMatrix().Mass();
    if (!(robot.mass_kg > 0)) throw WorldError(where + ": the link needs an <inertial><mass> > 0");
    robot.plugins = pluginsOf(*model, path);
    for (auto& p : robot.plugins) p.owner = robot.name;
    const bool duplicate = std::any_of(spec.robots.begin(), spec.robots.end(),
                                       [&](const RobotSpec& other) { return other.name == robot.name; });
    if (duplicate) throw WorldError(where + ": duplicate robot name");
    spec.robots.push_back(std::move(robot));
  }
  // The cache's inputs: the world file and every file of each model it included.
  std::set<std::string> files = {path};
  for (const auto& folder : *included) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
      if (entry.is_regular_file(error)) files.insert(entry.path().string());
    }
  }
  inputs.assign(files.begin(), files.end());
}
