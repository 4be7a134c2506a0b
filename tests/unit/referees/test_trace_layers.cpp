// The trace's layers (trace_layers.hpp) on plain messages: what is kept, when, and in what form.
#include <aula/referee/trace_layers.hpp>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

using aula::referee::Report;
using aula::referee::RunTrace;
using aula::referee::TraceLayers;

namespace {

aula::world::RobotSpec robotWithTwoLasers() {
  aula::world::RobotSpec robot;
  robot.name = "car";
  for (const auto& [name, channel, pose] : {std::tuple<std::string, std::string, std::string>{"front", "CAR_LASER_FRONT", "2 0 0.1 0 0 0"},
                                            {"right", "CAR_LASER_RIGHT", "0.3 -1 0.1 0 0 -1.5707963267948966"}}) {
    aula::world::PluginSpec laser;
    laser.name = name;
    laser.type = "laser";
    laser.params = {{"channel", channel}, {"pose", pose}};
    robot.plugins.push_back(laser);
  }
  return robot;
}

aula::config::Config settings(bool belief, bool plan) {
  aula::config::Config cfg;
  cfg.set("Ex.Console.Channel", "EX_CONSOLE", "test");
  if (belief) cfg.set("Ex.Belief.Channel", "EX_BELIEF", "test");
  if (plan) cfg.set("Ex.Plan.Channel", "EX_PLAN", "test");
  return cfg;
}

nlohmann::json layersOf(const TraceLayers& layers) {
  Report out;
  layers.addTo(out);
  return nlohmann::json::parse(out.toJson())["layers"];
}

aula::console_t printed(int64_t utime, const std::string& text) {
  aula::console_t msg{};
  msg.utime = utime;
  msg.text = text;
  return msg;
}

aula::laser_t scan(int64_t utime, std::vector<float> ranges) {
  aula::laser_t msg{};
  msg.utime = utime;
  msg.ranges = std::move(ranges);
  msg.num_ranges = static_cast<int32_t>(msg.ranges.size());
  msg.min_angle = -1.5f;
  msg.angle_increment = 1.5f;
  msg.max_range = 10.0f;
  return msg;
}

struct Layers : ::testing::Test {
  aula::lcmbus::Bus bus{"memq://"};
  RunTrace trace;
};

TEST_F(Layers, ConsoleLinesKeepTheirSimTimeInsideTheEpisodeOnly) {
  TraceLayers layers(bus, settings(false, false), robotWithTwoLasers(), "Ex", trace);
  layers.onConsole(printed(500'000, "before the start"));
  trace.start(1'000'000);
  layers.onConsole(printed(1'080'000, "hello\nworld"));
  layers.onConsole(printed(2'000'000, std::string("bad \xff byte")));
  trace.stop(3'000'000);
  layers.onConsole(printed(2'920'000, "stamped before the stop, read after it"));
  layers.onConsole(printed(3'000'000, "at the stop"));
  const nlohmann::json console = layersOf(layers)["console"];
  ASSERT_EQ(console["lines"].size(), 4u) << console.dump();
  EXPECT_EQ(console["lines"][0]["text"], "hello");
  EXPECT_DOUBLE_EQ(console["lines"][0]["t_s"].get<double>(), 0.08);
  EXPECT_EQ(console["lines"][1]["text"], "world");
  EXPECT_EQ(console["lines"][2]["text"], "bad \xEF\xBF\xBD byte") << "invalid UTF-8 becomes U+FFFD";
  EXPECT_EQ(console["lines"][3]["text"], "stamped before the stop, read after it");
  EXPECT_EQ(console["dropped_lines"], 0);
}

TEST_F(Layers, AFloodKeepsItsFirstAndLastLinesAndSaysWhatWasLeftOut) {
  TraceLayers layers(bus, settings(false, false), robotWithTwoLasers(), "Ex", trace);
  trace.start(0);
  const std::string line(99, 'x');  // 100 bytes with its line break
  for (int i = 0; i < 2000; ++i) layers.onConsole(printed(i * 1000, std::to_string(i % 10) + line.substr(1)));
  const nlohmann::json console = layersOf(layers)["console"];
  const size_t kept = console["lines"].size();
  EXPECT_EQ(kept, 2 * (TraceLayers::kConsoleHalfBytes / 100));
  EXPECT_EQ(console["dropped_lines"].get<size_t>(), 2000 - kept);
  EXPECT_EQ(console["dropped_bytes"].get<size_t>(), (2000 - kept) * 100);
  EXPECT_EQ(console["lines"][0]["text"].get<std::string>()[0], '0') << "the first line is kept";
  EXPECT_DOUBLE_EQ(console["lines"][kept - 1]["t_s"].get<double>(), 1.999) << "and the last";
}

TEST_F(Layers, LasersAreSampledOnSimTimeWithTheirMountsAndDeltaEncodedRanges) {
  TraceLayers layers(bus, settings(false, false), robotWithTwoLasers(), "Ex", trace);
  trace.start(1'000'000);
  // Every other beam: 1.0, 1.5 and 12 m (beyond the max range, kept at 10 m) of five.
  layers.onLaser(0, scan(1'000'000, {1.0f, 9.0f, 1.5f, 9.0f, 12.0f}));
  layers.onLaser(0, scan(2'900'000, {2.0f, 2.0f, 2.0f}));   // within the period (2 s): not kept
  layers.onLaser(0, scan(3'000'000, {3.0f, 3.0f, 3.0f}));
  layers.onLaser(1, scan(1'500'000, {0.25f}));
  const nlohmann::json lasers = layersOf(layers)["lasers"];
  ASSERT_EQ(lasers.size(), 2u);
  EXPECT_EQ(lasers[0]["name"], "front");
  EXPECT_EQ(lasers[0]["mount"], nlohmann::json({2.0, 0.0, 0.0}));
  EXPECT_NEAR(lasers[1]["mount"][2].get<double>(), -1.570796, 1e-6);
  ASSERT_EQ(lasers[0]["scans"].size(), 2u) << lasers.dump();
  EXPECT_DOUBLE_EQ(lasers[0]["range_step_m"].get<double>(), 0.02);
  EXPECT_EQ(lasers[0]["scans"][0]["ranges"], nlohmann::json({50, 25, 425})) << "1, 1.5 and 10 m in 2 cm steps, delta-encoded";
  EXPECT_DOUBLE_EQ(lasers[0]["increment_rad"].get<double>(), 3.0) << "two beams' angle";
  EXPECT_DOUBLE_EQ(lasers[0]["scans"][1]["t_s"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(lasers[0]["period_s"].get<double>(), 2.0);
  EXPECT_EQ(lasers[1]["scans"][0]["ranges"], nlohmann::json({13})) << "0.25 m: 12.5 steps, rounded";
}

TEST_F(Layers, TheBeliefIsPutWhereTheTruthWasWhenItFirstSpokeAndKeepsAMapAPeriodAndTheLatest) {
  TraceLayers layers(bus, settings(true, false), robotWithTwoLasers(), "Ex", trace);
  trace.start(0);
  trace.onPose(0, 5.0, -2.0, 0.0);
  auto belief = [](int64_t utime, double x_m, int64_t version) {
    aula::belief_t msg{};
    msg.utime = utime;
    msg.x_m = x_m;
    msg.map_version = version;
    if (version > 0) {
      msg.map_width = 2;
      msg.map_height = 2;
      msg.map_resolution_m = 0.1;
      msg.map_cells = {0, 0, 128, 255};
      msg.map_cells_count = 4;
    }
    return msg;
  };
  layers.onBelief(belief(0, 0.0, 1));
  layers.onBelief(belief(500'000, 0.5, 0));
  layers.onBelief(belief(10'000'000, 1.0, 2));   // not a period later: the latest, replaced by the next
  layers.onBelief(belief(20'000'000, 1.0, 3));   // the latest
  layers.onBelief(belief(130'000'000, 1.0, 3));  // the same version: nothing new
  const nlohmann::json b = layersOf(layers)["belief"];
  EXPECT_EQ(b["x_mm"], nlohmann::json({5000, 500, 500, 0, 0})) << "x placed 5 m on, delta-encoded";
  EXPECT_EQ(b["y_mm"][0], -2000);
  ASSERT_EQ(b["maps"].size(), 2u) << b["maps"].dump();
  EXPECT_DOUBLE_EQ(b["maps"][1]["t_s"].get<double>(), 20.0);
  EXPECT_EQ(b["maps"][0]["runs"], nlohmann::json({0, 2, 1, 1, 2, 1})) << "free, free, unknown, occupied";
  EXPECT_EQ(b["maps"][0]["origin_m"], nlohmann::json({5.0, -2.0}));
}

TEST_F(Layers, APlanMadeBeforeTheStartIsShownFromTheStartAndAnOlderOneIsNot) {
  TraceLayers layers(bus, settings(false, true), robotWithTwoLasers(), "Ex", trace);
  auto plan = [](int64_t utime, uint8_t grey) {
    aula::plan_t msg{};
    msg.utime = utime;
    msg.width = 2;
    msg.height = 1;
    msg.resolution_m = 1;
    msg.field = {grey, 255};
    msg.field_count = 2;
    msg.path_col = {1};
    msg.path_row = {0};
    msg.path_count = 1;
    return msg;
  };
  layers.onPlan(plan(100, 0));
  layers.onPlan(plan(200, 32));
  trace.start(300);
  layers.onPlan(plan(400, 64));
  const nlohmann::json plans = layersOf(layers)["plans"];
  ASSERT_EQ(plans.size(), 2u) << plans.dump();
  EXPECT_DOUBLE_EQ(plans[0]["t_s"].get<double>(), 0.0);
  EXPECT_EQ(plans[0]["field"], nlohmann::json({2, 1, 15, 1})) << "16 grey levels, run-length encoded";
  EXPECT_EQ(plans[0]["path"], nlohmann::json({1, 0}));
  EXPECT_EQ(plans[1]["field"][0], 4);
}

TEST_F(Layers, ANewEpisodeKeepsNothingOfTheLastOne) {
  TraceLayers layers(bus, settings(false, false), robotWithTwoLasers(), "Ex", trace);
  trace.start(0);
  layers.onConsole(printed(100'000, "first episode"));
  layers.onLaser(0, scan(100'000, {1.0f}));
  trace.start(5'000'000);  // a hot reload
  layers.onConsole(printed(5'100'000, "second episode"));
  const nlohmann::json l = layersOf(layers);
  ASSERT_EQ(l["console"]["lines"].size(), 1u);
  EXPECT_EQ(l["console"]["lines"][0]["text"], "second episode");
  EXPECT_TRUE(l["lasers"][0]["scans"].empty());
}

}  // namespace

// A headless run without --trace leaves the layers' channels: what comes on them is not read.
TEST_F(Layers, LayersLeftOutReadNothingFromTheBus) {
  TraceLayers kept(bus, settings(true, true), robotWithTwoLasers(), "Ex", trace);
  TraceLayers left(bus, settings(true, true), robotWithTwoLasers(), "Ex", trace);
  left.leave(bus);
  trace.start(0);
  const aula::laser_t msg = scan(1'000'000, {1.0f, 2.0f});
  bus.publish("CAR_LASER_FRONT", &msg);
  const aula::console_t line = printed(1'000'000, "hello");
  bus.publish("EX_CONSOLE", &line);
  while (bus.handleTimeout(0) > 0) {
  }
  EXPECT_EQ(layersOf(kept)["lasers"][0]["scans"].size(), 1u) << layersOf(kept).dump();
  EXPECT_EQ(layersOf(kept)["console"]["lines"].size(), 1u);
  EXPECT_EQ(layersOf(left)["lasers"][0]["scans"].size(), 0u) << layersOf(left).dump();
  EXPECT_EQ(layersOf(left)["console"]["lines"].size(), 0u) << layersOf(left).dump();
}
