// Aula's SDF reader: Gazebo-style SDF worlds -> Aula's plain WorldSpec, on tinyxml2 alone.
//
// One reader on Debian 12 and 13 (Debian 13 has no libsdformat; docs/architecture.md, "Reading
// SDF"). It reads the part of SDF that Aula's worlds use and refuses, naming the file and line,
// what it does not read where that would change the world: libsdformat 12 gives the same
// WorldSpec for every shipped, generated and test world (tests/unit/world/test_world_sdf_oracle.cpp,
// on Debian 12). What it reads:
//   <sdf><world name>         exactly one; <physics><max_step_size> (only when stated);
//                             <aula:destination name="N">X Y</aula:destination>
//   <model name>              <static>, <pose>, <link>s, nested <model>s and <include>s, <plugin>s
//   <include>                 <uri> (model://NAME[/FILE] on the model path, or an absolute path /
//                             file://), and the included model's <name>, <pose>, <static>, <plugin>s
//   <link name>               <pose>, <inertial><mass> (default 1 kg), <collision>s
//   <collision name>          <pose>, <geometry> <box><size> | <cylinder><radius><length> | <plane>
//                             (a ground plane: skipped)
//   <plugin name filename>    every child element kept as trimmed text (a driver's keys)
//   <pose>                    "x y z roll pitch yaw" (radians; degrees="true"), or with
//                             rotation_format="quat_xyzw" "x y z qx qy qz qw"; `relative_to` is refused
// Everything else (visuals, lights, sensors, joints, GUI) is not part of Aula's world and is skipped.
// Poses compose as parent * child, as libsdformat's raw poses did; rotations go through the same
// quaternion arithmetic as ignition-math, so the numbers are the same to the bit.
#include "world_sdf.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <set>
#include <sstream>

namespace aula::world {
namespace {
namespace fs = std::filesystem;
using tinyxml2::XMLElement;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::string textOf(const XMLElement* e) { return e != nullptr && e->GetText() != nullptr ? trim(e->GetText()) : ""; }
std::string attribute(const XMLElement* e, const char* name) {
  const char* value = e->Attribute(name);
  return value != nullptr ? value : "";
}

// Every file read, kept open while the world is read: errors name an element's file and line.
class Reader {
 public:
  Reader(std::string world_path, std::vector<std::string> folders)
      : world_path_(std::move(world_path)), folders_(std::move(folders)) {}

  void read(WorldSpec& spec, std::vector<std::string>& inputs);

 private:
  struct Model {  // a <model> element, with what an <include> said about it
    const XMLElement* element = nullptr;
    std::string file;
    std::string name;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    bool is_static = false;
    std::vector<std::pair<const XMLElement*, std::string>> plugins;  // element, its file
    std::vector<Model> children;  // its nested <model>s and <include>s
  };

  const XMLElement* load(const std::string& file);
  [[noreturn]] void fail(const std::string& where, const std::string& what, const XMLElement* e,
                         const std::string& file) const;
  std::string at(const XMLElement* e, const std::string& file) const;
  double number(const XMLElement* e, const std::string& file, const std::string& where, double fallback) const;
  std::vector<double> numbers(const std::string& text, const XMLElement* e, const std::string& file,
                              const std::string& where) const;
  bool boolean(const XMLElement* e, const std::string& file, const std::string& where, bool fallback) const;
  Eigen::Isometry3d poseOf(const XMLElement* parent, const std::string& file, const std::string& where) const;
  std::string nameOf(const XMLElement* e, const std::string& file, const std::string& where) const;
  Shape shapeOf(const XMLElement* collision, const std::string& file, const std::string& where,
                bool* is_plane) const;
  Model modelOf(const XMLElement* element, const std::string& file);
  Model included(const XMLElement* include, const std::string& file);
  std::string resolve(const std::string& uri, const XMLElement* include, const std::string& file) const;
  std::vector<Model> childModels(const XMLElement* parent, const std::string& file, const std::string& where);
  std::vector<PluginSpec> pluginsOf(const Model& model, const std::string& where) const;
  void addStatics(const Model& model, const Eigen::Isometry3d& model_pose, const std::string& prefix, WorldSpec& spec);
  void addRobot(const Model& model, WorldSpec& spec) const;
  void readDestinations(const XMLElement* world, WorldSpec& spec) const;

