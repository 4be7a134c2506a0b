// Worlds as Gazebo users write them (issue 55): COLLADA, STL meshes as static geometry (lasers'
// slices, maps), model.config with two SDF versions, <population>, unquoted attributes, what Aula
// skips, every problem of a world at once. Every world and mesh here is written by the test.
#include "../support/mesh_files.hpp"
#include "expect_same_world.hpp"

#include <aula/geometry/raycaster2d.hpp>
#include <aula/world/car_kinematics.hpp>
#include <aula/world/obstacle_slice.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace aula::world;
using aula::testing::MeshBox;

namespace {

class GazeboWorlds : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = (fs::temp_directory_path() / ("aula-gazebo-worlds-" + std::to_string(::getpid()))).string();
    fs::remove_all(dir_);
    fs::create_directories(dir_ + "/models");
    setenv("XDG_CACHE_HOME", (dir_ + "/cache").c_str(), 1);
    for (const char* v : {"AULA_MODEL_PATH", "GAZEBO_MODEL_PATH", "GZ_SIM_RESOURCE_PATH", "SDF_PATH"}) unsetenv(v);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& relative, const std::string& text) const {
    fs::create_directories(fs::path(dir_ + "/" + relative).parent_path());
    std::ofstream(dir_ + "/" + relative) << text;
  }
  // A world of `body` (inside <world name="w">), loaded with the test's models folder.
  WorldSpec load(const std::string& body, const std::string& name = "w.world") const {
    write(name, "<?xml version='1.0'?>\n<sdf version='1.6'>\n<world name='w'>\n" + body + "</world>\n</sdf>\n");
    return loadWorld(dir_ + "/" + name, {dir_ + "/models"});
  }
  std::vector<std::string> problemsOf(const std::string& body) const {
    try {
      load(body);
    } catch (const WorldError& e) {
      return e.problems();
    }
    ADD_FAILURE() << "loaded without a problem";
    return {};
  }

  std::string dir_;
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A static model of one mesh collision.
std::string meshModel(const std::string& name, const std::string& uri, const std::string& pose = "0 0 0 0 0 0",
                      const std::string& extra = "") {
  return "<model name='" + name + "'><static>true</static><pose>" + pose + "</pose><link name='l'><collision name='c'>"
         "<geometry><mesh><uri>" + uri + "</uri>" + extra + "</mesh></geometry></collision>"
         "<visual name='v'><geometry><mesh><uri>" + uri + "</uri></mesh></geometry></visual></link></model>\n";
}

// RA's city in small: blocks in [-1, 1] (Blender's export), a node matrix scaling x and y by 250,
// 3 m high, with a ground. The block around (50..100, 50..100) m, another at (-100..-50, 0..60) m.
void writeCity(const std::string& path, double unit_m = 1.0) {
  const double k = 1.0 / 250.0, u = 1.0 / unit_m;  // file units: world / 250 in x, y; / unit in all
  std::vector<MeshBox> blocks = {{{50 * k * u, 50 * k * u, 0}, {100 * k * u, 100 * k * u, 3 * u}},
                                 {{-100 * k * u, 0, 0}, {-50 * k * u, 60 * k * u, 3 * u}}};
  aula::testing::writeCollada(path, {aula::testing::boxTriangles(blocks, 1.0 * u)}, {"city"},
                              "250 0 0 0 0 250 0 0 0 0 1 0 0 0 0 1", unit_m);
}

}  // namespace

TEST_F(GazeboWorlds, AColladaCityWithANodeMatrixIsSeenByTheLasersAndTheMap) {
  fs::create_directories(dir_ + "/models/city/meshes");
  writeCity(dir_ + "/models/city/meshes/city.dae");
  write("models/city/model.config", "<model><name>city</name><sdf version='1.5'>model.sdf</sdf></model>");
  write("models/city/model.sdf", "<sdf version='1.5'>" + meshModel("city", "model://city/meshes/city.dae") + "</sdf>");
  const WorldSpec w = load("<include><uri>model://city</uri></include>\n");
  ASSERT_EQ(w.statics.size(), 1u);
  const StaticObject& city = w.statics[0];
  EXPECT_EQ(city.shape.kind, ShapeKind::Mesh);
  // The node matrix applied: the ground spans 500 m, the buildings 3 m up.
  const Eigen::Vector4d b = staticBounds(w);
  EXPECT_NEAR(b[0], -250, 1e-6);
  EXPECT_NEAR(b[2], 250, 1e-6);
  EXPECT_NEAR(city.shape.mesh->bounds_m.max().z(), 3.0, 1e-9);
  // A laser at 0.5 m, from the street at (75, 20) looking north (+y): the block's face at y = 50.
  const aula::geometry::Raycaster2D caster(sliceAtHeight(w, 0.5));
  EXPECT_NEAR(caster.cast({75, 20}, M_PI / 2, 100), 30.0, 1e-6);
  EXPECT_NEAR(caster.cast({-75, -20}, M_PI / 2, 100), 20.0, 1e-6);  // the other block from the south
  EXPECT_NEAR(caster.cast({0, 20}, 0, 40), 40.0, 1e-9);             // the street ahead is free
  // The map (TeleTaxi's 1.25 m cells over the heights the taxi touches): the blocks solid, the streets free.
  const OccupancyMap map = occupancyMapOf(w, {1.25, 0.01, 100.0});
  EXPECT_EQ(map.transform.width_px, 400);
  EXPECT_TRUE(pointProblem(map, 75, 75).has_value());
  EXPECT_TRUE(contains(*pointProblem(map, 75, 75), "inside a building"));
  EXPECT_TRUE(pointProblem(map, -60, 30).has_value());
  EXPECT_FALSE(pointProblem(map, 75, 20).has_value());
  EXPECT_FALSE(pointProblem(map, 0, 0).has_value()) << "the ground is not an obstacle";
  // A band below the roofs (the vacuum's): the blocks are still solid, not outlines.
  const OccupancyMap low = occupancyMapOf(w, {1.25, 0.005, 0.09});
  EXPECT_TRUE(pointProblem(low, 75, 75).has_value());
  EXPECT_FALSE(pointProblem(low, 75, 20).has_value());
}

TEST_F(GazeboWorlds, ColladaUnitsAreMetresAsGazeboReadsThem) {
  writeCity(dir_ + "/cm.dae", 0.01);  // the same city written in centimetres, <unit meter="0.01">
  const WorldSpec w = load(meshModel("city", dir_ + "/cm.dae"));
  const aula::geometry::Raycaster2D caster(sliceAtHeight(w, 0.5));
  EXPECT_NEAR(caster.cast({75, 20}, M_PI / 2, 100), 30.0, 1e-4);
  EXPECT_NEAR(w.statics[0].shape.mesh->bounds_m.max().z(), 3.0, 1e-6);
}

