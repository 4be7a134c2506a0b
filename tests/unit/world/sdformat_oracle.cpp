// The oracle of Aula's SDF reader (test_world_sdf_oracle.cpp): libsdformat 12 reading a world
// into a WorldSpec, as Aula did until it read SDF itself (Debian 13 has no libsdformat). Built
// only where find_package(sdformat12) finds it (Debian 12); never part of a program.
#include "sdformat_oracle.hpp"

#include "world_sdf.hpp"  // resolveInclude: Aula's model path rule, which sdformat is given as URI paths


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
#include <sdf/SDFImpl.hh>
#include <sdf/World.hh>
#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>

namespace aula::world::oracle {
namespace {

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
// <aula:destination name="N">X Y</aula:destination> under <world> (sdformat keeps an element
// with a namespace prefix as it is): each a name, unique, and two numbers.
void readDestinations(const sdf::ElementPtr& world, const std::string& path, WorldSpec& spec) {
  for (sdf::ElementPtr e = world->GetFirstElement(); e; e = e->GetNextElement()) {
    if (e->GetName() != "aula:destination") continue;
    const std::string name = e->HasAttribute("name") ? e->GetAttribute("name")->GetAsString() : "";
    const std::string where = path + ": <aula:destination" + (name.empty() ? "" : " name=\"" + name + "\"") + ">";
    if (name.empty()) throw WorldError(where + ": needs a name attribute");
    for (const Destination& d : spec.destinations) {
      if (d.name == name) throw WorldError(where + ": a second destination of that name");
    }
    std::istringstream text(e->GetValue() != nullptr ? e->GetValue()->GetAsString() : "");
    Destination d{name};
    std::string more;
    if (!(text >> d.x_m >> d.y_m) || (text >> more) || !std::isfinite(d.x_m) || !std::isfinite(d.y_m)) {
      throw WorldError(where + ": expected two numbers, X Y in metres");
    }
    spec.destinations.push_back(d);
  }
}

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
void loadXml(const std::string& path, tinyxml2::XMLDocument& doc) {
  if (doc.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS) {
    const char* detail = doc.ErrorStr();
    throw WorldError(path + ":" + std::to_string(doc.ErrorLineNum()) + ": malformed XML: " +
                     (detail != nullptr ? detail : "parse error"));
  }
}

void collectIncludeUris(const tinyxml2::XMLElement* element, std::vector<std::string>& uris) {
  for (const auto* child = element->FirstChildElement(); child != nullptr; child = child->NextSiblingElement()) {
    if (std::string(child->Name()) == "include") {
      const auto* uri = child->FirstChildElement("uri");
      uris.push_back(uri != nullptr && uri->GetText() != nullptr ? trim(uri->GetText()) : "");
    }
    collectIncludeUris(child, uris);
  }
}

// Every file `file` includes, depth first, before sdformat reads any of it: a world or model that
// includes itself is refused here (sdformat would recurse until memory runs out). Fills
// `model_dirs` with the model folders used.
void walkIncludes(const std::string& file, const std::vector<std::string>& folders, std::vector<std::string>& chain,
                  std::set<std::string>& model_dirs) {
  namespace fs = std::filesystem;
  std::error_code error;
  const std::string canonical = fs::weakly_canonical(file, error).string();
  if (std::find(chain.begin(), chain.end(), canonical) != chain.end() || chain.size() >= 32) {
    std::string cycle;
    for (const auto& f : chain) cycle += f + " -> ";
    throw WorldError(chain.front() + ": includes itself (" + cycle + canonical + ")");
  }
  chain.push_back(canonical);
  tinyxml2::XMLDocument doc;
  loadXml(file, doc);
  std::vector<std::string> uris;
  if (doc.RootElement() != nullptr) collectIncludeUris(doc.RootElement(), uris);
  for (const auto& uri : uris) {
    const std::string target = resolveInclude(uri, file, folders);
    if (!fs::is_directory(target, error)) {
      walkIncludes(target, folders, chain, model_dirs);
      continue;
    }
    model_dirs.insert(target);
    tinyxml2::XMLDocument config;
    loadXml(target + "/model.config", config);
    const auto* model = config.RootElement();
    for (const auto* sdf = model != nullptr ? model->FirstChildElement("sdf") : nullptr; sdf != nullptr;
         sdf = sdf->NextSiblingElement("sdf")) {
      const std::string sdf_file = target + "/" + (sdf->GetText() != nullptr ? trim(sdf->GetText()) : "");
      if (fs::is_regular_file(sdf_file, error)) walkIncludes(sdf_file, folders, chain, model_dirs);
    }
  }
  chain.pop_back();
}

}  // namespace

void parseWithSdformat(const std::string& path, const std::vector<std::string>& folders, WorldSpec& spec,
                       std::vector<std::string>& inputs) {
  std::vector<std::string> chain;
  std::set<std::string> included;  // model folders used: the cache's inputs
  walkIncludes(path, folders, chain, included);
  // model://NAME -> the first FOLDER/NAME (every one checked above), Gazebo style
  // (GAZEBO_MODEL_PATH). As URI paths they are searched before the working directory.
  sdf::ParserConfig config;
  for (const auto& folder : folders) config.AddURIPath("model://", folder);
  // An <include> inside an included model file is resolved through sdformat's global find
  // callback, not the URI paths: without one, sdformat 12 printed an error and dropped the
  // nested model, and the world loaded without it (Aula's reader before issue 40 did so).
  const auto find = [folders](const std::string& uri) -> std::string {
    if (uri.rfind("model://", 0) != 0) return "";
    for (const auto& folder : folders) {
      std::error_code error;
      if (std::filesystem::exists(folder + "/" + uri.substr(8), error)) return folder + "/" + uri.substr(8);
    }
    return "";
  };
  config.SetFindCallback(find);
  sdf::setFindCallback(find);
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

  readDestinations(world->Element(), path, spec);

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
  for (const auto& folder : included) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
      if (entry.is_regular_file(error)) files.insert(entry.path().string());
    }
  }
  inputs.assign(files.begin(), files.end());
}

}  // namespace aula::world::oracle
