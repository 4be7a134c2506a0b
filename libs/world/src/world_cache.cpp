#include "world_cache.hpp"
#include "world_sdf.hpp"
#include "reader_version.hpp"

#include <aula/config/paths.hpp>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

namespace aula::world {
namespace {

// The format's version, then the reader's own (its sources' SHA-256, reader_version.hpp): an entry
// written by another reader is never read, with no version to remember to raise.
const std::string& header() {
  static const std::string text = std::string("aula-world-cache-v5 ") + kReaderSourceSha256;
  return text;
}

std::string entryPath(const std::string& key) { return config::cacheDir() + "/" + entryName(key); }

// Strings on one tab-separated line: backslash, tab and newline escaped.
std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\\') out += "\\\\";
    else if (c == '\t') out += "\\t";
    else if (c == '\n') out += "\\n";
    else out += c;
  }
  return out;
}

std::string unescape(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\' || i + 1 == text.size()) {
      out += text[i];
      continue;
    }
    const char next = text[++i];
    out += next == 't' ? '\t' : next == 'n' ? '\n' : next;
  }
  return out;
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t tab; (tab = line.find('\t', start)) != std::string::npos; start = tab + 1) {
    out.push_back(unescape(line.substr(start, tab - start)));
  }
  out.push_back(unescape(line.substr(start)));
  return out;
}

// Numbers printed so that they read back exactly: the cached spec equals the parsed one.
std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string numbers(const Eigen::Isometry3d& pose) {
  std::string out;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) out += (out.empty() ? "" : " ") + number(pose.matrix()(r, c));
  }
  return out;
}

std::string numbers(const Shape& shape) {
  return std::to_string(static_cast<int>(shape.kind)) + " " + number(shape.box_size_m.x()) + " " +
         number(shape.box_size_m.y()) + " " + number(shape.box_size_m.z()) + " " + number(shape.radius_m) + " " +
         number(shape.length_m);
}

Eigen::Isometry3d readPose(std::istream& in) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) in >> pose.matrix()(r, c);
  }
  return pose;
}

Shape readShape(std::istream& in) {
  Shape shape;
  int kind = 0;
  in >> kind >> shape.box_size_m.x() >> shape.box_size_m.y() >> shape.box_size_m.z() >> shape.radius_m >> shape.length_m;
  shape.kind = kind == 2 ? ShapeKind::Mesh : kind == 1 ? ShapeKind::Cylinder : ShapeKind::Box;
  return shape;
}

std::optional<WorldSpec> parseEntry(std::istream& in) {
  std::string line;
  if (!std::getline(in, line) || line != header()) return std::nullopt;
  WorldSpec spec;
  // A mesh's triangles are not kept in the entry (a city is megabytes of them): its file, listed
  // among the inputs with its SHA-256, is read again, once per mesh.
  std::map<std::string, std::shared_ptr<const TriangleMesh>> meshes;
  bool ended = false;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = fields(line);
    const std::string& kind = f[0];
    if (kind == "input" && f.size() == 3) {
      std::error_code error;
      if (!std::filesystem::is_regular_file(f[2], error) || sha256OfFile(f[2]) != f[1]) return std::nullopt;  // stale
    } else if (kind == "world" && f.size() == 5) {
      spec.name = f[1];
      spec.source_path = f[2];
      spec.sha256 = f[3];
      spec.physics_step_s = std::stod(f[4]);
    } else if (kind == "static" && f.size() == 4) {
      StaticObject object;
      object.name = f[1];
      std::istringstream shape(f[2]), pose(f[3]);
      object.shape = readShape(shape);
      object.pose = readPose(pose);
      if (!shape || !pose) return std::nullopt;
      spec.statics.push_back(object);
    } else if (kind == "mesh" && f.size() == 5 && !spec.statics.empty() && spec.statics.back().shape.kind == ShapeKind::Mesh) {
      Shape& shape = spec.statics.back().shape;
      shape.mesh_source.file = f[1];
      std::istringstream scale(f[2]);
      scale >> shape.mesh_source.scale.x() >> shape.mesh_source.scale.y() >> shape.mesh_source.scale.z();
      if (!scale) return std::nullopt;
      shape.mesh_source.submesh = f[3];
      shape.mesh_source.center_submesh = f[4] == "1";
      auto& mesh = meshes[meshKey(shape.mesh_source)];
      if (mesh == nullptr) mesh = loadMesh(shape.mesh_source);
      shape.mesh = mesh;
    } else if (kind == "skipped" && f.size() == 2) {
      spec.skipped.push_back(f[1]);
    } else if (kind == "robot" && f.size() == 6) {
      RobotSpec robot;
      robot.name = f[1];
      robot.mass_kg = std::stod(f[2]);
      std::istringstream shape(f[3]), pose(f[4]), offset(f[5]);
      robot.shape = readShape(shape);
      robot.pose = readPose(pose);
      robot.shape_offset = readPose(offset);
      if (!shape || !pose || !offset) return std::nullopt;
      spec.robots.push_back(robot);
    } else if (kind == "destination" && f.size() == 4) {
      spec.destinations.push_back(Destination{f[1], std::stod(f[2]), std::stod(f[3])});
    } else if (kind == "plugin" && f.size() == 4 && !spec.robots.empty()) {
      spec.robots.back().plugins.push_back(PluginSpec{f[1], f[2], {}, f[3]});
    } else if (kind == "param" && f.size() == 3 && !spec.robots.empty() && !spec.robots.back().plugins.empty()) {
      spec.robots.back().plugins.back().params[f[1]] = f[2];
    } else if (kind == "end") {
      ended = true;
    } else {
      return std::nullopt;
    }
  }
  if (!ended) return std::nullopt;  // a truncated entry
  for (const auto& object : spec.statics) {
    if (object.shape.kind == ShapeKind::Mesh && object.shape.mesh == nullptr) return std::nullopt;
  }
  return spec;
}

}  // namespace

