// Aula's SDF reader: Gazebo-style SDF worlds -> Aula's plain WorldSpec, on tinyxml2 alone.
//
// One reader on Debian 12 and 13 (Debian 13 has no libsdformat; docs/architecture.md, "Reading
// SDF"). It reads the part of SDF that Aula's worlds use and refuses, naming the file and line,
// what it does not read where that would change the world: libsdformat 12 gives the same
// WorldSpec for every shipped, generated and test world of boxes and cylinders
// (tests/unit/world/test_world_sdf_oracle.cpp, on Debian 12). What it reads:
//   <sdf><world name>         exactly one; <physics><max_step_size> (only when stated);
//                             <aula:destination name="N">X Y</aula:destination>; <population>s
//                             (expanded into their models as Gazebo does)
//   <model name>              <static>, <pose>, <link>s, nested <model>s and <include>s, <plugin>s;
//                             not static with no drive (Aula's or Gazebo's): kept still as static geometry
//   <include>                 <uri> (model://NAME[/FILE] on the model path, or an absolute path /
//                             file://), and the included model's <name>, <pose>, <static>, <plugin>s;
//                             a model folder's newest SDF file in its model.config; Gazebo's built-in
//                             model://ground_plane and model://sun when no folder has them (skipped)
//   <link name>               <pose>, <inertial><mass> (default 1 kg), <collision>s
//   <collision name>          <pose>, <geometry> <box><size> | <cylinder><radius><length> |
//                             <mesh><uri><scale><submesh> (mesh.hpp) | <plane> (a ground plane: skipped)
//   <plugin name filename>    every child element kept as trimmed text (a driver's keys)
//   <pose>                    "x y z roll pitch yaw" (radians; degrees="true"), or with
//                             rotation_format="quat_xyzw" "x y z qx qy qz qw"; `relative_to` naming a
//                             link, joint or <frame> of the model (SDF 1.7), refused on a model's own pose
//   a Gazebo drive plugin      the model is Aula's robot of that kind (addGazeboRobot): all its links'
//                             collisions its shape, its level ray sensors its lasers, an Ackermann
//                             drive's wheel joints its wheelbase
// What Gazebo reads and Aula does not simulate (visuals, lights, sky, GUI, sensors, joints, world
// plugins, engine settings) is skipped and listed, one line per kind (WorldSpec::skipped). An
// attribute value without quotes, which Gazebo's TinyXML takes, is read as if quoted. Problems do
// not stop the reading: every one is kept (a model with one left out) and all are thrown at the
// end, each with its file and line.
// Poses compose as parent * child, as libsdformat's raw poses did; rotations go through the same
// quaternion arithmetic as ignition-math, so the numbers are the same to the bit.
#include "world_sdf.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <random>
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

// The frame a <pose relative_to="..."> child of `e` names ("" when none).
std::string relativeTo(const XMLElement* e) {
  const XMLElement* pose = e->FirstChildElement("pose");
  const char* frame = pose != nullptr ? pose->Attribute("relative_to") : nullptr;
  return frame != nullptr ? frame : "";
}

// An Ackermann car's numbers, as its Gazebo plugin gives them (ackermannCar).
struct CarNumbers {
  double wheelbase_m = 0, max_steer_rad = 0, rear_axle_x_m = 0, max_speed_mps = 0;
};

// Every file read, kept open while the world is read: errors name an element's file and line.
class Reader {
 public:
  Reader(std::string world_path, std::vector<std::string> folders)
      : world_path_(std::move(world_path)), folders_(std::move(folders)) {}

  void read(WorldSpec& spec, std::vector<std::string>& inputs, std::vector<std::string>& problems);

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
  void parseXml(const std::string& file, tinyxml2::XMLDocument& doc);
  void skip(const XMLElement* e, const std::string& file, const std::string& kind, const std::string& why);
  void skipUnread(const XMLElement* parent, const std::string& file, const std::set<std::string>& read);
  template <class Step> void attempt(Step&& step);
  std::vector<Model> population(const XMLElement* population, const std::string& file);
  [[noreturn]] void fail(const std::string& where, const std::string& what, const XMLElement* e,
                         const std::string& file) const;
  std::string at(const XMLElement* e, const std::string& file) const;
  double number(const XMLElement* e, const std::string& file, const std::string& where, double fallback) const;
  std::vector<double> numbers(const std::string& text, const XMLElement* e, const std::string& file,
                              const std::string& where) const;
  bool boolean(const XMLElement* e, const std::string& file, const std::string& where, bool fallback) const;
  Eigen::Isometry3d poseOf(const XMLElement* parent, const std::string& file, const std::string& where,
                           bool frames_known = false) const;
  Eigen::Isometry3d frameOf(const Model& model, const std::string& name, const std::string& where, int depth = 0) const;
  Eigen::Isometry3d placed(const XMLElement* e, const Model& model, const std::string& fallback, const std::string& where,
                           int depth = 0) const;
  std::string nameOf(const XMLElement* e, const std::string& file, const std::string& where) const;
  Shape shapeOf(const XMLElement* collision, const std::string& file, const std::string& where, bool* is_plane);
  Shape meshOf(const XMLElement* mesh, const std::string& file, const std::string& where);
  Model modelOf(const XMLElement* element, const std::string& file);
  std::optional<Model> included(const XMLElement* include, const std::string& file);
  std::string resolve(const std::string& uri, const XMLElement* include, const std::string& file) const;
  std::vector<Model> childModels(const XMLElement* parent, const std::string& file, const std::string& where);
  std::vector<PluginSpec> pluginsOf(const Model& model, const std::string& where) const;
  void addStatics(const Model& model, const Eigen::Isometry3d& model_pose, const std::string& prefix, WorldSpec& spec);
  void addModel(const Model& model, WorldSpec& spec);
  static bool keptStill(const Model& model);
  void addRobot(const Model& model, WorldSpec& spec);
  void addRobotOrThrow(const Model& model, WorldSpec& spec);
  void addGazeboRobot(const Model& model, WorldSpec& spec);
  void gazeboDrivers(const Model& model, const XMLElement* drive, const Eigen::Isometry3d& body,
                     const std::optional<CarNumbers>& car, RobotSpec& robot);
  void gazeboLasers(const Model& model, const Eigen::Isometry3d& body, RobotSpec& robot);
  void outlineOf(const XMLElement* link, const Model& model, const char* kind, const std::string& where,
                 std::vector<Eigen::Vector3d>& points);
  CarNumbers ackermannCar(const Model& model, const XMLElement* drive, double& heading, Eigen::Vector3d& rear_axle) const;
  void readDestinations(const XMLElement* world, WorldSpec& spec) const;

  std::string world_path_;
  std::vector<std::string> folders_;
  std::vector<std::pair<std::string, std::unique_ptr<tinyxml2::XMLDocument>>> documents_;
  std::vector<std::string> chain_;    // the files being read, outermost first: a cycle is an error
  std::set<std::string> inputs_;      // every file the world is read from (the cache's inputs)
  std::map<std::string, std::shared_ptr<const TriangleMesh>> meshes_;  // by meshKey: seven parked cars, one read
  std::vector<std::string> problems_;  // every problem found, in one pass (a model with one is left out)
  struct Skipped {
    int count = 0;
    std::string first;  // file:line
    std::string why;
  };
  std::vector<std::pair<std::string, Skipped>> skipped_;  // by kind, in the order first met
};

// Gazebo's drive plugins Aula knows a robot by, and the kind of Aula robot each makes: a
// planar-move robot is holonomic (moves sideways too), a differential or skid-steer drive is not,
// an Ackermann drive is a car (it turns about its rear axle, no tighter than its steering allows).
enum class Drive { Diff, Holonomic, Ackermann };
const std::map<std::string, Drive>& gazeboDrives() {
  static const std::map<std::string, Drive> kinds = {
      {"libgazebo_ros_planar_move.so", Drive::Holonomic}, {"libgazebo_ros_diff_drive.so", Drive::Diff},
      {"libgazebo_ros_skid_steer_drive.so", Drive::Diff}, {"libgazebo_ros_tricycle_drive.so", Drive::Diff},
      {"gz-sim-diff-drive-system", Drive::Diff}, {"ignition-gazebo-diff-drive-system", Drive::Diff},
      {"libgazebo_ros_ackermann_drive.so", Drive::Ackermann}};
  return kinds;
}

