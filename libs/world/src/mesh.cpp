// Mesh collisions through assimp (libassimp-dev, Debian 12 and 13), baked into plain triangles.
#include "aula/world/mesh.hpp"

#include <aula/world/world_spec.hpp>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace aula::world {
namespace {

Eigen::Matrix4d matrixOf(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return out;
}

// Every mesh under `node`, each with its node's world transform (root first), or only the ones
// named `wanted` (the mesh's own name or its node's).
void collect(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& parent, const std::string& wanted,
             TriangleMesh& out, std::set<std::string>& names) {
  const Eigen::Matrix4d transform = parent * matrixOf(node.mTransformation);
  const std::string node_name = node.mName.C_Str();
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
    const std::string mesh_name = mesh.mName.C_Str();
    if (!node_name.empty()) names.insert(node_name);
    if (!mesh_name.empty()) names.insert(mesh_name);
    if (!wanted.empty() && wanted != mesh_name && wanted != node_name) continue;
    const auto base = static_cast<std::uint32_t>(out.vertices_m.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      out.vertices_m.push_back((transform * Eigen::Vector4d(p.x, p.y, p.z, 1.0)).head<3>());
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines (aiProcess_SortByPType drops them) touch nothing
      out.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) collect(scene, *node.mChildren[c], transform, wanted, out, names);
}

}  // namespace

std::shared_ptr<const TriangleMesh> loadMesh(const MeshSource& source) {
  Assimp::Importer importer;
  // Gazebo keeps a COLLADA file's axes as they are (z up) whatever its <up_axis> says; assimp
  // would turn a Z_UP file to its own y up. Its <unit meter> stays applied, as in Gazebo.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(source.file, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                                            aiProcess_SortByPType);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    throw WorldError(source.file + ": cannot read the mesh (" + importer.GetErrorString() +
                     "); Aula reads COLLADA .dae, STL and OBJ meshes");
  }
  auto mesh = std::make_shared<TriangleMesh>();
  std::set<std::string> names;
  collect(*scene, *scene->mRootNode, Eigen::Matrix4d::Identity(), source.submesh, *mesh, names);
  if (mesh->triangles.empty()) {
    if (source.submesh.empty()) throw WorldError(source.file + ": the mesh has no triangles");
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    throw WorldError(source.file + ": no sub-mesh named '" + source.submesh + "' (it has: " +
                     (known.empty() ? "none" : known) + ")");
  }
  Eigen::AlignedBox3d box;
  for (const auto& v : mesh->vertices_m) box.extend(v);
  const Eigen::Vector3d shift = source.center_submesh && !source.submesh.empty() ? Eigen::Vector3d(-box.center())
                                                                                 : Eigen::Vector3d::Zero();
  mesh->bounds_m.setEmpty();
  for (auto& v : mesh->vertices_m) {
    v = (v + shift).cwiseProduct(source.scale);
    mesh->bounds_m.extend(v);
  }
  mesh->file_sha256 = sha256OfFile(source.file);
  return mesh;
}

void sliceMesh(const TriangleMesh& mesh, const Eigen::Isometry3d& pose, double z_m, std::vector<geometry::Segment2>& out) {
  std::vector<Eigen::Vector3d> world(mesh.vertices_m.size());
  for (std::size_t i = 0; i < world.size(); ++i) world[i] = pose * mesh.vertices_m[i];
  for (const auto& t : mesh.triangles) {
    Eigen::Vector2d cut[3];
    int n = 0;
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector3d& p = world[t[e]];
      const Eigen::Vector3d& q = world[t[(e + 1) % 3]];
      // Half-open on each edge (a vertex on the plane counts as above), so that a plane through a
      // vertex gives one crossing per edge pair, never a lone point.
      const bool p_above = p.z() >= z_m, q_above = q.z() >= z_m;
      if (p_above == q_above) continue;
      const double s = (z_m - p.z()) / (q.z() - p.z());
      if (n < 3) cut[n++] = (p + s * (q - p)).head<2>();
    }
    if (n == 2 && (cut[0] - cut[1]).squaredNorm() > 0) out.push_back({cut[0], cut[1]});
  }
}

namespace {
// The part of polygon `in` with z >= z (keep_above) or z <= z, Sutherland-Hodgman on one plane.
std::vector<Eigen::Vector3d> clipZ(const std::vector<Eigen::Vector3d>& in, double z, bool keep_above) {
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Eigen::Vector3d& p = in[i];
    const Eigen::Vector3d& q = in[(i + 1) % in.size()];
    const bool p_in = keep_above ? p.z() >= z : p.z() <= z;
    const bool q_in = keep_above ? q.z() >= z : q.z() <= z;
    if (p_in) out.push_back(p);
    if (p_in != q_in) out.push_back(p + (z - p.z()) / (q.z() - p.z()) * (q - p));
  }
  return out;
}
}  // namespace

void projectMesh(const TriangleMesh& mesh, const Eigen::Isometry3d& pose, double z_min_m, double z_max_m,
                 std::vector<std::vector<Eigen::Vector2d>>& out) {
  for (const auto& t : mesh.triangles) {
    std::vector<Eigen::Vector3d> poly = {pose * mesh.vertices_m[t[0]], pose * mesh.vertices_m[t[1]],
                                         pose * mesh.vertices_m[t[2]]};
    const double lo = std::min({poly[0].z(), poly[1].z(), poly[2].z()});
    const double hi = std::max({poly[0].z(), poly[1].z(), poly[2].z()});
    if (hi < z_min_m || lo > z_max_m) continue;
    if (lo < z_min_m) poly = clipZ(poly, z_min_m, true);
    if (hi > z_max_m && poly.size() >= 3) poly = clipZ(poly, z_max_m, false);
    if (poly.size() < 2) continue;
    std::vector<Eigen::Vector2d> flat;
    for (const auto& p : poly) flat.push_back(p.head<2>());
    out.push_back(std::move(flat));
  }
}

}  // namespace aula::world
