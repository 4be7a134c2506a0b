#include <aula/geometry/map_transform.hpp>
#include <aula/world/obstacle_slice.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <cstdlib>
#include <sys/wait.h>
#include <filesystem>
#include <fstream>
#include <iostream>

using namespace aula::world;
using aula::geometry::MapTransform;

namespace {
const std::string kWorlds = std::string(AULA_SOURCE_DIR) + "/worlds/";
const std::string kData = std::string(AULA_TEST_DATA_DIR) + "/worlds/";

std::string errorOf(const std::string& path) {
  try {
    loadWorld(path);
  } catch (const WorldError& e) {
    return e.what();
  }
  ADD_FAILURE() << path << " loaded without error";
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
}  // namespace

TEST(LoadWorld, CityHasTheTaxiAtTheOriginFacingSouth) {
  const WorldSpec w = loadWorld(kWorlds + "cityLarge.world");
  EXPECT_EQ(w.name, "cityLarge");
  ASSERT_EQ(w.robots.size(), 1u);
  const RobotSpec& taxi = w.robots[0];
  EXPECT_EQ(taxi.name, "taxi_holo");
  EXPECT_NEAR(taxi.pose.translation().norm(), 0.0, 1e-9);
  EXPECT_NEAR(yawOf(taxi.pose), -M_PI / 2, 1e-9);
  EXPECT_DOUBLE_EQ(taxi.mass_kg, 750.0);
  EXPECT_EQ(taxi.shape.kind, ShapeKind::Box);
  EXPECT_TRUE(taxi.shape.box_size_m.isApprox(Eigen::Vector3d(4, 2, 1.5)));
  ASSERT_NE(taxi.findPlugin("motors"), nullptr);
  EXPECT_EQ(taxi.findPlugin("motors")->getString("channel", ""), "TAXI_MOTORS");
  EXPECT_DOUBLE_EQ(taxi.findPlugin("motors")->getDouble("max_v", 0), 20.0);
  EXPECT_TRUE(taxi.findPlugin("motors")->getBool("holonomic", false));
  ASSERT_EQ(taxi.plugins.size(), 3u);
  EXPECT_EQ(taxi.findPlugin("pose3d")->getString("channel", ""), "TAXI_POSE");
  EXPECT_EQ(taxi.findPlugin("bumper")->getString("channel", ""), "TAXI_BUMPER");
  EXPECT_EQ(taxi.findPlugin("laser"), nullptr);
  // Resting on the ground: body frame at z = 0, the box centre 0.75 m above it.
  EXPECT_NEAR((taxi.pose * taxi.shape_offset).translation().z(), 0.75, 1e-9);
  EXPECT_GT(w.physics_step_s, 0.0);
  EXPECT_EQ(w.findRobot("taxi_holo"), &taxi);
  EXPECT_EQ(w.findRobot("nobody"), nullptr);
  EXPECT_GT(w.statics.size(), 100u);
  EXPECT_LE(w.statics.size(), 400u);
}

TEST(LoadWorld, VacuumHouseAndRoomba) {
  const WorldSpec w = loadWorld(kWorlds + "vacuum.world");
  ASSERT_EQ(w.robots.size(), 1u);
  const RobotSpec& roomba = w.robots[0];
  EXPECT_EQ(roomba.shape.kind, ShapeKind::Cylinder);
  EXPECT_DOUBLE_EQ(roomba.shape.radius_m, 0.165);
  EXPECT_NEAR(roomba.pose.translation().x(), -1.0, 1e-12);
  EXPECT_NEAR(roomba.pose.translation().y(), 1.5, 1e-12);
  const PluginSpec* laser = roomba.findPlugin("laser");
  ASSERT_NE(laser, nullptr);
  EXPECT_EQ(laser->getInt("samples", 0), 180);
  EXPECT_TRUE(laser->getPose("pose").translation().isApprox(Eigen::Vector3d(0.139, 0, 0.075)));
  EXPECT_NE(roomba.findPlugin("bumper"), nullptr);
  EXPECT_EQ(roomba.plugins.size(), 4u);
  EXPECT_DOUBLE_EQ(roomba.mass_kg, 2.5);
  EXPECT_DOUBLE_EQ(roomba.shape.length_m, 0.09);
  EXPECT_NEAR(laser->getDouble("min_angle", 0), -M_PI / 2, 1e-6);
  EXPECT_NEAR(laser->getDouble("max_angle", 0), M_PI / 2, 1e-6);
  EXPECT_EQ(laser->getString("channel", ""), "ROOMBA_LASER");
  EXPECT_FALSE(roomba.findPlugin("motors")->getBool("holonomic", true));
  // The outer walls span x [-4.10, 5.51], y [-3.68, 6.05].
  const Eigen::Vector4d b = staticBounds(w);
  EXPECT_NEAR(b[0], -4.10, 1e-9);
  EXPECT_NEAR(b[1], -3.68, 1e-9);
  EXPECT_NEAR(b[2], 5.51, 1e-9);
  EXPECT_NEAR(b[3], 6.05, 1e-9);
  // The dining table as the original: x [-2.8, -2.0], y [-0.5, 1.1].
  bool table = false;
  for (const auto& o : w.statics) {
    if (contains(o.name, "dining_table")) {
      table = true;
      EXPECT_NEAR(o.pose.translation().x(), -2.4, 1e-9);
      EXPECT_NEAR(o.pose.translation().y(), 0.3, 1e-9);
      EXPECT_NEAR(o.shape.box_size_m.x(), 0.8, 1e-9);
    }
  }
  EXPECT_TRUE(table);
}

TEST(LoadWorld, AutoparkStreet) {
  const WorldSpec w = loadWorld(kWorlds + "autopark.world");
  ASSERT_EQ(w.robots.size(), 1u);
  const RobotSpec& car = w.robots[0];
  EXPECT_EQ(car.name, "car");
  EXPECT_TRUE(car.pose.translation().isApprox(Eigen::Vector3d(-7, 2.5, 0)));
  int lasers = 0;
  for (const auto& p : car.plugins) lasers += p.type == "laser";
  EXPECT_EQ(lasers, 3);
  EXPECT_EQ(car.plugins.size(), 6u);
  EXPECT_NEAR(yawOf(car.pose), 0.0, 1e-12);
  for (const auto& p : car.plugins) {
    if (p.type != "laser") continue;
    // Mounted 0.5 m above the road as on RoboticsAcademy's car, above the 0.2 m curb tops.
    EXPECT_NEAR((car.pose * p.getPose("pose")).translation().z(), 0.5, 1e-9) << p.name;
    EXPECT_DOUBLE_EQ(p.getDouble("max_range", 0), p.name == "laser_right" ? 9.5 : 11.0) << p.name;
    EXPECT_EQ(p.getInt("samples", 0), 180);
  }
  const PluginSpec* right = nullptr;
  for (const auto& p : car.plugins) {
    if (p.name == "laser_right") right = &p;
  }
  ASSERT_NE(right, nullptr);
  EXPECT_EQ(right->getString("channel", ""), "CAR_LASER_RIGHT");
  EXPECT_NEAR(yawOf(right->getPose("pose")), -M_PI / 2, 1e-6);
  EXPECT_TRUE(right->getPose("pose").translation().head<2>().isApprox(Eigen::Vector2d(0.5, -1.25)));
  EXPECT_DOUBLE_EQ(car.findPlugin("motors")->getDouble("wheelbase", 0), 2.6);
  std::vector<double> car_x;
  double curb_face = 0;
  for (const auto& o : w.statics) {
    if (contains(o.name, "parked_car")) car_x.push_back(o.pose.translation().x());
    if (contains(o.name, "curb_parking_side")) curb_face = o.pose.translation().y() + o.shape.box_size_m.y() / 2;
  }
  EXPECT_EQ(car_x, (std::vector<double>{-20, -13.5, -7, 0.5, 14, 21.5, 29}));
  EXPECT_NEAR(curb_face, -4.25, 1e-9);
}

TEST(LoadWorld, ErrorsNameTheFileAndWhatIsWrong) {
  EXPECT_TRUE(contains(errorOf("/nonexistent.world"), "/nonexistent.world: cannot open"));
  const std::string missing = errorOf(kData + "missing_model.world");
  EXPECT_TRUE(contains(missing, "missing_model.world")) << missing;
  EXPECT_TRUE(contains(missing, "no_such_robot")) << missing;
  EXPECT_TRUE(contains(missing, "model 'no_such_robot' not found")) << missing;
  const std::string plugin = errorOf(kData + "bad_plugin.world");
  EXPECT_TRUE(contains(plugin, "model 'bot', plugin 'eyes': unknown driver filename 'camera'")) << plugin;
  EXPECT_TRUE(contains(plugin, "known: bumper, laser, motors, pose3d")) << plugin;
  const std::string mesh = errorOf(kData + "mesh_obstacle.world");
  EXPECT_TRUE(contains(mesh, "model 'statue', link 'body', collision 'shape': <uri>statue.dae</uri>: no such mesh file " + kData + "statue.dae")) << mesh;
  const std::string links = errorOf(kData + "two_links.world");
  EXPECT_TRUE(contains(links, "model 'wobbly': a robot (non-static model) must have exactly one <link>")) << links;
  // Each names the file and line of the element at fault, in the world or in the model it includes.
  EXPECT_TRUE(contains(mesh, "(" + kData + "mesh_obstacle.world:7)")) << mesh;
  EXPECT_TRUE(contains(links, "(" + kData + "models/two_links/model.sdf:3)")) << links;
  EXPECT_TRUE(contains(missing, "(" + kData + "missing_model.world:4)")) << missing;
  const std::string xml = errorOf(kData + "malformed.world");
  EXPECT_TRUE(contains(xml, "malformed.world:4: malformed XML")) << xml;
  const std::string misspelt = errorOf(kData + "misspelt_key.world");
  EXPECT_TRUE(contains(misspelt, "misspelt_key.world: model 'bot', plugin 'drive': unknown key <max_vel> (did you mean "
                                 "<max_v>?); a motors plugin reads channel, holonomic, kinematics, max_steer_rad, "
                                 "max_v, max_w, rear_axle_x, watchdog_s, wheelbase"))
      << misspelt;
  const std::string robot_mesh = errorOf(kData + "robot_mesh.world");
  EXPECT_TRUE(contains(robot_mesh, "robot_mesh.world: model 'blobby', collision 'hull': a robot's collision must be a "
                                   "<box> or a <cylinder>"))
      << robot_mesh;
}

namespace {
std::string freshDir() {
  char dir[] = "/tmp/aula_world_test_XXXXXX";
  if (mkdtemp(dir) == nullptr) ADD_FAILURE() << "mkdtemp";
  return dir;
}
void writeText(const std::string& path, const std::string& text) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path) << text;
}
}  // namespace