bool hasGazeboDrive(const std::vector<std::pair<const XMLElement*, std::string>>& plugins) {
  return std::any_of(plugins.begin(), plugins.end(), [](const auto& p) {
    const char* filename = p.first->Attribute("filename");
    return filename != nullptr && gazeboDrives().count(filename) != 0;
  });
}

// A plugin file of Gazebo's or ROS's (libNAME.so, gz-sim-..., ignition-gazebo-...), not a driver of Aula's.
bool gazeboLibrary(const std::string& filename) {
  const bool so = filename.size() > 6 && filename.rfind("lib", 0) == 0 && filename.compare(filename.size() - 3, 3, ".so") == 0;
  return so || filename.rfind("gz-", 0) == 0 || filename.rfind("ignition-", 0) == 0;
}

// What Aula does not simulate, by element: said once per kind, with the reason.
std::string whySkipped(const std::string& element) {
  static const std::map<std::string, std::string> reasons = {
      {"real_time_factor", "Aula runs as fast as the exercise allows, on sim time"},
      {"real_time_update_rate", "Aula runs as fast as the exercise allows, on sim time"},
      {"ode", "Aula's physics is DART's"},
      {"bullet", "Aula's physics is DART's"},
      {"simbody", "Aula's physics is DART's"},
      {"dart", "Aula sets DART up itself"},
      {"light", "Aula simulates no lighting"},
      {"scene", "Aula draws no sky, fog or scene"},
      {"gui", "Aula has its own windows"},
      {"physics", "Aula steps DART at each exercise's own step (Simulator.PhysicsStep); the engine's settings are not read"},
      {"plugin", "Aula loads no Gazebo world plugins"},
      {"audio", "Aula plays no sound"},
      {"visual", "Aula draws and senses collisions only (visuals and their materials are not read)"},
      {"sensor", "Aula's sensors are driver plugins (laser, bumper)"},
      {"joint", "Aula's robots are one rigid body"},
      {"spherical_coordinates", "Aula's worlds are flat, in metres"},
      {"gravity", "Aula's robots move in the plane"},
      {"magnetic_field", "Aula simulates no magnetometer"},
      {"atmosphere", "Aula simulates no atmosphere"},
      {"wind", "Aula simulates no wind"},
      {"state", "Aula starts every run from the world's poses"},
      {"plane", "a ground plane: Aula's robots stay on the ground by their planar joint"},
      {"road", "a road is drawn on the ground, nothing a robot touches"},
      {"surface", "Aula's contacts have their own friction"},
      {"max_contacts", "Aula's contacts are DART's"},
      {"self_collide", "Aula's robots are one rigid body"},
      {"kinematic", "Aula's robots are driven by their motors plugin"},
      {"velocity_decay", "Aula's robots are driven by their motors plugin"},
  };
  const auto it = reasons.find(element);
  return it != reasons.end() ? it->second : "not part of Aula's world";
}

std::string Reader::at(const XMLElement* e, const std::string& file) const {
  return " (" + file + (e != nullptr ? ":" + std::to_string(e->GetLineNum()) : std::string()) + ")";
}

void Reader::fail(const std::string& where, const std::string& what, const XMLElement* e, const std::string& file) const {
  throw WorldError(where + ": " + what + at(e, file));
}

// Gazebo reads SDF with TinyXML 1, which takes an attribute value without quotes
// (<gui fullscreen=1>, in RoboticsInfrastructure's worlds); tinyxml2 refuses it. Such values are
// quoted in the text before it is parsed, on their own line (line numbers stay right); each is
// counted among what was read differently. `lines` gets the line of each one repaired.
std::string quoteBareAttributes(const std::string& text, std::vector<int>& lines) {
  std::string out;
  out.reserve(text.size() + 16);
  int line = 1;
  std::size_t i = 0;
  auto copyUntil = [&](const char* end) {  // a comment, CDATA, declaration: copied as it is
    const std::size_t stop = text.find(end, i);
    const std::size_t next = stop == std::string::npos ? text.size() : stop + std::strlen(end);
    line += static_cast<int>(std::count(text.begin() + static_cast<long>(i), text.begin() + static_cast<long>(next), '\n'));
    out.append(text, i, next - i);
    i = next;
  };
  while (i < text.size()) {
    if (text.compare(i, 4, "<!--") == 0) { copyUntil("-->"); continue; }
    if (text.compare(i, 9, "<![CDATA[") == 0) { copyUntil("]]>"); continue; }
    if (text.compare(i, 2, "<?") == 0) { copyUntil("?>"); continue; }
    if (text.compare(i, 2, "<!") == 0) { copyUntil(">"); continue; }
    if (text[i] != '<') {
      if (text[i] == '\n') ++line;
      out += text[i++];
      continue;
    }
    // A tag: copy it, quoting each bare value after '='.
    while (i < text.size() && text[i] != '>') {
      const char c = text[i];
      if (c == '"' || c == '\'') {
        const std::size_t close = text.find(c, i + 1);
        const std::size_t next = close == std::string::npos ? text.size() : close + 1;
        line += static_cast<int>(std::count(text.begin() + static_cast<long>(i), text.begin() + static_cast<long>(next), '\n'));
        out.append(text, i, next - i);
        i = next;
        continue;
      }
      if (c == '\n') ++line;
      out += c;
      ++i;
      if (c != '=') continue;
      while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) out += text[i++];
      if (i >= text.size() || text[i] == '"' || text[i] == '\'') continue;
      std::size_t end = i;
      while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end])) && text[end] != '>' &&
             text.compare(end, 2, "/>") != 0) {
        ++end;
      }
      if (end == i) continue;
      out += '"';
      out.append(text, i, end - i);
      out += '"';
      lines.push_back(line);
      i = end;
    }
  }
  return out;
}

// Reads `file` into `doc`. Malformed XML names its line (tinyxml2's own message).
void Reader::parseXml(const std::string& file, tinyxml2::XMLDocument& doc) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw WorldError(file + ": cannot open the file");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  std::vector<int> repaired;
  const std::string text = quoteBareAttributes(bytes.str(), repaired);
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
    const char* detail = doc.ErrorStr();
    throw WorldError(file + ":" + std::to_string(doc.ErrorLineNum()) + ": malformed XML: " +
                     (detail != nullptr ? detail : "parse error"));
  }
  for (const int line : repaired) {
    const std::string where = file + ":" + std::to_string(line);
    auto it = std::find_if(skipped_.begin(), skipped_.end(), [](const auto& s) { return s.first == "unquoted attribute value"; });
    if (it == skipped_.end()) {
      skipped_.push_back({"unquoted attribute value", {0, where, "read as if quoted, as Gazebo's parser does"}});
      it = skipped_.end() - 1;
    }
    ++it->second.count;
  }
}

const XMLElement* Reader::load(const std::string& file) {
  auto doc = std::make_unique<tinyxml2::XMLDocument>();
  parseXml(file, *doc);
  inputs_.insert(file);
  const XMLElement* root = doc->RootElement();
  if (root == nullptr || std::string(root->Name()) != "sdf") {
    throw WorldError(file + ": the root element must be <sdf>" + at(root, file) +
                     (root != nullptr && std::string(root->Name()) == "gazebo"
                          ? "; <gazebo> is SDF 1.2: give the model an SDF 1.3 or newer file in its model.config"
                          : ""));
  }
  documents_.emplace_back(file, std::move(doc));
  return root;
}

void Reader::skip(const XMLElement* e, const std::string& file, const std::string& kind, const std::string& why) {
  auto it = std::find_if(skipped_.begin(), skipped_.end(), [&](const auto& s) { return s.first == kind; });
  if (it == skipped_.end()) {
    skipped_.push_back({kind, {0, file + ":" + std::to_string(e->GetLineNum()), why}});
    it = skipped_.end() - 1;
  }
  ++it->second.count;
}

