// Aula's SDF reader (libs/world/src/world_sdf.cpp, tinyxml2) against libsdformat 12, world by
// world: every shipped world, every generator's world (the tests' and `aula grade`'s own
// arguments) and every kind of world the tests write, read by both, give the same WorldSpec and
// the same files read, bit for bit; a world one refuses, the other refuses too. Built only where
// libsdformat is (Debian 12); Debian 13 has none, and there the reader is all there is.
#include "expect_same_world.hpp"
#include "sdformat_oracle.hpp"
#include "world_sdf.hpp"

#include <aula/grade/generated_worlds.hpp>
#include <aula/world/world_spec.hpp>

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using namespace aula::world;

namespace {

const std::string kWorlds = std::string(AULA_SOURCE_DIR) + "/worlds/";
const std::string kData = std::string(AULA_SOURCE_DIR) + "/tests/data/worlds/";

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void writeFile(const std::string& path, const std::string& text) {
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream(path) << text;
}

std::string freshDir() {
  char dir[] = "/tmp/aula_sdf_oracle_XXXXXX";
  if (mkdtemp(dir) == nullptr) ADD_FAILURE() << "mkdtemp";
  return dir;
}

// Reads `world` with both; both refuse it, or both give the same spec and files. Returns
// whether it was read.
bool expectBothAgree(const std::string& world, std::vector<std::string> folders = {}) {
  if (folders.empty()) folders = modelSearchPath(world);
  WorldSpec ours, theirs;
  std::vector<std::string> our_inputs, their_inputs;
  std::string our_error, their_error;
  try {
    parseSdfWorld(world, folders, ours, our_inputs);
  } catch (const WorldError& e) {
    our_error = e.what();
  }
  try {
    oracle::parseWithSdformat(world, folders, theirs, their_inputs);
  } catch (const WorldError& e) {
    their_error = e.what();
  }
  EXPECT_EQ(our_error.empty(), their_error.empty())
      << world << "\n  Aula's reader: " << (our_error.empty() ? "read it" : our_error)
      << "\n  libsdformat:   " << (their_error.empty() ? "read it" : their_error);
  if (!our_error.empty() || !their_error.empty()) return false;
  SCOPED_TRACE(world);
  aula::world::testing::expectSameWorld(ours, theirs);
  EXPECT_EQ(our_inputs, their_inputs) << world;
  return true;
}

int runGenerator(const std::string& tool, const std::string& out, const std::vector<std::string>& args) {
  std::string command = std::string(AULA_PYTHON) + " " + kWorlds + "tools/" + tool + " --out " + out;
  for (const auto& a : args) command += " '" + a + "'";  // the project's own arguments: no quote in them
  const int status = std::system((command + " >/dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST(SdfReaderOracle, EveryShippedWorld) {
  int read = 0;
  for (const auto& entry : fs::directory_iterator(kWorlds)) {
    if (entry.path().extension() != ".world") continue;
    EXPECT_TRUE(expectBothAgree(entry.path().string())) << entry.path();
    ++read;
  }
  EXPECT_GE(read, 9);
}

TEST(SdfReaderOracle, EveryTestDataWorldReadOrRefusedAlike) {
  int read = 0, refused = 0;
  for (const auto& entry : fs::directory_iterator(kData)) {
    if (entry.path().extension() != ".world") continue;
    (expectBothAgree(entry.path().string()) ? read : refused) += 1;
  }
  EXPECT_GE(read, 4);     // the driver keys are checked after reading (loadWorld): those are read
  EXPECT_GE(refused, 5);  // a missing model, meshes, malformed XML, a robot of two links
}

// The generators with the arguments the tests give them, and `aula grade`'s held-out worlds
// (generatorArguments, 3 of each kind, as --worlds=generate:KIND:3 writes them).
TEST(SdfReaderOracle, EveryGeneratorsWorlds) {
  const std::string dir = freshDir();
  std::vector<std::pair<std::string, std::vector<std::string>>> runs = {
      {"make_house.py", {}},
      {"make_house.py", {"--seed", "11", "--rooms-x", "2", "--rooms-y", "2", "--room-size", "3.6", "--start=1.5,1.5,1.0"}},
      {"make_house.py", {"--seed", "21", "--rooms-x", "3", "--rooms-y", "2"}},
      {"make_city.py", {}},
      {"make_city.py", {"--seed", "5", "--blocks", "3"}},
      {"make_autopark.py", {}},
      {"make_autopark.py", {"--slot-length", "8", "--slot-x", "6", "--start=-12,2.5,0"}},
      {"make_autopark.py", {"--slot-length", "5.6", "--curb-offset", "0.5", "--kinematics", "ackermann"}},
      {"make_autopark.py", {"--slot-length", "5.2", "--curb-offset", "0.5", "--kinematics", "diff"}},
  };
  for (const char* kind : {"house", "city", "street"}) {
    aula::grade::WorldsToGenerate what;
    what.kind = kind;
    what.count = 3;
    for (int i = 1; i <= what.count; ++i) {
      runs.emplace_back(std::string(kind) == "house" ? "make_house.py" : std::string(kind) == "city" ? "make_city.py" : "make_autopark.py",
                        aula::grade::generatorArguments(what, i));
    }
  }
  int n = 0;
  for (const auto& [tool, args] : runs) {
    const std::string world = dir + "/gen" + std::to_string(n++) + ".world";
    ASSERT_EQ(runGenerator(tool, world, args), 0) << tool;
    EXPECT_TRUE(expectBothAgree(world, {kWorlds + "models"})) << tool;
  }
  fs::remove_all(dir);
}

// What the tests write: a robot inline in the house, a model of the test's own on the model path
// included with a name and a pose, no <physics>, nested includes in a static model, an include
// that makes a model static and adds a plugin, poses in degrees and as quaternions.
TEST(SdfReaderOracle, TheKindsOfWorldTheTestsWrite) {
  const std::string dir = freshDir();
  const std::string house = readFile(kWorlds + "vacuum.world");
  const auto begin = house.find("<include>"), end = house.find("</include>") + 10;
  std::string roomba = readFile(kWorlds + "models/roomba/model.sdf");
  roomba = roomba.substr(roomba.find("<model name=\"roomba\">"), roomba.rfind("</model>") + 8 - roomba.find("<model name=\"roomba\">"));
  const std::string inline_robot = std::regex_replace(
      std::regex_replace(roomba, std::regex("ROOMBA_"), "CLEANER_"), std::regex("<model name=\"roomba\">"),
      "<model name=\"roomba\"><pose>-1.000000 1.500000 0 0 0 0</pose>");
  writeFile(dir + "/inline.world", house.substr(0, begin) + inline_robot + house.substr(end));
  EXPECT_TRUE(expectBothAgree(dir + "/inline.world"));

  writeFile(dir + "/my_models/tinybot/model.config",
            "<?xml version=\"1.0\"?><model><name>tinybot</name><sdf version=\"1.9\">model.sdf</sdf></model>\n");
  writeFile(dir + "/my_models/tinybot/model.sdf", "<?xml version=\"1.0\"?>\n<sdf version=\"1.9\">\n" + roomba + "\n</sdf>\n");
  std::string world = house.substr(0, begin) +
                      "<include><uri>model://tinybot</uri><name>tinybot</name><pose>-1 1.5 0 0 0 0.3</pose></include>" +
                      house.substr(end);
  world = std::regex_replace(world, std::regex("<physics[^>]*>.*</physics>"), "");
  writeFile(dir + "/worlds/house.world", world);
  EXPECT_TRUE(expectBothAgree(dir + "/worlds/house.world", {dir + "/my_models", kWorlds + "models"}));

  const std::string crate =
      "<?xml version='1.0'?><sdf version='1.9'><model name='crate'><pose>0 0 0.5 0 0 0.25</pose><link name='l'>"
      "<pose>0.1 0 0 0 0 0</pose><collision name='c'><geometry><box><size>1 2 1</size></box></geometry></collision>"
      "<collision name='d'><pose degrees='true'>1 0 0 0 0 90</pose><geometry><cylinder><radius>0.2</radius>"
      "<length>1</length></cylinder></geometry></collision></link></model></sdf>";
  writeFile(dir + "/models/crate/model.config", "<?xml version='1.0'?><model><name>crate</name><sdf version='1.9'>model.sdf</sdf></model>");
  writeFile(dir + "/models/crate/model.sdf", crate);
  writeFile(dir + "/models/stack/model.config", "<?xml version='1.0'?><model><name>stack</name><sdf version='1.9'>model.sdf</sdf></model>");
  writeFile(dir + "/models/stack/model.sdf",
            "<?xml version='1.0'?><sdf version='1.9'><model name='stack'><static>true</static>"
            "<include><uri>model://crate</uri><name>low</name></include>"
            "<include><uri>model://crate</uri><name>high</name><pose>0 0 1 0.1 0.2 0.3</pose></include>"
            "<model name='lid'><pose rotation_format='quat_xyzw'>0 0 2 0 0 0.3826834323650898 0.9238795325112867</pose>"
            "<link name='l'><collision name='c'><geometry><box><size>1 1 0.1</size></box></geometry></collision></link></model>"
            "</model></sdf>");
  writeFile(dir + "/yard.world",
            "<?xml version='1.0'?><sdf version='1.9'><world name='yard'>"
            "<physics name='fast' type='dart'><max_step_size>0.004</max_step_size></physics>"
            "<aula:destination name='gate'>3 -4.5</aula:destination>"
            "<include><uri>model://stack</uri><pose>5 5 0 0 0 -1</pose></include>"
            "<include><uri>model://crate</uri><name>fixed</name><static>true</static><pose>-5 0 0 0 0 0</pose></include>"
            "<include><uri>model://tinybot</uri><name>guest</name><pose>0 0 0 0 0 1.2</pose>"
            "<plugin name='extra_pose' filename='pose3d'><channel>GUEST_POSE2</channel><rate_hz> 10 </rate_hz></plugin>"
            "</include>"
            "<model name='ground'><static>1</static><link name='g'><collision name='plane'><geometry><plane>"
            "<normal>0 0 1</normal></plane></geometry></collision></link></model>"
            "</world></sdf>");
  EXPECT_TRUE(expectBothAgree(dir + "/yard.world", {dir + "/models", dir + "/my_models"}));

  // Refused by both: a pose relative to a frame, two worlds, a negative box, a robot with two
  // collisions, a model file with no model.config, an unreadable number.
  const std::string head = "<?xml version='1.0'?><sdf version='1.9'><world name='w'>";
  const std::vector<std::string> refused = {
      head + "<model name='m'><static>true</static><pose relative_to='x'>1 0 0 0 0 0</pose><frame name='x'/>"
             "<link name='l'><collision name='c'><geometry><box><size>1 1 1</size></box></geometry></collision></link></model></world></sdf>",
      head + "</world><world name='v'></world></sdf>",
      head + "<model name='m'><static>true</static><link name='l'><collision name='c'><geometry><box><size>1 -1 1</size></box>"
             "</geometry></collision></link></model></world></sdf>",
      head + "<model name='m'><link name='l'><collision name='c'><geometry><box/></geometry></collision>"
             "<collision name='d'><geometry><box/></geometry></collision></link>"
             "<plugin name='pose' filename='pose3d'><channel>M_POSE</channel></plugin></model></world></sdf>",
      head + "<include><uri>model://nothing_here</uri></include></world></sdf>",
      head + "<model name='m'><static>true</static><link name='l'><collision name='c'><geometry><cylinder><radius>abc</radius>"
             "</cylinder></geometry></collision></link></model></world></sdf>",
  };
  for (std::size_t i = 0; i < refused.size(); ++i) {
    const std::string path = dir + "/refused" + std::to_string(i) + ".world";
    writeFile(path, refused[i]);
    EXPECT_FALSE(expectBothAgree(path, {dir + "/models"})) << refused[i];
  }
  fs::remove_all(dir);
}