TEST(LoadWorld, AWorldOrModelThatIncludesItselfIsRefusedAtOnce) {
  const std::string dir = freshDir();
  const std::string world = dir + "/loop.world";
  writeText(world, "<?xml version=\"1.0\"?><sdf version=\"1.9\"><world name=\"loop\"><include><uri>file://" + world +
                       "</uri></include></world></sdf>\n");
  std::string error = errorOf(world);
  EXPECT_TRUE(contains(error, "loop.world: includes itself (" + world + " -> " + world + ")")) << error;
  // A model whose model.sdf includes the model again, one level down.
  writeText(dir + "/models/echo/model.config", "<model><name>echo</name><sdf version=\"1.9\">model.sdf</sdf></model>");
  writeText(dir + "/models/echo/model.sdf", "<sdf version=\"1.9\"><model name=\"echo\"><static>true</static>"
                                            "<include><uri>model://echo</uri></include></model></sdf>");
  writeText(world, "<sdf version=\"1.9\"><world name=\"w\"><include><uri>model://echo</uri></include></world></sdf>");
  error = errorOf(world);
  EXPECT_TRUE(contains(error, "includes itself (" + world + " -> " + dir + "/models/echo/model.sdf -> " + dir +
                                  "/models/echo/model.sdf)"))
      << error;
  // A relative path would be looked up in the working directory first: refused with what to give.
  writeText(world, "<sdf version=\"1.9\"><world name=\"w\"><include><uri>loop.world</uri></include></world></sdf>");
  error = errorOf(world);
  EXPECT_TRUE(contains(error, "<include><uri>loop.world</uri>: give model://NAME (found on the model path) or an "
                              "absolute path"))
      << error;
}