TEST_F(GazeboWorlds, StlWallsWithScaleAndPoseAndASubmeshOfACollada) {
  // Two walls, 0.2 m thick and 2 m high, in millimetres, scaled to metres; the model turned by 90 degrees.
  aula::testing::writeStl(dir_ + "/walls.stl", aula::testing::boxTriangles({{{4000, -2000, 0}, {4200, 2000, 2000}},
                                                                            {{-4200, -2000, 0}, {-4000, 2000, 2000}}}));
  const WorldSpec w = load(meshModel("walls", "walls.stl", "1 0 0 0 0 1.5707963267948966", "<scale>0.001 0.001 0.001</scale>"));
  const aula::geometry::Raycaster2D caster(sliceAtHeight(w, 0.1));
  // Turned: the walls now cross the y axis at y = +-4 (faces), shifted by x = 1.
  EXPECT_NEAR(caster.cast({1, 0}, M_PI / 2, 10), 4.0, 1e-6);
  EXPECT_NEAR(caster.cast({1, 0}, -M_PI / 2, 10), 4.0, 1e-6);
  EXPECT_NEAR(caster.cast({1, 0}, 0, 10), 10.0, 1e-9);
  EXPECT_EQ(sliceAtHeight(w, 2.5).segments.size(), 0u) << "above the walls";

  // A COLLADA of two geometries: <submesh> picks one, <center> moves it onto the frame's origin.
  aula::testing::writeCollada(dir_ + "/two.dae",
                              {aula::testing::boxTriangles({{{10, 10, 0}, {12, 11, 1}}}),
                               aula::testing::boxTriangles({{{-5, -5, 0}, {-4, -4, 1}}})},
                              {"kiosk", "bin"});
  const WorldSpec one = load(meshModel("kiosk", "two.dae", "0 0 0 0 0 0", "<submesh><name>kiosk</name><center>true</center></submesh>"));
  EXPECT_TRUE(one.statics[0].shape.mesh->bounds_m.min().isApprox(Eigen::Vector3d(-1, -0.5, -0.5)));
  const auto problems = problemsOf(meshModel("kiosk", "two.dae", "0 0 0 0 0 0", "<submesh><name>kisok</name></submesh>"));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(contains(problems[0], "no sub-mesh named 'kisok' (it has: ")) << problems[0];
  EXPECT_TRUE(contains(problems[0], "kiosk")) << problems[0];
  EXPECT_TRUE(contains(problems[0], "w.world:4)")) << problems[0];
}

TEST_F(GazeboWorlds, TheCacheReadsTheMeshAgainAndNoticesAnEditedOne) {
  aula::testing::writeStl(dir_ + "/wall.stl", aula::testing::boxTriangles({{{3, -1, 0}, {3.2, 1, 1}}}));
  const WorldSpec parsed = load(meshModel("wall", "wall.stl"));
  const WorldSpec cached = loadWorld(dir_ + "/w.world", {dir_ + "/models"});
  aula::world::testing::expectSameWorld(cached, parsed);
  const WorldFiles files = worldFilesOf(dir_ + "/w.world");
  EXPECT_NE(std::find(files.inputs.begin(), files.inputs.end(), dir_ + "/wall.stl"), files.inputs.end());
  aula::testing::writeStl(dir_ + "/wall.stl", aula::testing::boxTriangles({{{5, -1, 0}, {5.2, 1, 1}}}));
  const WorldSpec edited = loadWorld(dir_ + "/w.world", {dir_ + "/models"});
  EXPECT_NE(edited.sha256, parsed.sha256) << "the mesh is one of the files the world is read from";
  const aula::geometry::Raycaster2D caster(sliceAtHeight(edited, 0.5));
  EXPECT_NEAR(caster.cast({0, 0}, 0, 10), 5.0, 1e-6);
}

TEST_F(GazeboWorlds, ModelConfigPicksTheNewestSdfItLists) {
  // As RoboticsInfrastructure's old models: model.sdf is SDF 1.2 (a <gazebo> root), listed first.
  write("models/crate/model.config", "<?xml version='1.0'?>\n<model><name>crate</name>\n"
                                     "<sdf version='1.2'>model.sdf</sdf>\n<sdf version='1.3'>model-1_3.sdf</sdf>\n</model>\n");
  write("models/crate/model.sdf", "<gazebo version='1.2'><model name='crate'><static>true</static></model></gazebo>");
  write("models/crate/model-1_3.sdf", "<sdf version='1.3'><model name='crate'><static>true</static><link name='l'>"
                                      "<collision name='c'><geometry><box><size>1 2 3</size></box></geometry></collision>"
                                      "</link></model></sdf>");
  const WorldSpec w = load("<include><uri>model://crate</uri></include>\n");
  ASSERT_EQ(w.statics.size(), 1u);
  EXPECT_EQ(w.statics[0].shape.box_size_m, Eigen::Vector3d(1, 2, 3));
}

TEST_F(GazeboWorlds, ModelsAreFoundOnGazebosPathsToo) {
  write("gz/crate/model.config", "<model><sdf version='1.6'>model.sdf</sdf></model>");
  write("gz/crate/model.sdf", "<sdf version='1.6'><model name='crate'><static>true</static><link name='l'><collision name='c'>"
                              "<geometry><box><size>1 1 1</size></box></geometry></collision></link></model></sdf>");
  write("w.world", "<sdf version='1.6'><world name='w'><include><uri>model://crate</uri></include></world></sdf>");
  for (const char* variable : {"GAZEBO_MODEL_PATH", "GZ_SIM_RESOURCE_PATH", "SDF_PATH"}) {
    setenv(variable, ("/nonexistent:" + dir_ + "/gz").c_str(), 1);
    EXPECT_EQ(loadWorld(dir_ + "/w.world").statics.size(), 1u) << variable;
    unsetenv(variable);
  }
  EXPECT_THROW(loadWorld(dir_ + "/w.world"), WorldError);
}