  std::string world_path_;
  std::vector<std::string> folders_;
  std::vector<std::pair<std::string, std::unique_ptr<tinyxml2::XMLDocument>>> documents_;
  std::vector<std::string> chain_;    // the files being read, outermost first: a cycle is an error
  std::set<std::string> inputs_;      // every file the world is read from (the cache's inputs)
};

std::string Reader::at(const XMLElement* e, const std::string& file) const {
  return " (" + file + (e != nullptr ? ":" + std::to_string(e->GetLineNum()) : std::string()) + ")";
}

void Reader::fail(const std::string& where, const std::string& what, const XMLElement* e, const std::string& file) const {
  throw WorldError(where + ": " + what + at(e, file));
}

// Malformed XML names its line (tinyxml2's own message).
const XMLElement* Reader::load(const std::string& file) {
  auto doc = std::make_unique<tinyxml2::XMLDocument>();
  if (doc->LoadFile(file.c_str()) != tinyxml2::XML_SUCCESS) {
    const char* detail = doc->ErrorStr();
    throw WorldError(file + ":" + std::to_string(doc->ErrorLineNum()) + ": malformed XML: " +
                     (detail != nullptr ? detail : "parse error"));
  }
  inputs_.insert(file);
  const XMLElement* root = doc->RootElement();
  if (root == nullptr || std::string(root->Name()) != "sdf") {
    throw WorldError(file + ": the root element must be <sdf>" + at(root, file));
  }
  documents_.emplace_back(file, std::move(doc));
  return root;
}

std::vector<double> Reader::numbers(const std::string& text, const XMLElement* e, const std::string& file,
                                    const std::string& where) const {
  std::vector<double> values;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (errno != 0 || end != word.c_str() + word.size() || !std::isfinite(v)) {
      fail(where, "<" + std::string(e->Name()) + ">" + text + "</" + e->Name() + "> is not a list of numbers", e, file);
    }
    values.push_back(v);
  }
  return values;
}

// The child `e`'s one number, or `fallback` when there is no such child.
double Reader::number(const XMLElement* e, const std::string& file, const std::string& where, double fallback) const {
  if (e == nullptr) return fallback;
  const std::vector<double> v = numbers(textOf(e), e, file, where);
  if (v.size() != 1) fail(where, "<" + std::string(e->Name()) + "> needs one number", e, file);
  return v[0];
}

bool Reader::boolean(const XMLElement* e, const std::string& file, const std::string& where, bool fallback) const {
  if (e == nullptr) return fallback;
  std::string v = textOf(e);
  std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (v == "true" || v == "1") return true;
  if (v == "false" || v == "0") return false;
  fail(where, "<" + std::string(e->Name()) + ">" + textOf(e) + "</" + e->Name() + "> is not a boolean (true/false)", e, file);
}

// ignition-math's Quaternion(roll, pitch, yaw) and Normalize, then Eigen's rotation matrix: what
// libsdformat's Pose3d gave, so that a world reads the same numbers on every release.
Eigen::Isometry3d isometry(double x, double y, double z, double qw, double qx, double qy, double qz) {
  const double s = std::sqrt(qw * qw + qx * qx + qy * qy + qz * qz);
  if (std::fabs(s) <= 1e-6) {
    qw = 1, qx = qy = qz = 0;
  } else {
    qw /= s, qx /= s, qy /= s, qz /= s;
  }
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translation() = Eigen::Vector3d(x, y, z);
  out.linear() = Eigen::Quaterniond(qw, qx, qy, qz).normalized().toRotationMatrix();
  return out;
}

Eigen::Isometry3d fromRpy(double x, double y, double z, double roll, double pitch, double yaw) {
  const double phi = roll / 2.0, the = pitch / 2.0, psi = yaw / 2.0;
  return isometry(x, y, z, std::cos(phi) * std::cos(the) * std::cos(psi) + std::sin(phi) * std::sin(the) * std::sin(psi),
                  std::sin(phi) * std::cos(the) * std::cos(psi) - std::cos(phi) * std::sin(the) * std::sin(psi),
                  std::cos(phi) * std::sin(the) * std::cos(psi) + std::sin(phi) * std::cos(the) * std::sin(psi),
                  std::cos(phi) * std::cos(the) * std::sin(psi) - std::sin(phi) * std::sin(the) * std::cos(psi));
}

// The <pose> child of `parent` (identity when there is none).
Eigen::Isometry3d Reader::poseOf(const XMLElement* parent, const std::string& file, const std::string& where) const {
  const XMLElement* e = parent->FirstChildElement("pose");
  if (e == nullptr) return Eigen::Isometry3d::Identity();
  const std::string relative_to = attribute(e, "relative_to");
  if (!relative_to.empty()) {
    fail(where, "<pose relative_to=\"" + relative_to + "\"> is not supported; give poses relative to the parent element", e, file);
  }
  const std::vector<double> v = numbers(textOf(e), e, file, where);
  const std::string format = attribute(e, "rotation_format");
  if (format == "quat_xyzw") {
    if (v.size() != 7) fail(where, "a quat_xyzw <pose> needs 7 numbers, x y z qx qy qz qw", e, file);
    return isometry(v[0], v[1], v[2], v[6], v[3], v[4], v[5]);
  }
  if (!format.empty() && format != "euler_rpy") {
    fail(where, "<pose rotation_format=\"" + format + "\">: use euler_rpy or quat_xyzw", e, file);
  }
  if (v.size() != 6) fail(where, "<pose> needs 6 numbers, x y z roll pitch yaw", e, file);
  std::string degrees = attribute(e, "degrees");
  const bool in_degrees = degrees == "true" || degrees == "1";
  if (!degrees.empty() && !in_degrees && degrees != "false" && degrees != "0") {
    fail(where, "<pose degrees=\"" + degrees + "\"> is not a boolean", e, file);
  }
  const double k = in_degrees ? M_PI / 180.0 : 1.0;
  return fromRpy(v[0], v[1], v[2], v[3] * k, v[4] * k, v[5] * k);
}

std::string Reader::nameOf(const XMLElement* e, const std::string& file, const std::string& where) const {
  const std::string name = attribute(e, "name");
  if (name.empty()) fail(where, "<" + std::string(e->Name()) + "> needs a name attribute", e, file);
  return name;
}

// Box or cylinder collision geometry; <plane> sets *is_plane; anything else is an error.
Shape Reader::shapeOf(const XMLElement* collision, const std::string& file, const std::string& where,
                      bool* is_plane) const {
  const XMLElement* geometry = collision->FirstChildElement("geometry");
  Shape shape;
  *is_plane = false;
  if (const XMLElement* box = geometry != nullptr ? geometry->FirstChildElement("box") : nullptr) {
    shape.kind = ShapeKind::Box;
    shape.box_size_m = Eigen::Vector3d(1, 1, 1);
    if (const XMLElement* size = box->FirstChildElement("size")) {
      const std::vector<double> v = numbers(textOf(size), size, file, where);
      if (v.size() != 3) fail(where, "box <size> needs 3 numbers", size, file);
      shape.box_size_m = Eigen::Vector3d(v[0], v[1], v[2]);
    }
    if (!(shape.box_size_m.minCoeff() > 0)) fail(where, "box <size> must be positive", box, file);
    return shape;
  }
  if (const XMLElement* cylinder = geometry != nullptr ? geometry->FirstChildElement("cylinder") : nullptr) {
    shape.kind = ShapeKind::Cylinder;
    shape.radius_m = number(cylinder->FirstChildElement("radius"), file, where, 1.0);
    shape.length_m = number(cylinder->FirstChildElement("length"), file, where, 1.0);
    if (!(shape.radius_m > 0 && shape.length_m > 0)) {
      fail(where, "cylinder <radius> and <length> must be positive", cylinder, file);
    }
    return shape;
  }
  if (geometry != nullptr && geometry->FirstChildElement("plane") != nullptr) {
    *is_plane = true;
    return shape;
  }
  fail(where, "only <box> and <cylinder> collision geometry is supported", geometry != nullptr ? geometry : collision, file);
}

// A <model> element and, read now, the models it nests.
Reader::Model Reader::modelOf(const XMLElement* element, const std::string& file) {
  Model model;
  model.element = element;
  model.file = file;
  model.name = nameOf(element, file, file);
  const std::string where = file + ": model '" + model.name + "'";
  model.pose = poseOf(element, file, where);
  model.is_static = boolean(element->FirstChildElement("static"), file, where, false);
  for (const XMLElement* p = element->FirstChildElement("plugin"); p != nullptr; p = p->NextSiblingElement("plugin")) {
    model.plugins.emplace_back(p, file);
  }
  model.children = childModels(element, file, where);
  return model;
}

std::string Reader::resolve(const std::string& uri, const XMLElement* include, const std::string& file) const {
  try {
    return resolveInclude(uri, file, folders_);
  } catch (const WorldError& e) {
    throw WorldError(e.what() + at(include, file));
  }
}

// The model an <include> brings in, renamed, placed and made static as the <include> says, with
// the <include>'s plugins after its own. A model folder's file is the <sdf> its model.config names.
Reader::Model Reader::included(const XMLElement* include, const std::string& file) {
  const std::string uri = textOf(include->FirstChildElement("uri"));
  std::string target = resolve(uri, include, file);
  std::error_code error;
  if (fs::is_directory(target, error)) {
    const std::string folder = target;
    for (const auto& entry : fs::directory_iterator(folder, error)) {
      if (entry.is_regular_file(error)) inputs_.insert(entry.path().string());
    }
    tinyxml2::XMLDocument config;
    const std::string config_path = folder + "/model.config";
    if (config.LoadFile(config_path.c_str()) != tinyxml2::XML_SUCCESS) {
      const char* detail = config.ErrorStr();
      throw WorldError(config_path + ":" + std::to_string(config.ErrorLineNum()) + ": malformed XML: " +
                       (detail != nullptr ? detail : "parse error"));
    }
    const XMLElement* root = config.RootElement();
    const XMLElement* sdf = root != nullptr ? root->FirstChildElement("sdf") : nullptr;
    if (sdf == nullptr || textOf(sdf).empty()) {
      throw WorldError(config_path + ": names no <sdf> file for model " + uri + at(include, file));
    }
    target = folder + "/" + textOf(sdf);
    if (!fs::is_regular_file(target, error)) {
      throw WorldError(config_path + ": <sdf>" + textOf(sdf) + "</sdf>: no such file " + target + at(sdf, config_path));
    }
  }
  const std::string canonical = fs::weakly_canonical(target, error).string();
  if (std::find(chain_.begin(), chain_.end(), canonical) != chain_.end() || chain_.size() >= 32) {
    std::string cycle;
    for (const auto& f : chain_) cycle += f + " -> ";
    throw WorldError(chain_.front() + ": includes itself (" + cycle + canonical + ")");
  }
  const XMLElement* root = load(target);
  const XMLElement* element = root->FirstChildElement("model");
  if (element == nullptr) throw WorldError(file + ": <include><uri>" + uri + "</uri>: " + target + " has no <model>" + at(include, file));
  chain_.push_back(canonical);
  Model model = modelOf(element, target);
  if (const XMLElement* name = include->FirstChildElement("name")) model.name = textOf(name);
  const std::string where = file + ": model '" + model.name + "'";
  if (include->FirstChildElement("pose") != nullptr) model.pose = poseOf(include, file, where);
  model.is_static = boolean(include->FirstChildElement("static"), file, where, model.is_static);
  for (const XMLElement* p = include->FirstChildElement("plugin"); p != nullptr; p = p->NextSiblingElement("plugin")) {
    model.plugins.emplace_back(p, file);
  }
  chain_.pop_back();
  return model;
}

// The <model>s and <include>s directly under `parent`, in the file's order; names unique.
std::vector<Reader::Model> Reader::childModels(const XMLElement* parent, const std::string& file, const std::string& where) {
  std::vector<Model> models;
  for (const XMLElement* e = parent->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
    const std::string kind = e->Name();
    if (kind != "model" && kind != "include") continue;
    Model model = kind == "model" ? modelOf(e, file) : included(e, file);
    for (const Model& other : models) {
      if (other.name == model.name) fail(where, "two models named '" + model.name + "'", e, file);
    }
    models.push_back(std::move(model));
  }
  return models;
}

std::vector<PluginSpec> Reader::pluginsOf(const Model& model, const std::string& where) const {
  std::vector<PluginSpec> plugins;
  for (const auto& [p, file] : model.plugins) {
    PluginSpec spec;
    spec.owner = model.name;
    spec.name = nameOf(p, file, where);
    spec.type = attribute(p, "filename");
    const std::string here = where + ", plugin '" + spec.name + "'";
    if (spec.type.empty()) fail(here, "<plugin> needs a filename attribute (the driver type)", p, file);
    for (const auto& other : plugins) {
      if (other.name == spec.name) fail(here, "duplicate plugin name", p, file);
    }
    for (const XMLElement* child = p->FirstChildElement(); child != nullptr; child = child->NextSiblingElement()) {
      spec.params[child->Name()] = textOf(child);
    }
    plugins.push_back(std::move(spec));
  }
  return plugins;
}

// Static geometry of a static model (and of its nested models), in world coordinates. <plane>
// collisions (a Gazebo ground plane) are skipped: Aula's physics keeps robots on the ground with a
// planar joint, and a ground would be an obstacle in every map.
void Reader::addStatics(const Model& model, const Eigen::Isometry3d& model_pose, const std::string& prefix, WorldSpec& spec) {
  const std::string name = prefix + model.name;
  const std::string where = world_path_ + ": model '" + name + "'";
  const std::string& file = model.file;
  if (!model.plugins.empty()) fail(where, "a static model cannot carry drivers", model.plugins.front().first, model.plugins.front().second);
  std::set<std::string> links;
  for (const XMLElement* link = model.element->FirstChildElement("link"); link != nullptr; link = link->NextSiblingElement("link")) {
    const std::string link_name = nameOf(link, file, where);
    if (!links.insert(link_name).second) fail(where, "two links named '" + link_name + "'", link, file);
    const std::string in_link = where + ", link '" + link_name + "'";
    const Eigen::Isometry3d link_pose = model_pose * poseOf(link, file, in_link);
    std::set<std::string> collisions;
    for (const XMLElement* c = link->FirstChildElement("collision"); c != nullptr; c = c->NextSiblingElement("collision")) {
      const std::string collision_name = nameOf(c, file, in_link);
      if (!collisions.insert(collision_name).second) fail(in_link, "two collisions named '" + collision_name + "'", c, file);
      bool is_plane = false;
      StaticObject o;
      o.name = name + "::" + link_name + "::" + collision_name;
      o.shape = shapeOf(c, file, in_link + ", collision '" + collision_name + "'", &is_plane);
      if (is_plane) continue;
      o.pose = link_pose * poseOf(c, file, where + ", collision '" + collision_name + "'");
      spec.statics.push_back(o);
    }
  }
  for (const Model& nested : model.children) {
    addStatics(nested, model_pose * nested.pose, name + "::", spec);
  }
}

// A robot: one link, one collision, drivers as plugins.
void Reader::addRobot(const Model& model, WorldSpec& spec) const {
  const std::string where = world_path_ + ": model '" + model.name + "'";
  const std::string& file = model.file;
  const XMLElement* e = model.element;
  if (!model.children.empty()) {
    fail(where, "a robot (non-static model) cannot nest models", e, file);
  }
  int link_count = 0;
  for (const XMLElement* l = e->FirstChildElement("link"); l != nullptr; l = l->NextSiblingElement("link")) ++link_count;
  if (link_count != 1) {
    fail(where, "a robot (non-static model) must have exactly one <link>, it has " + std::to_string(link_count), e, file);
  }
  const XMLElement* link = e->FirstChildElement("link");
  const std::string link_name = nameOf(link, file, where);
  int collision_count = 0;
  for (const XMLElement* c = link->FirstChildElement("collision"); c != nullptr; c = c->NextSiblingElement("collision")) ++collision_count;
  if (collision_count != 1) {
    fail(where, "a robot's link must have exactly one <collision>, it has " + std::to_string(collision_count), link, file);
  }
  const XMLElement* collision = link->FirstChildElement("collision");
  const std::string in_collision = where + ", collision '" + nameOf(collision, file, where) + "'";
  RobotSpec robot;
  robot.name = model.name;
  robot.pose = model.pose * poseOf(link, file, where + ", link '" + link_name + "'");
  bool is_plane = false;
  robot.shape = shapeOf(collision, file, in_collision, &is_plane);
  if (is_plane) fail(in_collision, "only <box> and <cylinder> collision geometry is supported", collision, file);
  robot.shape_offset = poseOf(collision, file, in_collision);
  const XMLElement* inertial = link->FirstChildElement("inertial");
  const XMLElement* mass = inertial != nullptr ? inertial->FirstChildElement("mass") : nullptr;
  robot.mass_kg = number(mass, file, where, 1.0);  // SDF's default mass
  if (!(robot.mass_kg > 0)) fail(where, "the link needs an <inertial><mass> > 0", mass != nullptr ? mass : link, file);
  robot.plugins = pluginsOf(model, where);
  const bool duplicate = std::any_of(spec.robots.begin(), spec.robots.end(),
                                     [&](const RobotSpec& other) { return other.name == robot.name; });
  if (duplicate) fail(where, "duplicate robot name", e, file);
  spec.robots.push_back(std::move(robot));
}

// <aula:destination name="N">X Y</aula:destination> under <world>: each a name, unique, and two numbers.
void Reader::readDestinations(const XMLElement* world, WorldSpec& spec) const {
  for (const XMLElement* e = world->FirstChildElement("aula:destination"); e != nullptr;
       e = e->NextSiblingElement("aula:destination")) {
    const std::string name = attribute(e, "name");
    const std::string where = world_path_ + ": <aula:destination" + (name.empty() ? "" : " name=\"" + name + "\"") + ">";
    if (name.empty()) fail(where, "needs a name attribute", e, world_path_);
    for (const Destination& d : spec.destinations) {
      if (d.name == name) fail(where, "a second destination of that name", e, world_path_);
    }
    std::istringstream text(textOf(e));
    Destination d{name};
    std::string more;
    if (!(text >> d.x_m >> d.y_m) || (text >> more) || !std::isfinite(d.x_m) || !std::isfinite(d.y_m)) {
      fail(where, "expected two numbers, X Y in metres", e, world_path_);
    }
    spec.destinations.push_back(d);
  }
}

void Reader::read(WorldSpec& spec, std::vector<std::string>& inputs) {
  std::error_code error;
  chain_.push_back(fs::weakly_canonical(world_path_, error).string());
  const XMLElement* root = load(world_path_);
  const XMLElement* world = root->FirstChildElement("world");
  if (world == nullptr || world->NextSiblingElement("world") != nullptr) {
    throw WorldError(world_path_ + ": expected exactly one <world>" + at(root, world_path_));
  }
  spec.name = nameOf(world, world_path_, world_path_);
  spec.source_path = world_path_;
  // Only a step the file states counts (libsdformat's default <physics> was 1 ms).
  if (const XMLElement* physics = world->FirstChildElement("physics")) {
    if (const XMLElement* step = physics->FirstChildElement("max_step_size")) {
      spec.physics_step_s = number(step, world_path_, world_path_ + ": <physics>", 0.0);
    }
  }
  readDestinations(world, spec);
  for (const Model& model : childModels(world, world_path_, world_path_)) {
    if (model.is_static) {
      addStatics(model, model.pose, "", spec);
    } else {
      addRobot(model, spec);
    }
  }
  inputs.assign(inputs_.begin(), inputs_.end());
}

}  // namespace

