#pragma once
// A mesh collision (<geometry><mesh>: COLLADA .dae, STL, OBJ), read with assimp as Gazebo reads
// it: every node's transform applied (a COLLADA <node><matrix> scaling x and y by 250 gives a
// 500 m city from a [-1, 1] mesh), COLLADA's <unit meter> applied, its <up_axis> not (Gazebo
// keeps the file's z up), then <scale>, then the <submesh> chosen (and centred). What is left is
// plain triangles in the collision's frame: the one form every user of geometry takes it in
// (the lasers' and maps' cross-sections, DART's contacts).

#include <aula/geometry/raycaster2d.hpp>

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace aula::world {

// What a <mesh> says: the file (resolved), <scale>, <submesh><name> and <center>.
struct MeshSource {
  std::string file;
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  std::string submesh;           // empty: the whole mesh
  bool center_submesh = false;   // the sub-mesh's bounding-box centre moved to the frame's origin
};

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices_m;                 // in the collision frame
  std::vector<std::array<std::uint32_t, 3>> triangles;     // vertex indices
  Eigen::AlignedBox3d bounds_m;                            // of vertices_m
  std::string file_sha256;                                 // of the mesh file (maps' cache keys)
};

// Reads the mesh. Throws WorldError naming the file and what is wrong (unreadable, no triangles,
// no sub-mesh of that name: the names it has are listed).
std::shared_ptr<const TriangleMesh> loadMesh(const MeshSource& source);

// What a horizontal plane at height z_m cuts of the mesh placed at `pose` (world frame): one
// segment per triangle it crosses (a closed solid gives closed outlines).
void sliceMesh(const TriangleMesh& mesh, const Eigen::Isometry3d& pose, double z_m,
               std::vector<geometry::Segment2>& out);

// The mesh's triangles placed at `pose`, clipped to the heights [z_min_m, z_max_m] and seen from
// above: the polygon each leaves (3 to 5 corners, in order; degenerate for a vertical wall).
void projectMesh(const TriangleMesh& mesh, const Eigen::Isometry3d& pose, double z_min_m, double z_max_m,
                 std::vector<std::vector<Eigen::Vector2d>>& out);

}  // namespace aula::world