TEST_F(GazeboWorlds, APopulationIsExpandedForEveryDistribution) {
  const std::string crate = "<model name='crate'><static>true</static><link name='l'><collision name='c'><geometry>"
                            "<box><size>0.2 0.2 0.2</size></box></geometry></collision></link></model>";
  auto population = [&](const std::string& name, const std::string& region_and_count, const std::string& distribution) {
    return "<population name='" + name + "'>" + crate + "<pose>10 20 0 0 0 0</pose>" + region_and_count +
           "<distribution>" + distribution + "</distribution></population>\n";
  };
  const WorldSpec grid = load(population("p", "", "<type>grid</type><rows>2</rows><cols>3</cols><step>1 2 0</step>"));
  ASSERT_EQ(grid.statics.size(), 6u);
  EXPECT_EQ(grid.statics[0].name, "crate_clone_0::l::c");
  EXPECT_TRUE(grid.statics[0].pose.translation().isApprox(Eigen::Vector3d(9, 19, 0)));   // centred on the pose
  EXPECT_TRUE(grid.statics[5].pose.translation().isApprox(Eigen::Vector3d(11, 21, 0)));

  const WorldSpec line = load(population("p", "<box><size>4 2 1</size></box><model_count>4</model_count>", "<type>linear-x</type>"));
  ASSERT_EQ(line.statics.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(line.statics[i].pose.translation().isApprox(Eigen::Vector3d(8 + i, 20, 0))) << i;
  }
  const WorldSpec column = load(population("p", "<box><size>4 2 1</size></box><model_count>2</model_count>", "<type>linear-y</type>"));
  EXPECT_TRUE(column.statics[1].pose.translation().isApprox(Eigen::Vector3d(10, 20, 0)));
  const WorldSpec stack = load(population("p", "<box><size>4 2 1</size></box><model_count>2</model_count>", "<type>linear-z</type>"));
  EXPECT_TRUE(stack.statics[1].pose.translation().isApprox(Eigen::Vector3d(10, 20, 0)));

  for (const std::string& type : std::vector<std::string>{"random", "uniform"}) {
    const WorldSpec box = load(population("p", "<box><size>4 2 1</size></box><model_count>5</model_count>", "<type>" + type + "</type>"));
    ASSERT_EQ(box.statics.size(), 5u) << type;
    for (const auto& s : box.statics) {
      const Eigen::Vector3d p = s.pose.translation();
      EXPECT_TRUE(p.x() >= 8 && p.x() <= 12 && p.y() >= 19 && p.y() <= 21 && p.z() >= -0.5 && p.z() <= 0.5) << type << " " << p.transpose();
    }
    EXPECT_FALSE(box.statics[0].pose.translation().isApprox(box.statics[1].pose.translation())) << type;
    // Reproducible: the same world gives the same models.
    const WorldSpec again = load(population("p", "<box><size>4 2 1</size></box><model_count>5</model_count>", "<type>" + type + "</type>"), "again.world");
    EXPECT_TRUE(again.statics[4].pose.isApprox(box.statics[4].pose)) << type;
    const WorldSpec disc = load(population("p", "<cylinder><radius>3</radius><length>1</length></cylinder><model_count>4</model_count>",
                                           "<type>" + type + "</type>"));
    ASSERT_EQ(disc.statics.size(), 4u);
    for (const auto& s : disc.statics) EXPECT_LE((s.pose.translation().head<2>() - Eigen::Vector2d(10, 20)).norm(), 3.0) << type;
  }
  const auto problems = problemsOf(population("p", "<box><size>4 2 1</size></box><model_count>2</model_count>", "<type>spiral</type>"));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(contains(problems[0], "<type>spiral</type>: use random, uniform, grid, linear-x, linear-y or linear-z")) << problems[0];
}

TEST_F(GazeboWorlds, AnUnquotedAttributeIsReadAsGazebosParserReadsIt) {
  // RoboticsInfrastructure's worlds start with <gui fullscreen=1>: tinyxml2 alone refuses it.
  write("w.world", "<?xml version='1.0'?>\n<sdf version='1.6'>\n<world name=w>\n<gui fullscreen=1>\n</gui>\n"
                   "<model name='m'><static>true</static><link name='l'><collision name='c'><geometry>"
                   "<box><size>1 1 1</size></box></geometry></collision></link></model>\n</world>\n</sdf>\n");
  const WorldSpec w = loadWorld(dir_ + "/w.world", {dir_ + "/models"});
  EXPECT_EQ(w.name, "w");
  EXPECT_EQ(w.statics.size(), 1u);
  std::string skipped;
  for (const auto& line : w.skipped) skipped += line + "\n";
  EXPECT_TRUE(contains(skipped, "unquoted attribute value x2 (first at " + dir_ + "/w.world:3)")) << skipped;
  // Line numbers stay right after the repair: a problem on line 6 is said to be on line 6.
  write("w.world", "<sdf version='1.6'>\n<world name='w'>\n<gui fullscreen=1>\n</gui>\n"
                   "<model name='m'><static>true</static><link name='l'><collision name='c'><geometry>\n"
                   "<sphere><radius>1</radius></sphere></geometry></collision></link></model>\n</world>\n</sdf>\n");
  try {
    loadWorld(dir_ + "/w.world", {dir_ + "/models"});
    ADD_FAILURE();
  } catch (const WorldError& e) {
    EXPECT_TRUE(contains(e.what(), "w.world:5)")) << e.what();
  }
}

TEST_F(GazeboWorlds, WhatAulaDoesNotSimulateIsListedOnce) {
  write("models/sun/model.config", "<model><sdf version='1.6'>model.sdf</sdf></model>");
  write("models/sun/model.sdf", "<sdf version='1.6'><light type='directional' name='sun'><cast_shadows>true</cast_shadows></light></sdf>");
  const WorldSpec w = load("<include><uri>model://sun</uri></include>\n<light name='l1' type='point'/>\n"
                           "<light name='l2' type='point'/>\n<scene><sky/></scene>\n<plugin name='p' filename='libx.so'/>\n"
                           "<physics type='ode'><max_step_size>0.001</max_step_size><real_time_factor>1</real_time_factor></physics>\n"
                           "<model name='m'><static>true</static><link name='l'><collision name='c'><geometry><box><size>1 1 1</size>"
                           "</box></geometry><surface/></collision><visual name='v'/><visual name='v2'/></link></model>\n");
  EXPECT_EQ(w.physics_step_s, 0.001);
  std::string skipped;
  for (const auto& line : w.skipped) skipped += line + "\n";
  for (const std::string& expected : std::vector<std::string>{
       "<light> included (model://sun) (" + dir_ + "/models/sun/model.sdf:1): Aula simulates no lighting",
        "<light> in <world> x2 (first at " + dir_ + "/w.world:5): Aula simulates no lighting",
        "<scene> in <world> (" + dir_ + "/w.world:7): Aula draws no sky",
        "<plugin> in <world> (" + dir_ + "/w.world:8): Aula loads no Gazebo world plugins",
        "<real_time_factor> in <physics> (", "<physics type=\"ode\"> (", "<surface> in <collision> (",
        "<visual> in <link> x2 (first at "}) {
    EXPECT_TRUE(contains(skipped, expected)) << expected << "\nin:\n" << skipped;
  }
  EXPECT_EQ(std::count(skipped.begin(), skipped.end(), '\n'), 8) << skipped;  // one line per kind
  // The cache keeps the list.
  EXPECT_EQ(loadWorld(dir_ + "/w.world", {dir_ + "/models"}).skipped, w.skipped);
}