TEST(LoadWorld, ATypoInTheSdfIsNamedWithItsFileAndLine) {
  const std::string dir = freshDir();
  const std::string head = "<?xml version=\"1.0\"?>\n<sdf version=\"1.9\">\n<world name=\"w\">\n";
  const std::string box = "<link name=\"l\"><collision name=\"c\"><geometry><box><size>1 1 1</size></box></geometry>"
                          "</collision></link>";
  const std::vector<std::pair<std::string, std::string>> typos = {
      {"<model name=\"m\">\n<static>ture</static>" + box + "</model>", "model 'm': <static>ture</static> is not a boolean (true/false) (" + dir + "/typo.world:5)"},
      {"<model name=\"m\"><static>true</static>\n<pose>1 2 3 0 0</pose>" + box + "</model>", "model 'm': <pose> needs 6 numbers, x y z roll pitch yaw (" + dir + "/typo.world:5)"},
      {"<model name=\"m\"><static>true</static>\n<pose>1 2 3 0 0 0.5x</pose>" + box + "</model>", "is not a list of numbers (" + dir + "/typo.world:5)"},
      {"<model name=\"m\"><static>true</static>\n\n<pose relative_to=\"f\">1 2 3 0 0 0</pose>" + box + "</model>",
       "model 'm': <pose relative_to=\"f\"> is only read inside a model (naming its link, joint or frame) (" + dir + "/typo.world:6)"},
      {"<model name=\"m\"><static>true</static>" + box + "</model>\n<model name=\"m\"><static>true</static>" + box + "</model>",
       "two models named 'm' (" + dir + "/typo.world:5)"},
      {"<model><static>true</static>" + box + "</model>", "<model> needs a name attribute (" + dir + "/typo.world:4)"},
  };
  for (const auto& [model, said] : typos) {
    writeText(dir + "/typo.world", head + model + "\n</world>\n</sdf>\n");
    const std::string error = errorOf(dir + "/typo.world");
    EXPECT_TRUE(contains(error, said)) << error;
  }
}

