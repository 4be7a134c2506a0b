#pragma once
// Two WorldSpecs equal in every field, bit for bit (the cache's entry against the parse, Aula's
// reader against libsdformat): a wall moved by one bit is a failure.
#include <aula/world/world_spec.hpp>

#include <gtest/gtest.h>

#include <sstream>

namespace aula::world::testing {

inline std::string matrixText(const Eigen::Isometry3d& pose) {
  std::ostringstream out;
  out.precision(17);
  out << pose.matrix();
  return out.str();
}

inline void expectSamePose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, const std::string& what) {
  EXPECT_TRUE(a.matrix() == b.matrix()) << what << "\n" << matrixText(a) << "\n!=\n" << matrixText(b);
}

inline void expectSameShape(const Shape& a, const Shape& b, const std::string& what) {
  EXPECT_EQ(a.kind, b.kind) << what;
  EXPECT_TRUE(a.box_size_m == b.box_size_m) << what;
  EXPECT_EQ(a.radius_m, b.radius_m) << what;
  EXPECT_EQ(a.length_m, b.length_m) << what;
  EXPECT_EQ(a.mesh_source.file, b.mesh_source.file) << what;
  EXPECT_TRUE(a.mesh_source.scale == b.mesh_source.scale) << what;
  EXPECT_EQ(a.mesh_source.submesh, b.mesh_source.submesh) << what;
  EXPECT_EQ(a.mesh_source.center_submesh, b.mesh_source.center_submesh) << what;
  ASSERT_EQ(a.mesh == nullptr, b.mesh == nullptr) << what;
  if (a.mesh != nullptr) {
    EXPECT_TRUE(a.mesh->vertices_m == b.mesh->vertices_m) << what;
    EXPECT_TRUE(a.mesh->triangles == b.mesh->triangles) << what;
  }
}

inline void expectSameWorld(const WorldSpec& a, const WorldSpec& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.source_path, b.source_path);
  EXPECT_EQ(a.sha256, b.sha256);
  EXPECT_EQ(a.physics_step_s, b.physics_step_s);
  ASSERT_EQ(a.destinations.size(), b.destinations.size());
  for (std::size_t i = 0; i < a.destinations.size(); ++i) {
    EXPECT_EQ(a.destinations[i].name, b.destinations[i].name);
    EXPECT_EQ(a.destinations[i].x_m, b.destinations[i].x_m);
    EXPECT_EQ(a.destinations[i].y_m, b.destinations[i].y_m);
  }
  ASSERT_EQ(a.statics.size(), b.statics.size());
  for (std::size_t i = 0; i < a.statics.size(); ++i) {
    EXPECT_EQ(a.statics[i].name, b.statics[i].name);
    expectSamePose(a.statics[i].pose, b.statics[i].pose, a.statics[i].name);
    expectSameShape(a.statics[i].shape, b.statics[i].shape, a.statics[i].name);
  }
  ASSERT_EQ(a.robots.size(), b.robots.size());
  for (std::size_t r = 0; r < a.robots.size(); ++r) {
    const RobotSpec &x = a.robots[r], &y = b.robots[r];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.mass_kg, y.mass_kg) << x.name;
    expectSamePose(x.pose, y.pose, x.name);
    expectSamePose(x.shape_offset, y.shape_offset, x.name + ", its shape");
    expectSameShape(x.shape, y.shape, x.name);
    ASSERT_EQ(x.plugins.size(), y.plugins.size()) << x.name;
    for (std::size_t p = 0; p < x.plugins.size(); ++p) {
      EXPECT_EQ(x.plugins[p].name, y.plugins[p].name);
      EXPECT_EQ(x.plugins[p].type, y.plugins[p].type);
      EXPECT_EQ(x.plugins[p].owner, y.plugins[p].owner);
      EXPECT_EQ(x.plugins[p].params, y.plugins[p].params) << x.name << ", plugin " << x.plugins[p].name;
    }
  }
}

}  // namespace aula::world::testing