TEST_F(GazeboWorlds, EveryProblemOfAWorldIsListedAtOnceWithItsLine) {
  const auto problems = problemsOf(
      "<include><uri>model://nowhere</uri></include>\n"                                                     // line 4
      "<model name='a'><static>true</static><pose>1 2 3</pose></model>\n"                                   // line 5
      "<model name='b'><static>true</static><link name='l'><collision name='c'><geometry><sphere/>"
      "</geometry></collision></link></model>\n"                                                            // line 6
      "<model name='c'><static>true</static><link name='l'><collision name='c'><geometry><mesh><uri>gone.dae</uri>"
      "</mesh></geometry></collision></link></model>\n"                                                     // line 7
      "<model name='bot'><link name='l'><collision name='c'><geometry><box><size>1 1 1</size></box></geometry>"
      "</collision></link><plugin name='drive' filename='motors'><max_vel>1</max_vel></plugin></model>\n"  // line 8
      "<model name='taxi'><link name='l'><collision name='c'><geometry><mesh><uri>gone.dae</uri></mesh></geometry>"
      "</collision></link><plugin name='move' filename='ackermann'/></model>\n"                                 // line 9
      "<model name='ok'><static>true</static><link name='l'><collision name='c'><geometry><box><size>1 1 1</size></box>"
      "</geometry></collision></link></model>\n");
  ASSERT_EQ(problems.size(), 7u);
  EXPECT_TRUE(contains(problems[0], "model 'nowhere' not found")) << problems[0];
  EXPECT_TRUE(contains(problems[0], "w.world:4)")) << problems[0];
  EXPECT_TRUE(contains(problems[1], "<pose> needs 6 numbers, x y z roll pitch yaw")) << problems[1];
  EXPECT_TRUE(contains(problems[1], "w.world:5)")) << problems[1];
  EXPECT_TRUE(contains(problems[2], "only <box>, <cylinder> and <mesh> collision geometry is supported")) << problems[2];
  EXPECT_TRUE(contains(problems[2], "w.world:6)")) << problems[2];
  EXPECT_TRUE(contains(problems[3], "no such mesh file " + dir_ + "/gone.dae")) << problems[3];
  EXPECT_TRUE(contains(problems[3], "w.world:7)")) << problems[3];
  // A robot refused for its body still has its drivers checked.
  EXPECT_TRUE(contains(problems[4], "model 'taxi', collision 'c': a robot's collision must be a <box> or a <cylinder>")) << problems[4];
  EXPECT_TRUE(contains(problems[4], "w.world:9)")) << problems[4];
  EXPECT_TRUE(contains(problems[5], "model 'taxi', plugin 'move': unknown driver filename 'ackermann'")) << problems[5];
  EXPECT_TRUE(contains(problems[6], "unknown key <max_vel> (did you mean <max_v>?)")) << problems[6];
}

TEST_F(GazeboWorlds, AModelThatOnlyHoldsStaticModelsIsTheirContainer) {
  // As JdeRobot's house_int2: no <static> of its own, no link, its furniture each <static>true.
  const std::string table = "<model name='table'><static>true</static><pose>1 0 0 0 0 0</pose><link name='l'>"
                            "<collision name='c'><pose>0 0 0.7 0 0 0</pose><geometry><box><size>1.6 0.8 0.03</size></box>"
                            "</geometry></collision></link></model>";
  const WorldSpec w = load("<model name='house'><pose>0 2 0 0 0 0</pose>" + table + "</model>\n");
  ASSERT_EQ(w.statics.size(), 1u);
  EXPECT_EQ(w.statics[0].name, "house::table::l::c");
  EXPECT_TRUE(w.statics[0].pose.translation().isApprox(Eigen::Vector3d(1, 2, 0.7)));
  EXPECT_TRUE(w.robots.empty());
}