// model://NAME[/REST] is FOLDER/NAME[/REST] for the first FOLDER of the model path holding NAME,
// which must then be a model (model.config); any other URI must be an absolute path. Nothing is
// looked up in the working directory (a student's roomba/ folder beside `aula run` must not
// shadow the teacher's model).
std::string resolveInclude(const std::string& uri, const std::string& file, const std::vector<std::string>& folders) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (uri.rfind("model://", 0) == 0) {
    const std::string rest = uri.substr(8);
    const std::string name = rest.substr(0, rest.find('/'));
    for (const auto& folder : folders) {
      const std::string candidate = folder + "/" + name;
      if (!fs::exists(candidate, error)) continue;
      if (!fs::exists(candidate + "/model.config", error)) {
        throw WorldError(file + ": " + uri + " is " + candidate + ", which has no model.config");
      }
      return folder + "/" + rest;
    }
    std::string text = file + ": model '" + name + "' not found: looked for " + name + "/model.config in";
    for (const auto& folder : folders) text += " " + folder;
    throw WorldError(text + " (add a folder with AULA_MODEL_PATH)");
  }
  const bool file_scheme = uri.rfind("file://", 0) == 0;
  const std::string target = file_scheme ? uri.substr(7) : uri;
  if ((!file_scheme && uri.find("://") != std::string::npos) || target.empty() || target[0] != '/') {
    throw WorldError(file + ": <include><uri>" + uri + "</uri>: give model://NAME (found on the model path) or an absolute path");
  }
  if (!fs::exists(target, error)) throw WorldError(file + ": <include><uri>" + uri + "</uri>: no such file");
  return target;
}

void parseSdfWorld(const std::string& path, const std::vector<std::string>& folders, WorldSpec& spec,
                   std::vector<std::string>& inputs) {
  Reader(path, folders).read(spec, inputs);
}

}  // namespace aula::world