// Every child of `parent` that Aula does not read, counted by kind.
void Reader::skipUnread(const XMLElement* parent, const std::string& file, const std::set<std::string>& read) {
  for (const XMLElement* e = parent->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
    const std::string name = e->Name();
    if (read.count(name) != 0) continue;
    skip(e, file, "<" + name + "> in <" + parent->Name() + ">", whySkipped(name));
  }
}

// Runs one step of the reading; a problem it meets is kept and the reading goes on.
template <class Step>
void Reader::attempt(Step&& step) {
  try {
    step();
  } catch (const WorldError& e) {
    for (const auto& p : e.problems()) problems_.push_back(p);
  }
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

// The <pose> child of `parent` (identity when there is none). `relative_to` is read where a model's
// frames are known (placed()); elsewhere it is refused.
Eigen::Isometry3d Reader::poseOf(const XMLElement* parent, const std::string& file, const std::string& where,
                                 bool frames_known) const {
  const XMLElement* e = parent->FirstChildElement("pose");
  if (e == nullptr) return Eigen::Isometry3d::Identity();
  const std::string relative_to = attribute(e, "relative_to");
  if (!relative_to.empty() && !frames_known) {
    fail(where, "<pose relative_to=\"" + relative_to + "\"> is only read inside a model (naming its link, joint or frame)", e, file);
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

// The pose in `model`'s frame of its frame `name` (a <link>, <joint> or <frame>), as SDF 1.7 reads
// relative_to: a link is placed in the model's frame, a joint in its child link's, a frame in what
// it is attached to, unless their own relative_to names another (RoboticsInfrastructure's Ackermann
// cars place every wheel so).
Eigen::Isometry3d Reader::frameOf(const Model& model, const std::string& name, const std::string& where, int depth) const {
  if (name.empty() || name == "__model__") return Eigen::Isometry3d::Identity();
  if (depth > 32) fail(where, "relative_to='" + name + "': the frames name each other in a cycle", model.element, model.file);
  for (const char* kind : {"link", "joint", "frame"}) {
    for (const XMLElement* e = model.element->FirstChildElement(kind); e != nullptr; e = e->NextSiblingElement(kind)) {
      if (attribute(e, "name") != name) continue;
      const std::string fallback = std::string(kind) == "joint"   ? textOf(e->FirstChildElement("child"))
                                   : std::string(kind) == "frame" ? attribute(e, "attached_to")
                                                                  : std::string();
      return placed(e, model, fallback, where, depth + 1);
    }
  }
  fail(where, "relative_to='" + name + "' names no <link>, <joint> or <frame> of model '" + model.name + "'", model.element,
       model.file);
}

// The <pose> of `e` (a link, joint, frame, collision or sensor of `model`) in the model's frame:
// relative to the frame its relative_to names, else to the frame `fallback` names (its link).
Eigen::Isometry3d Reader::placed(const XMLElement* e, const Model& model, const std::string& fallback, const std::string& where,
                                 int depth) const {
  const XMLElement* pose = e->FirstChildElement("pose");
  const std::string relative_to = pose != nullptr ? attribute(pose, "relative_to") : "";
  return frameOf(model, relative_to.empty() ? fallback : relative_to, where, depth) * poseOf(e, model.file, where, true);
}

std::string Reader::nameOf(const XMLElement* e, const std::string& file, const std::string& where) const {
  const std::string name = attribute(e, "name");
  if (name.empty()) fail(where, "<" + std::string(e->Name()) + "> needs a name attribute", e, file);
  return name;
}

// A <mesh>: <uri> (model://NAME/..., file:// or absolute, else relative to the SDF file's folder,
// as sdformat resolves it), <scale>, <submesh><name><center>.
Shape Reader::meshOf(const XMLElement* mesh, const std::string& file, const std::string& where) {
  Shape shape;
  shape.kind = ShapeKind::Mesh;
  const XMLElement* uri = mesh->FirstChildElement("uri");
  if (uri == nullptr || textOf(uri).empty()) fail(where, "<mesh> needs a <uri> (model://NAME/meshes/FILE.dae)", mesh, file);
  const std::string text = textOf(uri);
  try {
    shape.mesh_source.file = resolveMeshUri(text, file, folders_);
  } catch (const WorldError& e) {
    fail(where, e.what(), uri, file);
  }
  if (const XMLElement* scale = mesh->FirstChildElement("scale")) {
    const std::vector<double> v = numbers(textOf(scale), scale, file, where);
    if (v.size() != 3 || !(v[0] != 0 && v[1] != 0 && v[2] != 0)) fail(where, "mesh <scale> needs 3 non-zero numbers", scale, file);
    shape.mesh_source.scale = Eigen::Vector3d(v[0], v[1], v[2]);
  }
  if (const XMLElement* submesh = mesh->FirstChildElement("submesh")) {
    shape.mesh_source.submesh = textOf(submesh->FirstChildElement("name"));
    if (shape.mesh_source.submesh.empty()) fail(where, "<submesh> needs a <name>", submesh, file);
    shape.mesh_source.center_submesh = boolean(submesh->FirstChildElement("center"), file, where, false);
  }
  const std::string key = meshKey(shape.mesh_source);
  auto& loaded = meshes_[key];
  if (loaded == nullptr) {
    try {
      loaded = loadMesh(shape.mesh_source);
    } catch (const WorldError& e) {
      meshes_.erase(key);
      fail(where, e.what(), uri, file);
    }
  }
  inputs_.insert(shape.mesh_source.file);
  shape.mesh = loaded;
  return shape;
}

// Box, cylinder or mesh collision geometry; <plane> sets *is_plane; anything else is an error.
Shape Reader::shapeOf(const XMLElement* collision, const std::string& file, const std::string& where, bool* is_plane) {
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
  if (const XMLElement* mesh = geometry != nullptr ? geometry->FirstChildElement("mesh") : nullptr) {
    return meshOf(mesh, file, where);
  }
  if (geometry != nullptr && geometry->FirstChildElement("plane") != nullptr) {
    *is_plane = true;
    return shape;
  }
  fail(where, "only <box>, <cylinder> and <mesh> collision geometry is supported (make it one of them)",
       geometry != nullptr ? geometry : collision, file);
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
  skipUnread(element, file, {"static", "pose", "link", "model", "include", "plugin"});
  // A robot known by its Gazebo drive plugin has its sensors read (gazeboRobot); others' are skipped here.
  const bool gazebo_drive = hasGazeboDrive(model.plugins);
  for (const XMLElement* link = element->FirstChildElement("link"); link != nullptr; link = link->NextSiblingElement("link")) {
    if (gazebo_drive) {
      skipUnread(link, file, {"pose", "inertial", "collision", "sensor"});
    } else {
      skipUnread(link, file, {"pose", "inertial", "collision"});
    }
    for (const XMLElement* c = link->FirstChildElement("collision"); c != nullptr; c = c->NextSiblingElement("collision")) {
      skipUnread(c, file, {"pose", "geometry"});
    }
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

// The version an SDF file declares in model.config (<sdf version="1.6">), as numbers to compare.
std::vector<int> versionOf(const XMLElement* sdf) {
  std::vector<int> version;
  std::stringstream text(attribute(sdf, "version"));
  for (std::string part; std::getline(text, part, '.');) version.push_back(std::atoi(part.c_str()));
  return version;
}

// The model an <include> brings in, renamed, placed and made static as the <include> says, with
// the <include>'s plugins after its own. A model folder's file is the <sdf> its model.config names;
// of several, the newest version (as Gazebo picks). A file of a <light> (model://sun) brings in
// nothing but a line among what is skipped.
std::optional<Reader::Model> Reader::included(const XMLElement* include, const std::string& file) {
  const std::string uri = textOf(include->FirstChildElement("uri"));
  skipUnread(include, file, {"uri", "name", "pose", "static", "plugin"});
  std::string target;
  try {
    target = resolve(uri, include, file);
  } catch (const WorldError&) {
    // Gazebo ships these two with itself, so worlds include them with no model folder of theirs.
    std::string name = uri;
    while (!name.empty() && name.back() == '/') name.pop_back();
    if (name == "model://ground_plane") {
      skip(include, file, "Gazebo's built-in model://ground_plane", "the floor: Aula's robots stay on it by their planar joint");
      return std::nullopt;
    }
    if (name == "model://sun") {
      skip(include, file, "Gazebo's built-in model://sun", whySkipped("light"));
      return std::nullopt;
    }
    throw;
  }
  std::error_code error;
  if (fs::is_directory(target, error)) {
    const std::string folder = target;
    for (const auto& entry : fs::directory_iterator(folder, error)) {
      if (entry.is_regular_file(error)) inputs_.insert(entry.path().string());
    }
    tinyxml2::XMLDocument config;
    const std::string config_path = folder + "/model.config";
    parseXml(config_path, config);
    const XMLElement* root = config.RootElement();
    const XMLElement* sdf = nullptr;
    for (const XMLElement* e = root != nullptr ? root->FirstChildElement("sdf") : nullptr; e != nullptr;
         e = e->NextSiblingElement("sdf")) {
      if (sdf == nullptr || versionOf(e) > versionOf(sdf)) sdf = e;
    }
    if (sdf == nullptr || textOf(sdf).empty()) {
      throw WorldError(config_path + ": names no <sdf> file for model " + uri + " (add <sdf version=\"1.9\">model.sdf</sdf>)" +
                       at(include, file));
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
  if (element == nullptr) {
    if (const XMLElement* other = root->FirstChildElement()) {  // model://sun: a <light>
      skip(other, target, "<" + std::string(other->Name()) + "> included (" + uri + ")", whySkipped(other->Name()));
      return std::nullopt;
    }
    throw WorldError(file + ": <include><uri>" + uri + "</uri>: " + target + " has no <model>" + at(include, file));
  }
  chain_.push_back(canonical);
  Model model = modelOf(element, target);
  chain_.pop_back();
  if (const XMLElement* name = include->FirstChildElement("name")) model.name = textOf(name);
  const std::string where = file + ": model '" + model.name + "'";
  if (include->FirstChildElement("pose") != nullptr) model.pose = poseOf(include, file, where);
  model.is_static = boolean(include->FirstChildElement("static"), file, where, model.is_static);
  for (const XMLElement* p = include->FirstChildElement("plugin"); p != nullptr; p = p->NextSiblingElement("plugin")) {
    model.plugins.emplace_back(p, file);
  }
  return model;
}

// The <model>s and <include>s directly under `parent` (and, under <world>, the models each
// <population> expands into), in the file's order; names unique. A model with a problem is left
// out, the problem kept, and the others read.
std::vector<Reader::Model> Reader::childModels(const XMLElement* parent, const std::string& file, const std::string& where) {
  std::vector<Model> models;
  for (const XMLElement* e = parent->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
    const std::string kind = e->Name();
    if (kind != "model" && kind != "include" && kind != "population") continue;
    std::vector<Model> read;
    attempt([&] {
      if (kind == "model") {
        read.push_back(modelOf(e, file));
      } else if (kind == "include") {
        if (auto model = included(e, file)) read.push_back(std::move(*model));
      } else {
        read = population(e, file);
      }
    });
    for (Model& model : read) {
      const bool taken = std::any_of(models.begin(), models.end(), [&](const Model& m) { return m.name == model.name; });
      if (taken) {
        attempt([&] { fail(where, "two models named '" + model.name + "'", e, file); });
        continue;
      }
      models.push_back(std::move(model));
    }
  }
  return models;
}

namespace {
// A reproducible generator for a population's random and uniform distributions: seeded by its
// name, so that a world gives the same models on every run (Gazebo draws new ones each time).
std::mt19937_64 generatorFor(const std::string& name) {
  std::seed_seq seed(name.begin(), name.end());
  return std::mt19937_64(seed);
}

// Lloyd's k-means of `points` into k centroids (k <= points), started from k of them drawn
// without repeats: what Gazebo's "uniform" distribution places models at.
std::vector<Eigen::Vector3d> kMeans(const std::vector<Eigen::Vector3d>& points, int k, std::mt19937_64& random) {
  std::vector<std::size_t> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), random);
  std::vector<Eigen::Vector3d> centroids;
  for (int i = 0; i < k; ++i) centroids.push_back(points[order[static_cast<std::size_t>(i)]]);
  std::vector<int> label(points.size(), -1);
  for (int iteration = 0; iteration < 100; ++iteration) {
    bool changed = false;
    for (std::size_t p = 0; p < points.size(); ++p) {
      int best = 0;
      for (int c = 1; c < k; ++c) {
        if ((points[p] - centroids[c]).squaredNorm() < (points[p] - centroids[best]).squaredNorm()) best = c;
      }
      changed = changed || label[p] != best;
      label[p] = best;
    }
    if (!changed) break;
    std::vector<Eigen::Vector3d> sum(static_cast<std::size_t>(k), Eigen::Vector3d::Zero());
    std::vector<int> count(static_cast<std::size_t>(k), 0);
    for (std::size_t p = 0; p < points.size(); ++p) sum[label[p]] += points[p], ++count[label[p]];
    for (int c = 0; c < k; ++c) {
      if (count[c] > 0) centroids[c] = sum[c] / count[c];
    }
  }
  return centroids;
}
}  // namespace

// A <population> as Gazebo (classic) expands it: its one <model> cloned as NAME_clone_I, each at
// a position of the distribution (random, uniform, grid, linear-x, linear-y, linear-z) in the
// region (<box> from pose - size/2, or <cylinder> about the pose), turned by the population's
// rotation; each clone's own pose is that position with no rotation, as Gazebo writes it.
std::vector<Reader::Model> Reader::population(const XMLElement* e, const std::string& file) {
  const std::string name = attribute(e, "name");
  const std::string where = file + ": <population" + (name.empty() ? "" : " name=\"" + name + "\"") + ">";
  skipUnread(e, file, {"model", "pose", "box", "cylinder", "model_count", "distribution"});
  const XMLElement* model_element = e->FirstChildElement("model");
  if (model_element == nullptr) fail(where, "needs a <model> to clone", e, file);
  Model model = modelOf(model_element, file);
  // <model name="can"><include>...</include></model>: the included model is the one cloned.
  if (model_element->FirstChildElement("link") == nullptr && model.children.size() == 1) {
    const bool outer_static = model.is_static;
    Model inner = std::move(model.children.front());
    inner.name = model.name;
    inner.is_static = inner.is_static || outer_static;
    model = std::move(inner);
  }
  const Eigen::Isometry3d pose = poseOf(e, file, where);
  Eigen::Vector3d origin = pose.translation();
  const XMLElement* distribution = e->FirstChildElement("distribution");
  const std::string type = textOf(distribution != nullptr ? distribution->FirstChildElement("type") : nullptr);
  std::vector<Eigen::Vector3d> offsets;
  auto random = generatorFor(name + "/" + model.name);
  auto uniform = [&](double hi) { return std::uniform_real_distribution<double>(0.0, hi)(random); };
  if (type == "grid") {
    const int rows = static_cast<int>(number(distribution->FirstChildElement("rows"), file, where, 1));
    const int cols = static_cast<int>(number(distribution->FirstChildElement("cols"), file, where, 1));
    const XMLElement* step_element = distribution->FirstChildElement("step");
    const std::vector<double> step = step_element != nullptr ? numbers(textOf(step_element), step_element, file, where)
                                                             : std::vector<double>{0.5, 0.5, 0};
    if (rows <= 0 || cols <= 0 || step.size() != 3) fail(where, "a grid needs <rows> and <cols> > 0 and a <step>X Y Z</step>", distribution, file);
    origin.x() -= step[0] * (cols - 1) / 2.0;  // Gazebo centres the grid on the pose
    origin.y() -= step[1] * (rows - 1) / 2.0;
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) offsets.emplace_back(c * step[0], r * step[1], 0.0);
    }
  } else {
    if (type != "random" && type != "uniform" && type != "linear-x" && type != "linear-y" && type != "linear-z") {
      fail(where, "<distribution><type>" + type + "</type>: use random, uniform, grid, linear-x, linear-y or linear-z",
           distribution != nullptr ? distribution : e, file);
    }
    const int count = static_cast<int>(number(e->FirstChildElement("model_count"), file, where, 0));
    if (count <= 0 || count > 10000) fail(where, "needs a <model_count> from 1 to 10000", e, file);
    if (const XMLElement* box = e->FirstChildElement("box")) {
      const XMLElement* size_element = box->FirstChildElement("size");
      const std::vector<double> v = size_element != nullptr ? numbers(textOf(size_element), size_element, file, where)
                                                            : std::vector<double>{};
      if (v.size() != 3 || !(v[0] > 0 && v[1] > 0 && v[2] > 0)) fail(where, "the region's <box><size> needs 3 positive numbers", box, file);
      const Eigen::Vector3d size(v[0], v[1], v[2]);
      origin -= size / 2;
      for (int i = 0; i < count && type == "random"; ++i) {
        const double x = uniform(size.x()), y = uniform(size.y());
        offsets.emplace_back(x, y, uniform(size.z()));
      }
      if (type == "uniform") {
        std::vector<Eigen::Vector3d> samples;  // a 10 cm lattice, as Gazebo samples the box
        for (double y = 0; y < size.y(); y += 0.1) {
          for (double x = 0; x < size.x(); x += 0.1) samples.emplace_back(x, y, uniform(size.z()));
        }
        if (static_cast<int>(samples.size()) < count) fail(where, "more models than 10 cm cells in the box", box, file);
        offsets = kMeans(samples, count, random);
      }
      for (int i = 0; i < count && type.rfind("linear-", 0) == 0; ++i) {
        const int axis = type.back() - 'x';
        Eigen::Vector3d offset = size / 2;
        offset[axis] = size[axis] * i / count;
        offsets.push_back(offset);
      }
    } else if (const XMLElement* cylinder = e->FirstChildElement("cylinder")) {
      const double radius = number(cylinder->FirstChildElement("radius"), file, where, 0);
      const double length = number(cylinder->FirstChildElement("length"), file, where, 0);
      if (!(radius > 0 && length > 0)) fail(where, "the region's <cylinder> needs <radius> and <length> > 0", cylinder, file);
      if (type != "random" && type != "uniform") fail(where, "a <cylinder> region takes the random or uniform distribution", distribution, file);
      auto inCylinder = [&] {
        const double angle = uniform(2 * M_PI), r = uniform(radius);
        const double x = r * std::cos(angle), y = r * std::sin(angle);
        return Eigen::Vector3d(x, y, uniform(length));
      };
      if (type == "random") {
        for (int i = 0; i < count; ++i) offsets.push_back(inCylinder());
      } else {
        std::vector<Eigen::Vector3d> samples;
        for (int i = 0; i < 10000; ++i) samples.push_back(inCylinder());
        offsets = kMeans(samples, count, random);
      }
    } else {
      fail(where, "needs a region, <box> or <cylinder>", e, file);
    }
  }
  std::vector<Model> clones;
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    Model clone = model;
    clone.name = model.name + "_clone_" + std::to_string(i);
    clone.pose = Eigen::Isometry3d::Identity();
    clone.pose.translation() = pose.linear() * offsets[i] + origin;
    clones.push_back(std::move(clone));
  }
  return clones;
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
    const Eigen::Isometry3d link_pose = model_pose * placed(link, model, "", in_link);

    std::set<std::string> collisions;
    for (const XMLElement* c = link->FirstChildElement("collision"); c != nullptr; c = c->NextSiblingElement("collision")) {
      const std::string collision_name = nameOf(c, file, in_link);
      if (!collisions.insert(collision_name).second) fail(in_link, "two collisions named '" + collision_name + "'", c, file);
      attempt([&] {
        bool is_plane = false;
        StaticObject o;
        o.name = name + "::" + link_name + "::" + collision_name;
        o.shape = shapeOf(c, file, in_link + ", collision '" + collision_name + "'", &is_plane);
        if (is_plane) {
          skip(c, file, "<plane> collision", whySkipped("plane"));
          return;
        }
        // Composed parent * child as libsdformat did (the same bits); a relative_to from the model's frame.
        const std::string in_collision = where + ", collision '" + collision_name + "'";
        o.pose = relativeTo(c).empty() ? link_pose * poseOf(c, file, in_collision)
                                       : model_pose * placed(c, model, link_name, in_collision);
        spec.statics.push_back(o);
      });
    }
  }
  for (const Model& nested : model.children) {
    addStatics(nested, model_pose * nested.pose, name + "::", spec);
  }
}

namespace {
std::string upper(std::string text) {
  for (char& c : text) c = std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : '_';
  return text;
}

// Where a laser of `yaw_rad` (in the body's frame) faces, as Aula's worlds name their lasers, or ""
// when it faces between (more than 45 degrees from each).
std::string facing(double yaw_rad) {
  const double a = std::remainder(yaw_rad, 2 * M_PI);
  if (std::abs(a) < M_PI / 4) return "laser_front";
  if (std::abs(a) > 3 * M_PI / 4) return "laser_rear";
  if (std::abs(a + M_PI / 2) < M_PI / 4) return "laser_right";
  if (std::abs(a - M_PI / 2) < M_PI / 4) return "laser_left";
  return "";
}

// A driver of a robot that its Gazebo plugins make.
void addDriver(RobotSpec& robot, const std::string& name, const std::string& type, std::map<std::string, std::string> params) {
  PluginSpec spec;
  spec.name = name;
  spec.type = type;
  spec.owner = robot.name;
  spec.params = std::move(params);
  robot.plugins.push_back(std::move(spec));
}

std::string decimal(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}
}  // namespace

// A robot known by its Gazebo plugins (RoboticsAcademy's taxi_holo_ROS with
// libgazebo_ros_planar_move.so, RoboticsInfrastructure's Prius with libgazebo_ros_ackermann_drive.so):
// Aula's robot of that kind, its drivers made from what the model says. pose3d, motors (holonomic
// for a planar move; a car of `car`'s numbers for an Ackermann drive) and bumper (every Aula robot
// senses contact), on channels NAME_POSE, NAME_MOTORS, NAME_BUMPER; a laser per level <sensor
// type="ray"> of its links (channel NAME_LASER_SENSOR; pose in the body's frame, samples, angles,
// range, noise, rate from the sensor), named by where it faces (laser_front, laser_rear,
// laser_right, laser_left, as Aula's worlds name them) when it alone faces that way, else by the
// sensor's name. Its other Gazebo plugins and sensors are listed among what is skipped.
void Reader::gazeboDrivers(const Model& model, const XMLElement* drive, const Eigen::Isometry3d& body,
                           const std::optional<CarNumbers>& car, RobotSpec& robot) {
  const std::string prefix = upper(model.name);
  for (const auto& [p, plugin_file] : model.plugins) {
    if (p != drive) skip(p, plugin_file, "Gazebo <plugin filename=\"" + attribute(p, "filename") + "\"> of a robot", "its drive plugin makes the robot's drivers");
  }
  auto add = [&](const std::string& name, const std::string& type, std::map<std::string, std::string> params) {
    addDriver(robot, name, type, std::move(params));
  };
  add("pose3d", "pose3d", {{"channel", prefix + "_POSE"}});
  std::map<std::string, std::string> motors = {{"channel", prefix + "_MOTORS"}};
  if (car) {
    // The plugin caps the speed and the steering angle; the yaw rate follows from them.
    motors["kinematics"] = "ackermann";
    motors["wheelbase"] = decimal(car->wheelbase_m);
    motors["max_steer_rad"] = decimal(car->max_steer_rad);
    motors["rear_axle_x"] = decimal(car->rear_axle_x_m);
    motors["max_v"] = decimal(car->max_speed_mps);
    motors["max_w"] = decimal(car->max_speed_mps * std::tan(car->max_steer_rad) / car->wheelbase_m);
  } else {
    motors["holonomic"] = gazeboDrives().at(attribute(drive, "filename")) == Drive::Holonomic ? "true" : "false";
    // Gazebo's drive plugins move the robot as commanded, with no speed limit of their own: the
    // exercise's MaxV and MaxW (its motors proxy) are the limits. The driver's default (1 m/s,
    // 1 rad/s) held RoboticsAcademy's taxi to 1 m/s in its city (mark 8.77) and its roomba's turns to 1 rad/s.
    constexpr const char* kNoLimit = "1000";
    motors["max_v"] = kNoLimit;
    motors["max_w"] = kNoLimit;
  }
  add("motors", "motors", motors);
  add("bumper", "bumper", {{"channel", prefix + "_BUMPER"}});
  gazeboLasers(model, body, robot);
}

// The lasers of a robot known by its Gazebo plugins (gazeboDrivers), from its links' level rays.
void Reader::gazeboLasers(const Model& model, const Eigen::Isometry3d& body, RobotSpec& robot) {
  const std::string& file = model.file;
  const std::string where = world_path_ + ": model '" + model.name + "'";
  const std::string prefix = upper(model.name);
  struct Laser {
    std::string sensor, side;  // its <sensor>'s name, where it faces
    std::map<std::string, std::string> params;
  };
  std::vector<Laser> lasers;
  std::map<std::string, int> facings;
  for (const XMLElement* link = model.element->FirstChildElement("link"); link != nullptr; link = link->NextSiblingElement("link")) {
    const std::string link_name = attribute(link, "name");
    for (const XMLElement* sensor = link->FirstChildElement("sensor"); sensor != nullptr; sensor = sensor->NextSiblingElement("sensor")) {
      const std::string type = attribute(sensor, "type");
      const std::string name = nameOf(sensor, file, where);
      const XMLElement* ray = sensor->FirstChildElement("ray");
      if (ray == nullptr) ray = sensor->FirstChildElement("lidar");
      if ((type != "ray" && type != "gpu_ray" && type != "lidar" && type != "gpu_lidar") || ray == nullptr) {
        if (type != "contact") skip(sensor, file, "<sensor type=\"" + type + "\"> of a robot", whySkipped("sensor"));
        continue;  // a contact sensor: the bumper above
      }
      const std::string in_sensor = where + ", sensor '" + name + "'";
      // A sensor on a mount (a laser link on a fixed joint) is placed in the body's frame.
      const Eigen::Isometry3d pose = body.inverse() * placed(sensor, model, link_name, in_sensor);
      const Eigen::Vector3d z_axis = pose.linear().col(2);
      if (z_axis.z() < std::cos(0.1)) {  // a cliff sensor looks down: not a planar laser
        skip(sensor, file, "a robot's <sensor type=\"ray\"> not level", "Aula's lasers scan the plane");
        continue;
      }
      const XMLElement* scan = ray->FirstChildElement("scan");
      const XMLElement* horizontal = scan != nullptr ? scan->FirstChildElement("horizontal") : nullptr;
      const XMLElement* range = ray->FirstChildElement("range");
      const XMLElement* noise = ray->FirstChildElement("noise");
      auto value = [&](const XMLElement* parent, const char* key, double fallback) {
        return number(parent != nullptr ? parent->FirstChildElement(key) : nullptr, file, in_sensor, fallback);
      };
      if (value(horizontal, "samples", 640) < 2) {  // roombaROS's wall_sensor: an IR range finder, not the laser
        skip(sensor, file, "a robot's one-beam <sensor type=\"ray\">", "Aula's lasers scan (an infrared range finder is not one)");
        continue;
      }
      const Eigen::Vector3d at = pose.translation();
      lasers.push_back({name, facing(yawOf(pose)),
                        {{"channel", prefix + "_LASER_" + upper(name)},
                         {"pose", decimal(at.x()) + " " + decimal(at.y()) + " " + decimal(at.z()) + " 0 0 " + decimal(yawOf(pose))},
                         {"samples", std::to_string(static_cast<int>(value(horizontal, "samples", 640)))},
                         {"min_angle", decimal(value(horizontal, "min_angle", 0))},
                         {"max_angle", decimal(value(horizontal, "max_angle", 0))},
                         {"min_range", decimal(value(range, "min", 0))},
                         {"max_range", decimal(value(range, "max", 10))},
                         {"noise_stddev", decimal(value(noise, "stddev", 0))},
                         {"rate_hz", decimal(number(sensor->FirstChildElement("update_rate"), file, in_sensor, 10))}}});
      ++facings[lasers.back().side];
    }
  }
  for (const Laser& laser : lasers) {
    // A side's name is the laser's when it alone faces that way and no other sensor bears that name.
    const bool taken = std::any_of(lasers.begin(), lasers.end(), [&](const Laser& other) {
      return other.sensor == laser.side && &other != &laser;
    });
    const bool by_side = !laser.side.empty() && facings[laser.side] == 1 && !taken;
    addDriver(robot, by_side ? laser.side : laser.sensor, "laser", laser.params);
  }
}

// The outline of a link's <collision>s (`kind` "collision") or <visual>s, in the model's frame,
// added to `points`: boxes' corners, cylinders' and spheres' rims, meshes' vertices.
void Reader::outlineOf(const XMLElement* link, const Model& model, const char* kind, const std::string& where,
                       std::vector<Eigen::Vector3d>& points) {
  const std::string& file = model.file;
  const std::string link_name = attribute(link, "name");
  for (const XMLElement* c = link->FirstChildElement(kind); c != nullptr; c = c->NextSiblingElement(kind)) {
    const std::string in_collision = where + ", " + kind + " '" + nameOf(c, file, where) + "'";
    const Eigen::Isometry3d pose = placed(c, model, link_name, in_collision);
    const XMLElement* geometry = c->FirstChildElement("geometry");
    auto rim = [&](double r, double z) {
      for (int k = 0; k < 32; ++k) {
        const double a = 2 * M_PI * k / 32;
        points.push_back(pose * Eigen::Vector3d(r * std::cos(a), r * std::sin(a), z));
      }
    };
    if (const XMLElement* sphere = geometry != nullptr ? geometry->FirstChildElement("sphere") : nullptr) {
      // A caster ball: part of the body's outline (a sphere is no static geometry of Aula's).
      const double r = number(sphere->FirstChildElement("radius"), file, in_collision, 1.0);
      rim(r, 0);
      points.push_back(pose * Eigen::Vector3d(0, 0, r));
      points.push_back(pose * Eigen::Vector3d(0, 0, -r));
      continue;
    }
    bool is_plane = false;
    const Shape shape = shapeOf(c, file, in_collision, &is_plane);
    if (is_plane) continue;
    if (shape.kind == ShapeKind::Mesh) {
      skip(c, file, std::string("a robot's <mesh> ") + kind, "Aula's robot is the box or cylinder around it");
      for (const auto& v : shape.mesh->vertices_m) points.push_back(pose * v);
    } else if (shape.kind == ShapeKind::Box) {
      for (int i = 0; i < 8; ++i) {
        points.push_back(pose * Eigen::Vector3d((i & 1 ? 0.5 : -0.5) * shape.box_size_m.x(), (i & 2 ? 0.5 : -0.5) * shape.box_size_m.y(),
                                                (i & 4 ? 0.5 : -0.5) * shape.box_size_m.z()));
      }
    } else {
      rim(shape.radius_m, -0.5 * shape.length_m);
      rim(shape.radius_m, 0.5 * shape.length_m);
    }
  }
}

// An Ackermann drive's car, in the model's frame: its axles from the wheel joints the plugin names
// (front_left_joint ..., with the plugin's defaults), its steering and speed caps (max_steer 0.6
// rad, max_speed 20 m/s by default, as the plugin has them). Sets `heading` (the model-frame yaw
// from the rear axle's centre to the front's) and `rear_axle` (the rear axle's centre).
CarNumbers Reader::ackermannCar(const Model& model, const XMLElement* drive, double& heading, Eigen::Vector3d& rear_axle) const {
  const std::string where = world_path_ + ": model '" + model.name + "', plugin '" + attribute(drive, "name") + "'";
  auto joint = [&](const char* key) -> Eigen::Vector3d {
    const XMLElement* e = drive->FirstChildElement(key);
    const std::string name = e != nullptr ? textOf(e) : key;
    const bool found = [&] {
      for (const XMLElement* j = model.element->FirstChildElement("joint"); j != nullptr; j = j->NextSiblingElement("joint")) {
        if (attribute(j, "name") == name) return true;
      }
      return false;
    }();
    if (!found) fail(where, "<" + std::string(key) + ">" + name + ": the model has no <joint> of that name", e != nullptr ? e : drive, model.file);
    return frameOf(model, name, where).translation();
  };
  const Eigen::Vector3d front = (joint("front_left_joint") + joint("front_right_joint")) / 2;
  rear_axle = (joint("rear_left_joint") + joint("rear_right_joint")) / 2;
  CarNumbers car;
  car.wheelbase_m = std::hypot(front.x() - rear_axle.x(), front.y() - rear_axle.y());
  if (!(car.wheelbase_m > 0.01)) fail(where, "the front and rear wheel joints stand at the same place: no wheelbase", drive, model.file);
  heading = std::atan2(front.y() - rear_axle.y(), front.x() - rear_axle.x());
  car.max_steer_rad = number(drive->FirstChildElement("max_steer"), model.file, where, 0.6);
  car.max_speed_mps = number(drive->FirstChildElement("max_speed"), model.file, where, 20.0);
  if (!(car.max_steer_rad > 0 && car.max_steer_rad < 1.5) || !(car.max_speed_mps > 0)) {
    fail(where, "needs 0 < <max_steer> < 1.5 rad and <max_speed> > 0", drive, model.file);
  }
  return car;
}

// A robot known by its Gazebo drive plugin, of one or more links: the model is one rigid body (its
// wheels, steering and sensor mounts are part of it: listed as skipped), its links' collisions
// together its shape (their <visual>s when it has no collision at all, as RoboticsAcademy's
// taxi_holo_laser_ROS: said), a cylinder when they are round seen from above (a roomba), else the
// box around them; its mass the links' together. Its body frame is its first link's; an Ackermann
// car's is at the centre of its footprint, x from the rear axle to the front (as Aula's cars).
void Reader::addGazeboRobot(const Model& model, WorldSpec& spec) {
  const std::string where = world_path_ + ": model '" + model.name + "'";
  const std::string& file = model.file;
  const XMLElement* drive = nullptr;
  for (const auto& [p, plugin_file] : model.plugins) {
    if (gazeboDrives().count(attribute(p, "filename")) != 0) drive = p;
  }
  const XMLElement* first = model.element->FirstChildElement("link");
  if (first == nullptr) fail(where, "a robot needs a <link>", model.element, file);
  RobotSpec robot;
  robot.name = model.name;
  robot.mass_kg = 0;
  std::vector<Eigen::Vector3d> points;  // the links' collisions, in the model's frame
  for (const XMLElement* link = first; link != nullptr; link = link->NextSiblingElement("link")) {
    const XMLElement* inertial = link->FirstChildElement("inertial");
    robot.mass_kg += number(inertial != nullptr ? inertial->FirstChildElement("mass") : nullptr, file, where, link == first ? 1.0 : 0.0);
    if (link != first) skip(link, file, "a robot's <link> besides its body", "Aula's robot is one rigid body (its wheels and mounts are part of it, inside the outline of its links' collisions)");
    outlineOf(link, model, "collision", where + ", link '" + nameOf(link, file, where) + "'", points);
  }
  if (!(robot.mass_kg > 0)) fail(where, "the links need an <inertial><mass> > 0", first, file);
  if (points.empty()) {
    for (const XMLElement* link = first; link != nullptr; link = link->NextSiblingElement("link")) {
      outlineOf(link, model, "visual", where + ", link '" + attribute(link, "name") + "'", points);
    }
    if (points.empty()) fail(where, "the robot's links have no <collision> (nor a <visual>) to give its shape", first, file);
    skip(model.element, file, "a robot with no <collision>",
         "its shape is the box around its <visual>s (in Gazebo it would touch nothing; in Aula it touches what it meets)");
  }
  std::optional<CarNumbers> car;
  Eigen::Isometry3d body = placed(first, model, "", where);
  if (gazeboDrives().at(attribute(drive, "filename")) == Drive::Ackermann) {
    double heading = 0;
    Eigen::Vector3d rear_axle;
    car = ackermannCar(model, drive, heading, rear_axle);
    const Eigen::Isometry3d turned(Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()));
    Eigen::AlignedBox3d footprint;
    for (const auto& p : points) footprint.extend(turned.inverse() * p);
    const Eigen::Vector3d centre = footprint.center();
    body = turned * Eigen::Translation3d(centre.x(), centre.y(), 0);
    car->rear_axle_x_m = (body.inverse() * rear_axle).x();
    if (std::abs(car->rear_axle_x_m) > car->wheelbase_m) {
      fail(where, "the rear axle lies outside the car's outline (its collisions): check the wheel joints' poses", drive, file);
    }
    skip(drive, file, "Ackermann drive <plugin filename=\"" + attribute(drive, "filename") + "\">",
         "Aula's car turns about its rear axle's centre, no tighter than max_steer allows; wheelbase between the wheel joints; "
         "its shape the box around its links' collisions, centred on it");
  }
  robot.pose = model.pose * body;
  for (auto& p : points) p = body.inverse() * p;
  Eigen::AlignedBox3d bounds;
  for (const auto& p : points) bounds.extend(p);
  const Eigen::Vector3d centre = bounds.center(), size = bounds.sizes();
  double reach = 0;
  for (const auto& p : points) reach = std::max(reach, std::hypot(p.x() - centre.x(), p.y() - centre.y()));
  const double half = std::max(size.x(), size.y()) / 2;
  robot.shape_offset = Eigen::Isometry3d(Eigen::Translation3d(centre));
  // Round: no corner sticks out (a box's reaches 1.41 times its half width). RoboticsInfrastructure's
  // roombaROS reaches 1.022 times: its bumpers' arcs reach 0.175 m, 1 cm past its 0.165 m body,
  // and at 1.02 it was a 0.332 x 0.343 m box, which could not turn on the spot beside a wall or a
  // sofa 5 cm off (30 s of bumps at a time in its house).
  if (!car && std::abs(size.x() - size.y()) < 0.05 * 2 * half && reach <= 1.1 * half) {
    robot.shape.kind = ShapeKind::Cylinder;
    robot.shape.radius_m = std::max(half, reach);  // around every point
    robot.shape.length_m = size.z();
  } else {
    robot.shape.box_size_m = size;
  }
  if (!(robot.shape.kind == ShapeKind::Cylinder ? robot.shape.length_m > 0 : size.minCoeff() > 0)) {
    fail(where, "the robot's collisions have no volume", first, file);
  }
  gazeboDrivers(model, drive, body, car, robot);
  const bool duplicate = std::any_of(spec.robots.begin(), spec.robots.end(),
                                     [&](const RobotSpec& other) { return other.name == robot.name; });
  if (duplicate) fail(where, "duplicate robot name", model.element, file);
  spec.robots.push_back(std::move(robot));
}