TEST_F(GazeboWorlds, ARobotKnownByItsGazeboPluginsIsAulasRobotOfThatKind) {
  // As RoboticsAcademy's taxi_holo_ROS: one link, a mesh body, libgazebo_ros_planar_move.so; here
  // with a level laser and a cliff sensor looking down.
  fs::create_directories(dir_ + "/models/taxi/meshes");
  aula::testing::writeCollada(dir_ + "/models/taxi/meshes/taxi.dae", {aula::testing::boxTriangles({{{-2, -1, 0}, {2, 1, 1.5}}})},
                              {"body"});
  write("models/taxi/model.config", "<model><sdf version='1.5'>model.sdf</sdf></model>");
  write("models/taxi/model.sdf",
        "<sdf version='1.5'><model name='taxi_holo'><static>false</static><link name='taxi_holo'>"
        "<inertial><mass>750</mass></inertial>"
        "<collision name='collision'><geometry><mesh><uri>model://taxi/meshes/taxi.dae</uri></mesh></geometry></collision>"
        "<sensor name='front' type='ray'><pose>2.4 0 0.5 0 0 0</pose><update_rate>20</update_rate><ray><scan><horizontal>"
        "<samples>180</samples><min_angle>-1.5708</min_angle><max_angle>1.5708</max_angle></horizontal></scan>"
        "<range><min>0.08</min><max>11</max></range></ray>"
        "<plugin name='laser_ros' filename='libgazebo_ros_laser.so'/></sensor>"
        "<sensor name='cliff' type='ray'><pose>1.5 0 0.1 0 1.5708 0</pose><ray><range><min>0.01</min><max>0.04</max></range></ray></sensor>"
        "</link><plugin name='object_controller' filename='libgazebo_ros_planar_move.so'><commandTopic>cmd_vel</commandTopic></plugin>"
        "</model></sdf>");
  const WorldSpec w = load("<include><uri>model://taxi</uri><pose>0 0 0 0 0 -1.5529944</pose></include>\n");
  const RobotSpec& taxi = requireRobot(w, "taxi_holo");
  EXPECT_EQ(taxi.shape.kind, ShapeKind::Box);
  EXPECT_TRUE(taxi.shape.box_size_m.isApprox(Eigen::Vector3d(4, 2, 1.5)));
  EXPECT_TRUE(taxi.shape_offset.translation().isApprox(Eigen::Vector3d(0, 0, 0.75)));
  EXPECT_DOUBLE_EQ(taxi.mass_kg, 750);
  EXPECT_EQ(channelOf(taxi, "pose3d"), "TAXI_HOLO_POSE");
  EXPECT_EQ(channelOf(taxi, "motors"), "TAXI_HOLO_MOTORS");
  EXPECT_EQ(channelOf(taxi, "bumper"), "TAXI_HOLO_BUMPER");
  EXPECT_TRUE(taxi.findPlugin("motors")->getBool("holonomic", false));
  // Gazebo's planar move has no speed limit of its own: the exercise's MaxV and MaxW are the
  // limits (TeleTaxi.MaxV may be up to 50 m/s, any exercise's MaxW up to 10 rad/s).
  EXPECT_GE(taxi.findPlugin("motors")->getDouble("max_v", 0), 50.0);
  EXPECT_GE(taxi.findPlugin("motors")->getDouble("max_w", 0), 10.0);
  const PluginSpec* laser = taxi.findPluginNamed("laser_front");  // named by where it faces, as Aula's worlds name them
  ASSERT_NE(laser, nullptr);
  EXPECT_EQ(laser->type, "laser");
  EXPECT_EQ(laser->getInt("samples", 0), 180);
  EXPECT_DOUBLE_EQ(laser->getDouble("max_range", 0), 11.0);
  EXPECT_DOUBLE_EQ(laser->getDouble("rate_hz", 0), 20.0);
  EXPECT_TRUE(laser->getPose("pose").translation().isApprox(Eigen::Vector3d(2.4, 0, 0.5)));
  EXPECT_EQ(taxi.findPluginNamed("cliff"), nullptr) << "a ray looking down is no planar laser";
  std::string skipped;
  for (const auto& line : w.skipped) skipped += line + "\n";
  EXPECT_TRUE(contains(skipped, "a robot's <sensor type=\"ray\"> not level (")) << skipped;
  EXPECT_TRUE(contains(skipped, "a robot's <mesh> collision (")) << skipped;
  // A model with a Gazebo plugin that drives nothing Aula knows is no robot: it is kept still, and said.
  write("models/taxi/model.sdf", "<sdf version='1.5'><model name='taxi_holo'><link name='l'><collision name='c'><geometry>"
                                 "<box><size>1 1 1</size></box></geometry></collision></link>"
                                 "<plugin name='drive' filename='libgazebo_ros_hovercraft.so'/></model></sdf>");
  const WorldSpec still = load("<include><uri>model://taxi</uri></include>\n");
  EXPECT_TRUE(still.robots.empty());
  ASSERT_EQ(still.statics.size(), 1u);
  skipped.clear();
  for (const auto& line : still.skipped) skipped += line + "\n";
  EXPECT_TRUE(contains(skipped, "a model not static in the file, with no drive (" + dir_ + "/models/taxi/model.sdf:1): Aula keeps it still"))
      << skipped;
  EXPECT_TRUE(contains(skipped, "Gazebo <plugin filename=\"libgazebo_ros_hovercraft.so\"> of a model kept still (")) << skipped;
}

TEST_F(GazeboWorlds, ARoombaOfSeveralLinksIsAulasRoundRobot) {
  // As RoboticsInfrastructure's roombaROS: a round base (here a cylinder and a bumper box inside
  // its disc), two wheel links, a laser on a mount link, cliff rays and a contact sensor, driven
  // by libgazebo_ros_planar_move.so.
  const std::string wheel = "<inertial><mass>0.1</mass></inertial><collision name='c'><geometry><cylinder><radius>0.03</radius>"
                            "<length>0.02</length></cylinder></geometry></collision>";
  write("w.world",
        "<sdf version='1.6'><world name='w'><model name='roomba'><pose>-1 1.5 0 0 0 0</pose>"
        "<link name='base'><pose>0 0 0.02 0 0 0</pose><inertial><mass>2</mass></inertial>"
        "<collision name='body'><pose>0 0 0.03 0 0 0</pose><geometry><cylinder><radius>0.165</radius><length>0.06</length>"
        "</cylinder></geometry></collision>"
        "<collision name='bumper'><pose>0.1 0 0.03 0 0 0</pose><geometry><box><size>0.05 0.2 0.04</size></box></geometry></collision>"
        "<collision name='caster'><pose>0.13 0 0.017 0 0 0</pose><geometry><sphere><radius>0.018</radius></sphere></geometry></collision>"
        "<sensor name='cliff' type='ray'><pose>0.15 0 0.01 0 1.5708 0</pose><ray/></sensor>"
        "<sensor name='wall' type='ray'><pose>0.09 -0.12 0.06 0 0 -1</pose><ray><scan><horizontal><samples>1</samples>"
        "</horizontal></scan></ray></sensor>"
        "<sensor name='bump' type='contact'><contact><collision>bumper</collision></contact></sensor></link>"
        "<link name='left_wheel'><pose>0 0.12 0.03 0 1.5708 1.5708</pose>" + wheel + "</link>"
        "<link name='right_wheel'><pose>0 -0.12 0.03 0 1.5708 1.5708</pose>" + wheel + "</link>"
        "<link name='laser'><pose>0.1 0 0.12 0 0 0</pose><sensor name='laser' type='ray'><ray><scan><horizontal>"
        "<samples>360</samples><min_angle>-3.14</min_angle><max_angle>3.14</max_angle></horizontal></scan>"
        "<range><min>0.1</min><max>8</max></range></ray></sensor></link>"
        "<joint name='j' type='fixed'><parent>base</parent><child>laser</child></joint>"
        "<plugin name='drive' filename='libgazebo_ros_planar_move.so'/></model></world></sdf>");
  const WorldSpec w = loadWorld(dir_ + "/w.world", {dir_ + "/models"});
  const RobotSpec& roomba = requireRobot(w, "roomba");
  EXPECT_EQ(roomba.shape.kind, ShapeKind::Cylinder);
  EXPECT_NEAR(roomba.shape.radius_m, 0.165, 1e-9);
  EXPECT_NEAR(roomba.shape.length_m, 0.08, 1e-6);  // the wheels reach 2 cm below the body's link, the body 6 cm above
  EXPECT_TRUE(roomba.pose.translation().isApprox(Eigen::Vector3d(-1, 1.5, 0.02)));
  EXPECT_NEAR(roomba.mass_kg, 2.2, 1e-12);
  EXPECT_EQ(channelOf(roomba, "bumper"), "ROOMBA_BUMPER");
  const PluginSpec* laser = roomba.findPluginNamed("laser_front");
  ASSERT_NE(laser, nullptr);
  EXPECT_TRUE(laser->getPose("pose").translation().isApprox(Eigen::Vector3d(0.1, 0, 0.1))) << "in the body's frame";
  EXPECT_EQ(laser->getInt("samples", 0), 360);
  EXPECT_EQ(roomba.plugins.size(), 4u);  // pose3d, motors, bumper, laser
  std::string skipped;
  for (const auto& line : w.skipped) skipped += line + "\n";
  EXPECT_TRUE(contains(skipped, "a robot's <link> besides its body x3 (")) << skipped;
  EXPECT_TRUE(contains(skipped, "<joint> in <model> (")) << skipped;
  EXPECT_TRUE(contains(skipped, "a robot's one-beam <sensor type=\"ray\"> (")) << skipped;
  EXPECT_EQ(roomba.findPluginNamed("wall"), nullptr) << "an infrared range finder is not the laser";
}