TEST(LoadWorld, ModelUrisNeverResolveInTheWorkingDirectory) {
  // A student's roomba/ folder (no model.config) where the program starts, and an empty folder
  // of the same name first on the model path: the first is ignored, the second named.
  const std::string dir = freshDir();
  writeText(dir + "/student/roomba/main.cpp", "int main() {}\n");
  writeText(dir + "/house.world", "<sdf version=\"1.9\"><world name=\"h\"><include><uri>model://roomba</uri>"
                                  "</include></world></sdf>");
  const auto previous = std::filesystem::current_path();
  std::filesystem::current_path(dir + "/student");
  const WorldSpec w = loadWorld(dir + "/house.world", {kWorlds + "models"});
  ASSERT_EQ(w.robots.size(), 1u);
  EXPECT_EQ(w.robots[0].name, "roomba");
  std::filesystem::create_directories(dir + "/empty/roomba");
  std::string error;
  try {
    loadWorld(dir + "/house.world", {dir + "/empty", kWorlds + "models"});
  } catch (const WorldError& e) {
    error = e.what();
  }
  std::filesystem::current_path(previous);
  EXPECT_TRUE(contains(error, "model://roomba is " + dir + "/empty/roomba, which has no model.config")) << error;
}

TEST(LoadWorld, NestedStaticModelsGroundPlaneAndInlineRobot) {
  const WorldSpec w = loadWorld(kData + "nested_static.world");
  EXPECT_DOUBLE_EQ(w.physics_step_s, 0.002);
  ASSERT_EQ(w.statics.size(), 2u);  // the ground plane is not an obstacle
  EXPECT_EQ(w.statics[0].name, "yard::base::post");
  EXPECT_TRUE(w.statics[0].pose.translation().isApprox(Eigen::Vector3d(10, 0, 1)));
  EXPECT_EQ(w.statics[1].name, "yard::shed::body::walls");
  EXPECT_TRUE(w.statics[1].pose.translation().isApprox(Eigen::Vector3d(9, 2, 1.5)));
  EXPECT_NEAR(yawOf(w.statics[1].pose), M_PI / 2, 1e-9);
  ASSERT_EQ(w.robots.size(), 1u);
  const RobotSpec& bot = w.robots[0];
  EXPECT_EQ(bot.name, "bot");
  EXPECT_NEAR(yawOf(bot.pose), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(bot.mass_kg, 4.0);
  ASSERT_EQ(bot.plugins.size(), 2u);
  EXPECT_EQ(bot.plugins[0].name, "drive");
  EXPECT_EQ(bot.plugins[0].owner, "bot");
  EXPECT_DOUBLE_EQ(bot.plugins[0].getDouble("max_v", 0), 1.5);  // whitespace trimmed
  try {
    bot.plugins[0].getBool("holonomic", false);
    FAIL();
  } catch (const WorldError& e) {
    EXPECT_STREQ(e.what(), "robot 'bot', plugin 'drive': <holonomic>yes</holonomic> is not a boolean (true/false)");
  }
  // Bounds and raster: the post and the shed only; the robot at (-3, -2) is not drawn.
  const Eigen::Vector4d b = staticBounds(w);
  EXPECT_TRUE(b.isApprox(Eigen::Vector4d(8.5, -0.5, 10.5, 3.0))) << b.transpose();
  MapTransform t;
  t.resolution_m = 0.5;
  t.origin_x_m = -5;
  t.origin_y_m = 5;
  t.width_px = t.height_px = 40;
  const cv::Mat map = rasterizeOccupancy(w, t, 0.0, 2.5);
  EXPECT_EQ(map.at<uint8_t>(t.worldToRow(-2), t.worldToCol(-3)), 255);
  EXPECT_EQ(map.at<uint8_t>(t.worldToRow(0), t.worldToCol(10)), 0);
  EXPECT_EQ(map.at<uint8_t>(t.worldToRow(2), t.worldToCol(9)), 0);
  // Post: a disc of radius 0.5 at (10, 0) -> pixel centres within 0.5 m: 5 pixels (a plus).
  cv::Mat post = map(cv::Rect(t.worldToCol(9), t.worldToRow(1), 4, 4)).clone();
  EXPECT_EQ(4 * 4 - cv::countNonZero(post), 4) << post;
}

TEST(PluginSpec, TypedParametersNameRobotPluginAndKey) {
  PluginSpec p;
  p.owner = "roomba";
  p.name = "laser";
  p.params = {{"samples", "18O"}, {"pose", "1 2 3"}, {"rate_hz", "20"}};
  EXPECT_EQ(p.getInt("missing", 7), 7);
  EXPECT_DOUBLE_EQ(p.getDouble("rate_hz", 0), 20.0);
  try {
    p.getInt("samples", 0);
    FAIL();
  } catch (const WorldError& e) {
    EXPECT_STREQ(e.what(), "robot 'roomba', plugin 'laser': <samples>18O</samples> is not an integer");
  }
  EXPECT_THROW(p.getPose("pose"), WorldError);
  // A driver type's reads are declared in world::pluginKeys: an undeclared one is a bug of Aula's.
  p.type = "laser";
  EXPECT_DOUBLE_EQ(p.getDouble("max_range", 10.0), 10.0);
  EXPECT_THROW(p.getDouble("max_rnge", 10.0), std::logic_error);
}

TEST(Occupancy, RotatedBoxIsRasterisedPixelExact) {
  const WorldSpec w = loadWorld(kData + "one_box.world");
  ASSERT_EQ(w.statics.size(), 1u);
  MapTransform t;
  t.resolution_m = 0.1;
  t.origin_x_m = 0;
  t.origin_y_m = 4;
  t.width_px = 30;
  t.height_px = 40;
  const cv::Mat map = rasterizeOccupancy(w, t, 0.0, 2.0);
  // Footprint x [0.5, 1.5], y [1, 3]: columns 5..14, rows 10..29 (pixel centres inside).
  for (int row = 0; row < 40; ++row) {
    for (int col = 0; col < 30; ++col) {
      const bool inside = col >= 5 && col <= 14 && row >= 10 && row <= 29;
      EXPECT_EQ(map.at<uint8_t>(row, col), inside ? 0 : 255) << "col " << col << " row " << row;
    }
  }
  // Out of the height band: nothing drawn.
  EXPECT_EQ(cv::countNonZero(rasterizeOccupancy(w, t, 1.5, 2.0)), 30 * 40);
}

TEST(GeneratedMaps, CityRoadsAreConnectedAndTheTaxiStartIsClear) {
  std::string image;
  const MapTransform t = MapTransform::load(std::string(AULA_MAPS_DIR) + "/cityLarge.yaml", &image);
  EXPECT_EQ(t.width_px, 400);
  EXPECT_EQ(t.height_px, 400);
  cv::Mat map = cv::imread(image, cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(map.empty());
  const int total_free = cv::countNonZero(map);
  // Strictly binary.
  EXPECT_EQ(cv::countNonZero(map == 0) + cv::countNonZero(map == 255), 400 * 400);
  // Clearance >= 4 m around the origin: every pixel touching the 4 m disc is free.
  const int c0 = t.worldToCol(0), r0 = t.worldToRow(0);
  const double reach = 4.0 + t.resolution_m * M_SQRT1_2;
  for (int row = 0; row < t.height_px; ++row) {
    for (int col = 0; col < t.width_px; ++col) {
      if (std::hypot(t.colToWorldX(col), t.rowToWorldY(row)) <= reach) {
        EXPECT_EQ(map.at<uint8_t>(row, col), 255) << "col " << col << " row " << row;
      }
    }
  }
  cv::Mat filled = map.clone();
  const int reached = cv::floodFill(filled, cv::Point(c0, r0), cv::Scalar(128), nullptr, 0, 0, 4);
  EXPECT_EQ(reached, total_free) << "some free space is not reachable from the taxi's start";
}

TEST(GeneratedMaps, VacuumFreeFloorIsAboutFiftySquareMetres) {
  std::string image;
  const MapTransform t = MapTransform::load(std::string(AULA_MAPS_DIR) + "/vacuum.yaml", &image);
  EXPECT_DOUBLE_EQ(t.resolution_m, 0.02);
  cv::Mat map = cv::imread(image, cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(map.empty());
  cv::Mat inside = map.clone();
  const int start_col = t.worldToCol(-1.0), start_row = t.worldToRow(1.5);
  ASSERT_EQ(map.at<uint8_t>(start_row, start_col), 255);
  const int reached = cv::floodFill(inside, cv::Point(start_col, start_row), cv::Scalar(128), nullptr, 0, 0, 4);
  const double area_m2 = reached * t.resolution_m * t.resolution_m;
  EXPECT_GT(area_m2, 40.0);
  EXPECT_LT(area_m2, 60.0);
  std::cout << "vacuum free floor reachable from the start: " << area_m2 << " m2\n";
  // No door to the outside: the flood never reaches the image border.
  for (int c = 0; c < map.cols; ++c) {
    EXPECT_NE(inside.at<uint8_t>(0, c), 128);
    EXPECT_NE(inside.at<uint8_t>(map.rows - 1, c), 128);
  }
}

TEST(GeneratedMaps, AutoparkStreetAtTwelvePixelsPerMetre) {
  std::string image;
  const MapTransform t = MapTransform::load(std::string(AULA_MAPS_DIR) + "/autopark.yaml", &image);
  EXPECT_NEAR(t.resolution_m, 1.0 / 12, 1e-12);
  EXPECT_NEAR(t.origin_x_m, -27, 1e-9);
  EXPECT_NEAR(t.origin_y_m, 7, 1e-9);
  const cv::Mat map = cv::imread(image, cv::IMREAD_GRAYSCALE);
  ASSERT_EQ(map.size(), cv::Size(768, 168));
  auto at = [&](double x, double y) { return map.at<uint8_t>(t.worldToRow(y), t.worldToCol(x)); };
  EXPECT_EQ(at(-7, 2.5), 255);      // the car's start (robots are not drawn)
  EXPECT_EQ(at(7.25, -3), 255);     // the free slot
  EXPECT_EQ(at(0.5, -3), 0);        // a parked car
  EXPECT_EQ(at(14, -3), 0);
  EXPECT_EQ(at(7.25, -4.2), 255);   // curb face at y = -4.25
  EXPECT_EQ(at(7.25, -4.3), 0);
  EXPECT_EQ(at(7.25, 4.95), 255);   // far curb face at y = +5
  EXPECT_EQ(at(7.25, 5.05), 0);
}

namespace {
int runMapgen(const std::string& args) {
  const int status = std::system((std::string(AULA_MAPGEN) + " " + args + " 2>/dev/null").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace

TEST(Mapgen, WritesImageAndMetadataAndRejectsBadInput) {
  const std::string dir = ::testing::TempDir();
  ASSERT_EQ(runMapgen(kData + "one_box.world --out " + dir + "one_box.png --resolution 0.1"), 0);
  std::string image;
  const MapTransform t = MapTransform::load(dir + "one_box.yaml", &image);
  // Default bounds: the box's footprint x [0.5, 1.5], y [1, 3].
  EXPECT_EQ(t.width_px, 10);
  EXPECT_EQ(t.height_px, 20);
  EXPECT_NEAR(t.origin_x_m, 0.5, 1e-9);
  EXPECT_NEAR(t.origin_y_m, 3.0, 1e-9);
  const cv::Mat map = cv::imread(image, cv::IMREAD_GRAYSCALE);
  ASSERT_EQ(map.size(), cv::Size(10, 20));
  EXPECT_EQ(cv::countNonZero(map), 0);  // all box
  EXPECT_EQ(runMapgen(""), 2);
  EXPECT_EQ(runMapgen(kData + "one_box.world --out " + dir + "x.png"), 2);
  EXPECT_EQ(runMapgen(kData + "one_box.world --out " + dir + "x.png --resolution -1"), 2);
  EXPECT_EQ(runMapgen(kData + "one_box.world --out " + dir + "x.png --resolution 0.1 --size 10"), 2);
  EXPECT_EQ(runMapgen(kData + "one_box.world --out " + dir + "x.jpg --resolution 0.1"), 2);
  EXPECT_EQ(runMapgen(kData + "missing_model.world --out " + dir + "x.png --resolution 0.1"), 2);
}

TEST(SliceAtHeight, KeepsOnlyWhatTheSensorPlaneCuts) {
  WorldSpec w;
  StaticObject low, high, cyl;
  low.shape.box_size_m = Eigen::Vector3d(1, 2, 0.2);
  low.pose.translation() = Eigen::Vector3d(1, 0, 0.1);  // z 0..0.2
  high.shape.box_size_m = Eigen::Vector3d(1, 1, 0.4);
  high.pose.translation() = Eigen::Vector3d(3, 0, 0.8);  // z 0.6..1.0: a table top
  cyl.shape.kind = ShapeKind::Cylinder;
  cyl.shape.radius_m = 0.3;
  cyl.shape.length_m = 1.0;
  cyl.pose = Eigen::Translation3d(0, 4, 0.5) * Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ());
  w.statics = {low, high, cyl};
  const aula::geometry::Obstacles2D at_laser = sliceAtHeight(w, 0.1);
  ASSERT_EQ(at_laser.rects.size(), 1u);
  EXPECT_EQ(at_laser.rects[0].length_m, 1.0);
  EXPECT_EQ(at_laser.rects[0].width_m, 2.0);
  ASSERT_EQ(at_laser.circles.size(), 1u);
  EXPECT_EQ(sliceAtHeight(w, 0.7).rects.size(), 1u);
}