// A non-static model that nothing drives: it has links, and no plugin but Gazebo's own that drive
// nothing (an Aula driver or a Gazebo drive makes a robot; any other filename is a driver's typo,
// said as such when it is read as a robot).
bool Reader::keptStill(const Model& model) {
  if (model.element->FirstChildElement("link") == nullptr || hasGazeboDrive(model.plugins)) return false;
  return std::all_of(model.plugins.begin(), model.plugins.end(), [](const auto& p) {
    const std::string filename = attribute(p.first, "filename");
    return pluginKeys().count(filename) == 0 && gazeboLibrary(filename);
  });
}

// A world's model: static geometry, a robot, or a container (no link, no plugin, only nested
// models, as JdeRobot's house_int2 holds its furniture) whose nested models are each what their
// own <static> says, placed by the container's pose.
void Reader::addModel(const Model& model, WorldSpec& spec) {
  if (model.is_static) {
    addStatics(model, model.pose, "", spec);
    return;
  }
  if (model.element->FirstChildElement("link") == nullptr && model.plugins.empty() && !model.children.empty()) {
    for (const Model& nested : model.children) {
      Model placed = nested;
      placed.pose = model.pose * nested.pose;
      if (placed.is_static) {
        attempt([&] { addStatics(placed, placed.pose, model.name + "::", spec); });
      } else {
        attempt([&] { addModel(placed, spec); });
      }
    }
    return;
  }
  if (keptStill(model)) {
    // RoboticsAcademy's parked cars: <static>false</static>, no plugin; Gazebo would let them be pushed.
    skip(model.element, model.file, "a model not static in the file, with no drive",
         "Aula keeps it still, as static geometry (Aula has no movable obstacles)");
    Model still = model;
    for (const auto& [p, plugin_file] : model.plugins) {
      skip(p, plugin_file, "Gazebo <plugin filename=\"" + attribute(p, "filename") + "\"> of a model kept still", "it drives nothing Aula moves");
    }
    still.plugins.clear();
    addStatics(still, still.pose, "", spec);
    return;
  }
  addRobot(model, spec);
}