namespace {
// As RoboticsInfrastructure's prius_ackermann_3laser, in small: forward along the model's +y, an
// empty first link, a chassis box, four wheel links and two steering links placed through
// relative_to frames, a steering wheel, three lasers on the chassis, libgazebo_ros_ackermann_drive.so.
std::string ackermannCar(const std::string& front_left_joint = "fl_axle") {
  auto wheel = [](const std::string& link, const std::string& joint, const std::string& parent, const std::string& at) {
    return "<joint name='" + joint + "' type='revolute'><pose relative_to='" + parent + "'>" + at + "</pose><parent>" + parent +
           "</parent><child>" + link + "</child><axis><xyz>-1 0 0</xyz></axis></joint>"
           "<link name='" + link + "'><pose relative_to='" + joint + "'>0 0 0 0 0 0</pose><inertial><mass>24.5</mass></inertial>"
           "<collision name='c'><pose relative_to='" + joint + "'>0 0 0 0 1.5708 0</pose><geometry><cylinder><radius>0.33</radius>"
           "<length>0.22</length></cylinder></geometry></collision><visual name='v'/></link>";
  };
  auto steer = [](const std::string& link, const std::string& joint, const std::string& at) {
    return "<joint name='" + joint + "' type='revolute'><pose relative_to='chassis_link'>" + at + "</pose><parent>chassis_link"
           "</parent><child>" + link + "</child></joint><link name='" + link + "'><pose relative_to='" + joint +
           "'>0 0 0 0 0 0</pose><inertial><mass>1</mass></inertial></link>";
  };
  auto laser = [](const std::string& name, const std::string& frame, const std::string& pose, double max_m) {
    return "<sensor name='" + name + "' type='ray'><pose relative_to='" + frame + "'>" + pose + "</pose><update_rate>40</update_rate>"
           "<ray><scan><horizontal><samples>180</samples><resolution>1</resolution><min_angle>-1.570796</min_angle>"
           "<max_angle>1.570796</max_angle></horizontal></scan><range><min>0.12</min><max>" + std::to_string(max_m) +
           "</max></range><noise><type>gaussian</type><mean>0</mean><stddev>0.01</stddev></noise></ray>"
           "<plugin name='" + name + "_ros' filename='libgazebo_ros_ray_sensor.so'/></sensor>";
  };
  return "<sdf version='1.5'><model name='prius'><pose>0 0 0 0 0 0</pose><link name='base_link'/>"
         "<joint name='chassis_joint' type='fixed'><parent>base_link</parent><child>chassis_link</child></joint>"
         "<link name='chassis_link'><inertial><mass>1580</mass></inertial>"
         "<collision name='body'><pose>0 0.2 0.9 0 0 0</pose><geometry><box><size>1.8 4.6 1.2</size></box></geometry></collision>" +
         laser("front_hokuyo", "chassis_link", "0 2.45 0.5 0 0 1.5708", 30) +
         laser("back_hokuyo", "base_link", "0 -2.2 0.5 0 0 -1.5708", 30) +
         laser("side_hokuyo", "base_link", "1.0 0 0.5 0 0 0", 20) + "</link>" +
         wheel("bl", "bl_axle", "chassis_link", "-0.775 -1.35 0.33 0 0 0") +
         wheel("br", "br_axle", "chassis_link", "0.775 -1.35 0.33 0 0 0") +
         steer("l_steer_1", "l_steer", "-0.8 1.55 0.33 0 0 0") + wheel("fl", "fl_axle", "l_steer_1", "-0.05 0 0 0 0 0") +
         steer("r_steer_1", "r_steer", "0.8 1.55 0.33 0 0 0") + wheel("fr", "fr_axle", "r_steer_1", "0.05 0 0 0 0 0") +
         "<link name='steering_wheel'><pose relative_to='chassis_link'>0 0.6 1.0 0 0 0</pose></link>"
         "<plugin name='ackermann_drive' filename='libgazebo_ros_ackermann_drive.so'><update_rate>100</update_rate>"
         "<front_left_joint>" + front_left_joint + "</front_left_joint><front_right_joint>fr_axle</front_right_joint>"
         "<rear_left_joint>bl_axle</rear_left_joint><rear_right_joint>br_axle</rear_right_joint>"
         "<left_steering_joint>l_steer</left_steering_joint><right_steering_joint>r_steer</right_steering_joint>"
         "<max_steer>0.52</max_steer><max_speed>50</max_speed></plugin></model></sdf>";
}
}  // namespace

