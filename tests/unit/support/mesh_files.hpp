#pragma once
// Mesh files a test writes itself (no shipped or downloaded mesh): solid boxes as triangles, in
// a COLLADA 1.4.1 file (a node matrix, a <unit>, an <up_axis>, as Blender writes them) or an
// ASCII STL file. Each box is closed and its faces point outwards.

#include <Eigen/Core>

#include <array>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace aula::testing {

struct MeshBox {
  Eigen::Vector3d min, max;
};

// The 12 triangles (36 corners) of each box; with `ground`, two more covering [-g, g]^2 at z = 0.
inline std::vector<Eigen::Vector3d> boxTriangles(const std::vector<MeshBox>& boxes, double ground = 0.0) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& b : boxes) {
    auto corner = [&](int i) {
      return Eigen::Vector3d((i & 1) ? b.max.x() : b.min.x(), (i & 2) ? b.max.y() : b.min.y(), (i & 4) ? b.max.z() : b.min.z());
    };
    // Each face as a quad, counter-clockwise seen from outside.
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) {
      for (const int i : {f[0], f[1], f[2], f[0], f[2], f[3]}) out.push_back(corner(i));
    }
  }
  if (ground > 0) {
    const Eigen::Vector3d a(-ground, -ground, 0), b(ground, -ground, 0), c(ground, ground, 0), d(-ground, ground, 0);
    for (const auto& p : {a, b, c, a, c, d}) out.push_back(p);
  }
  return out;
}

// A COLLADA file of the triangles: one geometry named `geometry_name` under one node with the
// given 4x4 matrix (row-major, as COLLADA writes it), in `unit_m` metres per unit.
inline void writeCollada(const std::string& path, const std::vector<std::vector<Eigen::Vector3d>>& geometries,
                         const std::vector<std::string>& names, const std::string& node_matrix = "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1",
                         double unit_m = 1.0, const std::string& up_axis = "Z_UP") {
  std::ostringstream g, nodes;
  for (std::size_t k = 0; k < geometries.size(); ++k) {
    const auto& corners = geometries[k];
    const std::string id = names[k];
    g << "    <geometry id=\"" << id << "-mesh\" name=\"" << id << "\"><mesh>\n"
      << "      <source id=\"" << id << "-pos\"><float_array id=\"" << id << "-pos-array\" count=\"" << 3 * corners.size() << "\">";
    for (const auto& p : corners) g << p.x() << " " << p.y() << " " << p.z() << " ";
    g << "</float_array>\n      <technique_common><accessor source=\"#" << id << "-pos-array\" count=\"" << corners.size()
      << "\" stride=\"3\"><param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" "
         "type=\"float\"/></accessor></technique_common></source>\n"
      << "      <vertices id=\"" << id << "-vtx\"><input semantic=\"POSITION\" source=\"#" << id << "-pos\"/></vertices>\n"
      << "      <triangles count=\"" << corners.size() / 3 << "\"><input semantic=\"VERTEX\" source=\"#" << id
      << "-vtx\" offset=\"0\"/><p>";
    for (std::size_t i = 0; i < corners.size(); ++i) g << i << " ";
    g << "</p></triangles>\n    </mesh></geometry>\n";
    nodes << "      <node id=\"" << id << "\" name=\"" << id << "\" type=\"NODE\"><matrix sid=\"transform\">" << node_matrix
          << "</matrix><instance_geometry url=\"#" << id << "-mesh\"/></node>\n";
  }
  std::ofstream(path) << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
                      << "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
                      << "  <asset><unit name=\"u\" meter=\"" << unit_m << "\"/><up_axis>" << up_axis << "</up_axis></asset>\n"
                      << "  <library_geometries>\n" << g.str() << "  </library_geometries>\n"
                      << "  <library_visual_scenes><visual_scene id=\"Scene\" name=\"Scene\">\n" << nodes.str()
                      << "  </visual_scene></library_visual_scenes>\n"
                      << "  <scene><instance_visual_scene url=\"#Scene\"/></scene>\n</COLLADA>\n";
}

// An ASCII STL file of the triangles.
inline void writeStl(const std::string& path, const std::vector<Eigen::Vector3d>& corners) {
  std::ofstream out(path);
  out << "solid walls\n";
  for (std::size_t i = 0; i + 2 < corners.size(); i += 3) {
    const Eigen::Vector3d n = (corners[i + 1] - corners[i]).cross(corners[i + 2] - corners[i]).normalized();
    out << " facet normal " << n.x() << " " << n.y() << " " << n.z() << "\n  outer loop\n";
    for (int k = 0; k < 3; ++k) out << "   vertex " << corners[i + k].x() << " " << corners[i + k].y() << " " << corners[i + k].z() << "\n";
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid walls\n";
}

}  // namespace aula::testing
