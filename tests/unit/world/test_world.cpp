#include <aula/world/map_transform.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>

using namespace aula::world;

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
  EXPECT_EQ(car.name, "taxi_holo_laser");
  EXPECT_TRUE(car.pose.translation().isApprox(Eigen::Vector3d(-7, 2.5, 0)));
  int lasers = 0;
  for (const auto& p : car.plugins) lasers += p.type == "laser";
  EXPECT_EQ(lasers, 3);
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
  const std::string plugin = errorOf(kData + "bad_plugin.world");
  EXPECT_TRUE(contains(plugin, "model 'bot', plugin 'eyes': unknown driver filename 'camera'")) << plugin;
  EXPECT_TRUE(contains(plugin, "known: bumper, laser, motors, pose3d")) << plugin;
  const std::string mesh = errorOf(kData + "mesh_obstacle.world");
  EXPECT_TRUE(contains(mesh, "model 'statue', collision 'shape': only <box> and <cylinder>")) << mesh;
  const std::string links = errorOf(kData + "two_links.world");
  EXPECT_TRUE(contains(links, "model 'wobbly': a robot (non-static model) must have exactly one <link>")) << links;
  const std::string xml = errorOf(kData + "malformed.world");
  EXPECT_TRUE(contains(xml, "malformed.world: cannot load world")) << xml;
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
}

TEST(MapTransform, RoundTripAndFile) {
  MapTransform t;
  t.resolution_m = 1.25;
  t.origin_x_m = -250;
  t.origin_y_m = 250;
  t.width_px = t.height_px = 400;
  for (int col : {0, 1, 199, 200, 399}) {
    for (int row : {0, 57, 399}) {
      EXPECT_EQ(t.worldToCol(t.colToWorldX(col)), col);
      EXPECT_EQ(t.worldToRow(t.rowToWorldY(row)), row);
    }
  }
  EXPECT_EQ(t.worldToCol(0.0), 200);
  EXPECT_EQ(t.worldToRow(249.9), 0);  // north is up
  const std::string path = ::testing::TempDir() + "aula_map.yaml";
  t.save(path, "map.png");
  std::string image;
  const MapTransform u = MapTransform::load(path, &image);
  EXPECT_EQ(u.width_px, 400);
  EXPECT_DOUBLE_EQ(u.resolution_m, 1.25);
  EXPECT_DOUBLE_EQ(u.origin_x_m, -250);
  EXPECT_EQ(image, ::testing::TempDir() + "map.png");
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
  // Clearance of 4 m (3 px) around the origin.
  const int c0 = t.worldToCol(0), r0 = t.worldToRow(0);
  for (int dr = -3; dr <= 3; ++dr)
    for (int dc = -3; dc <= 3; ++dc) EXPECT_EQ(map.at<uint8_t>(r0 + dr, c0 + dc), 255);
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
  EXPECT_LT(area_m2, 65.0);
  // No door to the outside: the flood never reaches the image border.
  for (int c = 0; c < map.cols; ++c) {
    EXPECT_NE(inside.at<uint8_t>(0, c), 128);
    EXPECT_NE(inside.at<uint8_t>(map.rows - 1, c), 128);
  }
}