TEST_F(GazeboWorlds, AnAckermannCarOfNineLinksIsAulasCar) {
  write("models/prius/model.config", "<model><sdf version='1.5'>model.sdf</sdf></model>");
  write("models/prius/model.sdf", ackermannCar());
  // Turned -90 degrees in the world, as the Prius street turns it, so that it drives along +x.
  const WorldSpec w = load("<include><uri>model://prius</uri><pose>-7 2.5 0.02 0 0 -1.5707963267948966</pose></include>\n");
  const RobotSpec& car = requireRobot(w, "prius");
  // Its body frame: the footprint's centre (the chassis 0.2 m ahead of the model's origin), x forward.
  EXPECT_NEAR(car.pose.translation().x(), -6.8, 1e-9);
  EXPECT_NEAR(car.pose.translation().y(), 2.5, 1e-9);
  EXPECT_NEAR(yawOf(car.pose), 0.0, 1e-9);
  // The box around every link's collisions: the chassis, and the wheels 6 cm past its sides.
  EXPECT_EQ(car.shape.kind, ShapeKind::Box);
  EXPECT_TRUE(car.shape.box_size_m.isApprox(Eigen::Vector3d(4.6, 1.92, 1.5), 1e-4)) << car.shape.box_size_m.transpose();
  EXPECT_TRUE(car.shape_offset.translation().isApprox(Eigen::Vector3d(0, 0, 0.75), 1e-4)) << car.shape_offset.translation().transpose();
  EXPECT_NEAR(car.mass_kg, 1 + 1580 + 4 * 24.5 + 2, 1e-9);  // the empty first link weighs SDF's default 1 kg
  // Its motors: a car, wheelbase between the wheel joints, turning about the rear axle's centre.
  const PluginSpec* motors = car.findPlugin("motors");
  ASSERT_NE(motors, nullptr);
  const CarKinematics k = readCarKinematics(*motors);
  EXPECT_TRUE(k.ackermann);
  EXPECT_NEAR(k.wheelbase_m, 2.9, 1e-9);
  EXPECT_NEAR(k.max_steer_rad, 0.52, 1e-12);
  EXPECT_NEAR(k.rear_axle_x_m, -1.55, 1e-9);
  EXPECT_NEAR(k.min_turn_radius_m, 2.9 / std::tan(0.52), 1e-9);
  EXPECT_DOUBLE_EQ(motors->getDouble("max_v", 0), 50.0);
  // Its lasers from its sensors, in the body's frame, named by where they face.
  struct Expected {
    std::string name;
    Eigen::Vector3d at;
    double yaw_rad, max_m;
  };
  for (const Expected& e : {Expected{"laser_front", {2.25, 0, 0.5}, 0.0, 30}, Expected{"laser_rear", {-2.4, 0, 0.5}, M_PI, 30},
                            Expected{"laser_right", {-0.2, -1.0, 0.5}, -M_PI / 2, 20}}) {
    const PluginSpec* laser = car.findPluginNamed(e.name);
    ASSERT_NE(laser, nullptr) << e.name;
    const Eigen::Isometry3d pose = laser->getPose("pose");
    EXPECT_TRUE(pose.translation().isApprox(e.at, 1e-4)) << e.name << ": " << pose.translation().transpose();
    EXPECT_NEAR(std::remainder(yawOf(pose) - e.yaw_rad, 2 * M_PI), 0.0, 1e-4) << e.name;
    EXPECT_EQ(laser->getInt("samples", 0), 180);
    EXPECT_DOUBLE_EQ(laser->getDouble("min_angle", 0), -1.570796);
    EXPECT_DOUBLE_EQ(laser->getDouble("min_range", 0), 0.12);
    EXPECT_DOUBLE_EQ(laser->getDouble("max_range", 0), e.max_m);
    EXPECT_DOUBLE_EQ(laser->getDouble("noise_stddev", 0), 0.01);
    EXPECT_DOUBLE_EQ(laser->getDouble("rate_hz", 0), 40.0);
  }
  EXPECT_EQ(channelOf(car, "laser", "laser_front"), "PRIUS_LASER_FRONT_HOKUYO");
  EXPECT_EQ(channelOf(car, "bumper"), "PRIUS_BUMPER");
  std::string skipped;
  for (const auto& line : w.skipped) skipped += line + "\n";
  EXPECT_TRUE(contains(skipped, "Ackermann drive <plugin filename=\"libgazebo_ros_ackermann_drive.so\"> (")) << skipped;
  EXPECT_TRUE(contains(skipped, "a robot's <link> besides its body x8 (")) << skipped;
  // A wheel joint the plugin names and the model lacks: said, with the plugin's line.
  write("models/prius/model.sdf", ackermannCar("front_left"));
  const auto problems = problemsOf("<include><uri>model://prius</uri></include>\n");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(contains(problems[0], "plugin 'ackermann_drive': <front_left_joint>front_left: the model has no <joint> of that name"))
      << problems[0];
}

TEST_F(GazeboWorlds, ParkedCarsNotStaticWithNoDriveAreKeptStillAsTheirMeshes) {
  // As RoboticsAcademy's autoparking street: a car mesh whose own axes run across (2.2 m along x,
  // 4.9 m along y), turned 1.57 rad in the file, <static>false</static>, no plugin.
  fs::create_directories(dir_ + "/models/opel/meshes");
  aula::testing::writeCollada(dir_ + "/models/opel/meshes/car.dae",
                              {aula::testing::boxTriangles({{{-1.1, -2.45, 0}, {1.1, 2.45, 1.7}}})}, {"car"});
  write("models/opel/model.config", "<model><sdf version='1.5'>model.sdf</sdf></model>");
  auto parked = [](const std::string& name, double x) {
    return "<model name='" + name + "'><pose>" + std::to_string(x) + " -3 0 0 0 1.57</pose><static>false</static>"
           "<link name='car1'><gravity>false</gravity><collision name='collision'><geometry><mesh>"
           "<uri>model://opel/meshes/car.dae</uri></mesh></geometry></collision></link></model>\n";
  };
  const WorldSpec w = load(parked("car4", 0.5) + parked("car5", 14));
  EXPECT_TRUE(w.robots.empty());
  ASSERT_EQ(w.statics.size(), 2u);
  const aula::geometry::OrientedBox f = footprintOf(w.statics[0]);
  EXPECT_NEAR(f.centre.x_m, 0.5, 1e-9);
  EXPECT_NEAR(std::abs(std::sin(f.centre.yaw_rad)), 1.0, 1e-3) << "its length runs along the street";
  std::string skipped;
  for (const auto& line : w.skipped) skipped += line + "\n";
  EXPECT_TRUE(contains(skipped, "a model not static in the file, with no drive x2 (first at " + dir_ +
                                    "/w.world:4): Aula keeps it still, as static geometry"))
      << skipped;
  // The lasers see the cars' mesh: a right laser at y = 2.5 looking down the street's width meets
  // the car4's side 2.5 + 3 - 1.1 = 4.4 m away; the slot between them is free to y = -inf.
  const aula::geometry::Raycaster2D caster(sliceAtHeight(w, 0.5));
  EXPECT_NEAR(caster.cast({0.5, 2.5}, -M_PI / 2, 11), 2.5 + 3 - 1.1, 1e-2);
  EXPECT_NEAR(caster.cast({7.25, 2.5}, -M_PI / 2, 11), 11.0, 1e-9);
  EXPECT_NEAR(caster.cast({-5, -3}, 0, 11), 5.5 - 2.45, 1e-2) << "along the row: the car's back, 2.45 m behind its centre";
  // The map: the cars are solid, the slot free.
  const OccupancyMap map = occupancyMapOf(w, {0.1, 0.01, 2.0});
  EXPECT_TRUE(pointProblem(map, 14, -3).has_value());
  EXPECT_FALSE(pointProblem(map, 7.25, -3).has_value());
}

