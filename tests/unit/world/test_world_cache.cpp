// The parsed-world cache ($XDG_CACHE_HOME/aula/worlds): a cached spec equals the parsed one
// exactly, and an edited world or model file is parsed again.
#include "expect_same_world.hpp"

#include <aula/world/world_spec.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;
using namespace aula::world;

namespace {

// A private cache folder for this test process.
class WorldCache : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("aula-world-cache-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    setenv("XDG_CACHE_HOME", (root_ / "cache").c_str(), 1);
  }
  void TearDown() override { fs::remove_all(root_); }
  std::size_t entries() const {
    std::error_code error;
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(root_ / "cache" / "aula" / "worlds", error)) n += e.path().extension() == ".txt";
    return n;
  }
  fs::path root_;
};

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

std::string boxModel(double size_m) {
  const std::string s = std::to_string(size_m);
  return "<?xml version='1.0'?><sdf version='1.9'><model name='crate'><static>true</static><link name='l'>"
         "<collision name='c'><geometry><box><size>" + s + " " + s + " 1</size></box></geometry></collision>"
         "</link></model></sdf>";
}

}  // namespace

TEST_F(WorldCache, TheCachedSpecEqualsTheParsedOneExactly) {
  for (const char* name : {"autopark.world", "vacuum.world", "cityLarge.world"}) {
    const std::string path = std::string(AULA_SOURCE_DIR) + "/worlds/" + name;
    const WorldSpec parsed = loadWorld(path);
    const std::size_t written = entries();
    const WorldSpec cached = loadWorld(path);
    EXPECT_EQ(entries(), written);
    SCOPED_TRACE(name);
    aula::world::testing::expectSameWorld(cached, parsed);
  }
  EXPECT_EQ(entries(), 3u);
}

TEST_F(WorldCache, AnEditedWorldOrModelFileIsParsedAgain) {
  const fs::path models = root_ / "models";
  write(models / "crate" / "model.config", "<?xml version='1.0'?><model><name>crate</name><sdf version='1.9'>model.sdf</sdf></model>");
  write(models / "crate" / "model.sdf", boxModel(1.0));
  const fs::path world = root_ / "yard.world";
  const std::string head = "<?xml version='1.0'?><sdf version='1.9'><world name='yard'>";
  write(world, head + "<include><uri>model://crate</uri><pose>3 0 0.5 0 0 0</pose></include></world></sdf>");

  EXPECT_EQ(loadWorld(world.string(), {models.string()}).statics.at(0).shape.box_size_m.x(), 1.0);
  const WorldSpec first = loadWorld(world.string(), {models.string()});
  EXPECT_EQ(loadWorld(world.string(), {models.string()}).statics.at(0).shape.box_size_m.x(), 1.0);  // cached
  EXPECT_NE(first.sha256, sha256OfFile(world.string())) << "the world's hash covers the models it includes";

  write(models / "crate" / "model.sdf", boxModel(2.0));
  const WorldSpec edited = loadWorld(world.string(), {models.string()});
  EXPECT_EQ(edited.statics.at(0).shape.box_size_m.x(), 2.0) << "an edited model";
  EXPECT_NE(edited.sha256, first.sha256) << "an edited model changes the world's hash";

  write(world, head + "<include><uri>model://crate</uri><pose>7 0 0.5 0 0 0</pose></include></world></sdf>");
  const WorldSpec moved = loadWorld(world.string(), {models.string()});
  EXPECT_EQ(moved.statics.at(0).pose.translation().x(), 7.0) << "an edited world";
  EXPECT_NE(moved.sha256, edited.sha256) << "an edited world changes its hash";
  EXPECT_EQ(moved.sha256, worldSha256(world.string(), {(models / "crate" / "model.config").string(),
                                                       (models / "crate" / "model.sdf").string(), world.string()}));
}

TEST_F(WorldCache, ADamagedEntryIsIgnored) {
  const std::string path = std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world";
  const WorldSpec parsed = loadWorld(path);
  for (const auto& e : fs::directory_iterator(root_ / "cache" / "aula" / "worlds")) {
    std::ofstream(e.path(), std::ios::trunc) << "aula-world-cache-v2\nworld\tvacuum\n";  // cut short
  }
  const WorldSpec again = loadWorld(path);
  EXPECT_EQ(again.statics.size(), parsed.statics.size());
  EXPECT_EQ(again.robots.size(), parsed.robots.size());
}

// An entry is read only by the reader that wrote it: its first line names the reader's sources'
// SHA-256 (built in, libs/world/cmake/reader_version.cmake), so an Aula whose reader changed never
// serves a world as an older one read it (older robots, maps, marks), with no version to raise by hand.
TEST_F(WorldCache, AnEntryOfAnotherReaderIsNotRead) {
  const std::string path = std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world";
  const WorldSpec parsed = loadWorld(path);
  ASSERT_EQ(entries(), 1u);
  for (const auto& e : fs::directory_iterator(root_ / "cache" / "aula" / "worlds")) {
    std::ifstream in(e.path());
    std::string header, rest((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t eol = rest.find('\n');
    header = rest.substr(0, eol);
    ASSERT_EQ(header.size(), std::string("aula-world-cache-v5 ").size() + 64) << header;
    EXPECT_EQ(header.find_first_not_of("0123456789abcdef", header.size() - 64), std::string::npos) << header;
    // The entry as another reader could have left it: another digest, and the world named otherwise.
    std::string other = "aula-world-cache-v5 " + std::string(64, '0') + rest.substr(eol);
    const std::size_t name = other.find("\nworld\t" + parsed.name + "\t");
    ASSERT_NE(name, std::string::npos);
    other.replace(name + 7, parsed.name.size(), "older");
    std::ofstream(e.path(), std::ios::trunc) << other;
  }
  const WorldSpec again = loadWorld(path);
  EXPECT_EQ(again.name, parsed.name) << "the other reader's entry was read";
  aula::world::testing::expectSameWorld(again, parsed);
}