// A robot: one link, one collision, drivers as plugins.
void Reader::addRobot(const Model& model, WorldSpec& spec) {
  try {
    addRobotOrThrow(model, spec);
  } catch (const WorldError& e) {
    // A robot refused for its body: its drivers' problems are said in the same pass, after it.
    for (const auto& p : e.problems()) problems_.push_back(p);
    const bool gazebo_drive = hasGazeboDrive(model.plugins);
    if (gazebo_drive) return;  // its drivers are made from its Gazebo plugins, not read from them
    WorldSpec alone;
    alone.source_path = world_path_;
    alone.robots.emplace_back();
    alone.robots.back().name = model.name;
    attempt([&] { alone.robots.back().plugins = pluginsOf(model, world_path_ + ": model '" + model.name + "'"); });
    std::vector<std::string> driver_problems;
    checkPluginKeys(alone, driver_problems);
    problems_.insert(problems_.end(), driver_problems.begin(), driver_problems.end());
  }
}

void Reader::addRobotOrThrow(const Model& model, WorldSpec& spec) {
  const std::string where = world_path_ + ": model '" + model.name + "'";
  const std::string& file = model.file;
  const XMLElement* e = model.element;
  if (!model.children.empty()) {
    fail(where, "a robot (non-static model) cannot nest models", e, file);
  }
  const bool gazebo_drive = hasGazeboDrive(model.plugins);
  if (gazebo_drive) {
    addGazeboRobot(model, spec);
    return;
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
  const XMLElement* geometry = collision->FirstChildElement("geometry");
  if (geometry != nullptr && geometry->FirstChildElement("mesh") != nullptr) {  // refused before it is read
    fail(in_collision, "a robot's collision must be a <box> or a <cylinder> (its footprint); a mesh or plane is not",
         geometry->FirstChildElement("mesh"), file);
  }
  robot.pose = model.pose * poseOf(link, file, where + ", link '" + link_name + "'");
  bool is_plane = false;
  robot.shape = shapeOf(collision, file, in_collision, &is_plane);
  if (is_plane) {
    fail(in_collision, "a robot's collision must be a <box> or a <cylinder> (its footprint); a mesh or plane is not", collision, file);
  }
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

void Reader::read(WorldSpec& spec, std::vector<std::string>& inputs, std::vector<std::string>& problems) {
  std::error_code error;
  chain_.push_back(fs::weakly_canonical(world_path_, error).string());
  attempt([&] {
    const XMLElement* root = load(world_path_);
    const XMLElement* world = root->FirstChildElement("world");
    if (world == nullptr || world->NextSiblingElement("world") != nullptr) {
      throw WorldError(world_path_ + ": expected exactly one <world>" + at(root, world_path_));
    }
    spec.name = nameOf(world, world_path_, world_path_);
    spec.source_path = world_path_;
    skipUnread(root, world_path_, {"world"});
    skipUnread(world, world_path_, {"model", "include", "population", "aula:destination", "physics"});
    // Only a step the file states counts (libsdformat's default <physics> was 1 ms); the rest of
    // <physics> (the engine, its solver) is Gazebo's.
    if (const XMLElement* physics = world->FirstChildElement("physics")) {
      attempt([&] {
        if (const XMLElement* step = physics->FirstChildElement("max_step_size")) {
          spec.physics_step_s = number(step, world_path_, world_path_ + ": <physics>", 0.0);
        }
      });
      skipUnread(physics, world_path_, {"max_step_size"});
      if (!attribute(physics, "type").empty()) {
        skip(physics, world_path_, "<physics type=\"" + attribute(physics, "type") + "\">", whySkipped("physics"));
      }
    }
    attempt([&] { readDestinations(world, spec); });
    for (const Model& model : childModels(world, world_path_, world_path_)) attempt([&] { addModel(model, spec); });
  });
  for (const auto& [kind, s] : skipped_) {
    spec.skipped.push_back(kind + (s.count > 1 ? " x" + std::to_string(s.count) + " (first at " : " (") + s.first + "): " + s.why);
  }
  inputs.assign(inputs_.begin(), inputs_.end());
  problems.insert(problems.end(), problems_.begin(), problems_.end());
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
    throw WorldError(text + " (add a folder with AULA_MODEL_PATH or GAZEBO_MODEL_PATH)");
  }
  const bool file_scheme = uri.rfind("file://", 0) == 0;
  const std::string target = file_scheme ? uri.substr(7) : uri;
  if ((!file_scheme && uri.find("://") != std::string::npos) || target.empty() || target[0] != '/') {
    throw WorldError(file + ": <include><uri>" + uri + "</uri>: give model://NAME (found on the model path) or an absolute path");
  }
  if (!fs::exists(target, error)) throw WorldError(file + ": <include><uri>" + uri + "</uri>: no such file");
  return target;
}

std::string resolveMeshUri(const std::string& uri, const std::string& file, const std::vector<std::string>& folders) {
  namespace fs = std::filesystem;
  std::error_code error;
  std::string target;
  if (uri.rfind("model://", 0) == 0) {
    target = resolveInclude(uri, file, folders);
  } else if (uri.rfind("file://", 0) == 0) {
    target = uri.substr(7);
  } else if (uri.find("://") != std::string::npos) {
    throw WorldError("<uri>" + uri + "</uri>: give model://NAME/FILE, file:///PATH, or a path relative to " + file);
  } else {
    target = uri[0] == '/' ? uri : (fs::path(file).parent_path() / uri).lexically_normal().string();
  }
  if (!fs::is_regular_file(target, error)) throw WorldError("<uri>" + uri + "</uri>: no such mesh file " + target);
  return target;
}

std::string meshKey(const MeshSource& source) {
  std::ostringstream key;
  key.precision(17);
  key << source.file << '\n' << source.scale.transpose() << '\n' << source.submesh << '\n' << source.center_submesh;
  return key.str();
}

void readSdfWorld(const std::string& path, const std::vector<std::string>& folders, WorldSpec& spec,
                  std::vector<std::string>& inputs, std::vector<std::string>& problems) {
  Reader(path, folders).read(spec, inputs, problems);
}

void parseSdfWorld(const std::string& path, const std::vector<std::string>& folders, WorldSpec& spec,
                   std::vector<std::string>& inputs) {
  std::vector<std::string> problems;
  readSdfWorld(path, folders, spec, inputs, problems);
  if (!problems.empty()) throw WorldError(problems);
}

}  // namespace aula::world