TEST_F(GazeboWorlds, GazebosOwnGroundPlaneAndSunNeedNoModelFolder) {
  const WorldSpec w = load("<include><uri>model://ground_plane</uri></include>\n<include><uri>model://sun</uri></include>\n"
                           "<model name='m'><static>true</static><link name='l'><collision name='c'><geometry><box>"
                           "<size>1 1 1</size></box></geometry></collision></link></model>\n");
  EXPECT_EQ(w.statics.size(), 1u) << "the ground is no obstacle";
  std::string skipped;
  for (const auto& line : w.skipped) skipped += line + "\n";
  EXPECT_TRUE(contains(skipped, "Gazebo's built-in model://ground_plane (" + dir_ + "/w.world:4): the floor")) << skipped;
  EXPECT_TRUE(contains(skipped, "Gazebo's built-in model://sun (" + dir_ + "/w.world:5): Aula simulates no lighting")) << skipped;
  // A folder of that name on the model path is read instead, as Gazebo reads the first it finds.
  write("models/ground_plane/model.config", "<model><sdf version='1.6'>model.sdf</sdf></model>");
  write("models/ground_plane/model.sdf", "<sdf version='1.6'><model name='ground_plane'><static>true</static><link name='l'>"
                                         "<collision name='c'><geometry><box><size>2 2 0.1</size></box></geometry></collision>"
                                         "</link></model></sdf>");
  EXPECT_EQ(load("<include><uri>model://ground_plane</uri></include>\n").statics.size(), 1u);
  // Any other model missing is still a problem.
  EXPECT_EQ(problemsOf("<include><uri>model://ground</uri></include>\n").size(), 1u);
}

TEST_F(GazeboWorlds, ARobotWithNoCollisionIsTheBoxAroundItsVisuals) {
  // As RoboticsAcademy's taxi_holo_laser_ROS: a visual mesh, no collision, three laser links
  // (laser_f, laser_r, laser_b), libgazebo_ros_planar_move.so.
  fs::create_directories(dir_ + "/models/taxi/meshes");
  aula::testing::writeCollada(dir_ + "/models/taxi/meshes/taxi.dae", {aula::testing::boxTriangles({{{-2.3, -1, 0}, {2.3, 1, 1.5}}})},
                              {"body"});
  auto laser_link = [](const std::string& link, const std::string& sensor, const std::string& pose) {
    return "<link name='" + link + "'><sensor name='" + sensor + "' type='ray'><pose>" + pose + "</pose><ray><scan><horizontal>"
           "<samples>180</samples><min_angle>-1.57</min_angle><max_angle>1.57</max_angle></horizontal></scan>"
           "<range><min>0.08</min><max>11</max></range></ray></sensor></link>";
  };
  write("models/taxi/model.config", "<model><sdf>model.sdf</sdf></model>");
  write("models/taxi/model.sdf",
        "<sdf version='1.5'><model name='taxi_holo'><link name='taxi_holo_laser'><inertial><mass>750</mass></inertial>"
        "<visual name='visual'><geometry><mesh><uri>model://taxi/meshes/taxi.dae</uri></mesh></geometry></visual></link>" +
            laser_link("laser_front", "laser_f", "2.4 0 0.5 0 0 0") + laser_link("laser_right", "laser_r", "0.5 -1.25 0.5 0 0 -1.5708") +
            laser_link("laser_back", "laser_b", "-2.4 0 0.5 0 0 3.1416") +
            "<plugin name='object_controller' filename='libgazebo_ros_planar_move.so'/></model></sdf>");
  const WorldSpec w = load("<include><uri>model://taxi</uri><pose>-7 2.5 0.02 0 0 0</pose></include>\n");
  const RobotSpec& taxi = requireRobot(w, "taxi_holo");
  EXPECT_TRUE(taxi.shape.box_size_m.isApprox(Eigen::Vector3d(4.6, 2, 1.5), 1e-6)) << taxi.shape.box_size_m.transpose();
  EXPECT_DOUBLE_EQ(taxi.mass_kg, 750);
  for (const char* name : {"laser_front", "laser_rear", "laser_right"}) EXPECT_NE(taxi.findPluginNamed(name), nullptr) << name;
  EXPECT_EQ(channelOf(taxi, "laser", "laser_rear"), "TAXI_HOLO_LASER_LASER_B");
  std::string skipped;
  for (const auto& line : w.skipped) skipped += line + "\n";
  EXPECT_TRUE(contains(skipped, "a robot with no <collision> (" + dir_ + "/models/taxi/model.sdf:1): its shape is the box around its <visual>s"))
      << skipped;
}

TEST_F(GazeboWorlds, ARoundBodyWithBumpersBulgingPastItIsACylinderAroundThem) {
  // As roombaROS's bumper arcs: they bulge past the 0.165 m body at its sides, the box around
  // them a centimetre wider across than along, and reach 1.04 times its half width. A box there
  // could not turn on the spot beside a wall; the cylinder holds every point.
  const std::string bumper = "<geometry><box><size>0.1 0.01 0.04</size></box></geometry>";
  write("w.world",
        "<sdf version='1.6'><world name='w'><model name='roomba'><link name='base'><inertial><mass>2</mass></inertial>"
        "<collision name='body'><geometry><cylinder><radius>0.165</radius><length>0.06</length></cylinder></geometry></collision>"
        "<collision name='left'><pose>0 0.168 0 0 0 0</pose>" + bumper + "</collision>"
        "<collision name='right'><pose>0 -0.168 0 0 0 0</pose>" + bumper + "</collision></link>"
        "<plugin name='drive' filename='libgazebo_ros_planar_move.so'/></model></world></sdf>");
  const WorldSpec w = loadWorld(dir_ + "/w.world", {dir_ + "/models"});  // kept: the robot is a part of it
  const RobotSpec& roomba = requireRobot(w, "roomba");
  ASSERT_EQ(roomba.shape.kind, ShapeKind::Cylinder);
  EXPECT_NEAR(roomba.shape.radius_m, std::hypot(0.05, 0.173), 1e-9) << "to the bumpers' outer corners";
  // A box stays a box: its corners reach 1.41 times its half width.
  write("w.world",
        "<sdf version='1.6'><world name='w'><model name='cube'><link name='base'><inertial><mass>2</mass></inertial>"
        "<collision name='body'><geometry><box><size>0.33 0.33 0.06</size></box></geometry></collision></link>"
        "<plugin name='drive' filename='libgazebo_ros_planar_move.so'/></model></world></sdf>");
  EXPECT_EQ(requireRobot(loadWorld(dir_ + "/w.world", {dir_ + "/models"}), "cube").shape.kind, ShapeKind::Box);
}