std::string worldCacheKey(const std::string& path, const std::vector<std::string>& model_folders) {
  std::string key = header() + "\n" + std::filesystem::absolute(path).string() + "\n";
  for (const auto& folder : model_folders) key += folder + "\n";
  return sha256Hex(key);
}

std::string entryName(const std::string& key) { return "worlds/" + key + ".txt"; }

std::vector<std::string> cachedInputs(const std::string& key) {
  std::ifstream in(entryPath(key));
  std::vector<std::string> inputs;
  std::string line;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = fields(line);
    if (f.size() == 3 && f[0] == "input") inputs.push_back(f[2]);
  }
  return inputs;
}

std::optional<WorldSpec> readCachedWorld(const std::string& key) {
  std::ifstream in(entryPath(key));
  if (!in) return std::nullopt;
  try {
    return parseEntry(in);
  } catch (const std::exception&) {  // a damaged entry (a number that does not read): parse the world
    return std::nullopt;
  }
}

void writeCachedWorld(const std::string& key, const WorldSpec& spec, const std::vector<std::string>& inputs) {
  std::ostringstream out;
  out << header() << "\n";
  for (const auto& input : inputs) out << "input\t" << sha256OfFile(input) << "\t" << escape(input) << "\n";
  out << "world\t" << escape(spec.name) << "\t" << escape(spec.source_path) << "\t" << spec.sha256 << "\t"
      << number(spec.physics_step_s) << "\n";
  for (const auto& d : spec.destinations) {
    out << "destination\t" << escape(d.name) << "\t" << number(d.x_m) << "\t" << number(d.y_m) << "\n";
  }
  for (const auto& object : spec.statics) {
    out << "static\t" << escape(object.name) << "\t" << numbers(object.shape) << "\t" << numbers(object.pose) << "\n";
    if (object.shape.kind == ShapeKind::Mesh) {
      const MeshSource& m = object.shape.mesh_source;
      out << "mesh\t" << escape(m.file) << "\t" << number(m.scale.x()) << " " << number(m.scale.y()) << " "
          << number(m.scale.z()) << "\t" << escape(m.submesh) << "\t" << (m.center_submesh ? "1" : "0") << "\n";
    }
  }
  for (const auto& line : spec.skipped) out << "skipped\t" << escape(line) << "\n";
  for (const auto& robot : spec.robots) {
    out << "robot\t" << escape(robot.name) << "\t" << number(robot.mass_kg) << "\t" << numbers(robot.shape) << "\t"
        << numbers(robot.pose) << "\t" << numbers(robot.shape_offset) << "\n";
    for (const auto& plugin : robot.plugins) {
      out << "plugin\t" << escape(plugin.name) << "\t" << escape(plugin.type) << "\t" << escape(plugin.owner) << "\n";
      for (const auto& [name, value] : plugin.params) out << "param\t" << escape(name) << "\t" << escape(value) << "\n";
    }
  }
  out << "end\n";
  const std::string path = entryPath(key);
  std::error_code error;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), error);
  if (error) return;
  const std::string partial = path + "." + std::to_string(::getpid()) + ".tmp";
  {
    std::ofstream file(partial, std::ios::binary);
    file << out.str();
    if (!file.flush()) return;
  }
  std::filesystem::rename(partial, path, error);
}

}  // namespace aula::world
