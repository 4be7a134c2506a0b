#include <aula/geometry/map_transform.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>
#include <string>

using aula::geometry::MapTransform;

namespace {
bool hasText(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
}  // namespace

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
  EXPECT_DOUBLE_EQ(u.origin_y_m, 250);
  EXPECT_EQ(u.height_px, 400);
}

TEST(MapTransform, LoadErrorsNameFileAndLine) {
  const std::string path = ::testing::TempDir() + "aula_bad_map.yaml";
  {
    std::ofstream out(path);
    out << "# comment\nimage: x.png\nresolution: fast\norigin_x: 0\norigin_y: 0\nwidth: 4\nheight: 4\n";
  }
  try {
    MapTransform::load(path);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(hasText(e.what(), path + ":3: 'resolution' is not a number")) << e.what();
  }
  {
    std::ofstream out(path);
    out << "image: x.png\nno colon here\n";
  }
  try {
    MapTransform::load(path);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(hasText(e.what(), path + ":2: expected 'key: value'")) << e.what();
  }
}
