// The vacuum cleaner exercise, headless in lockstep: `aula run vacuum` with the reference
// solution for the full 900 s of sim time (about 4 s wall each). The figures over many seeds
// are in docs/performance.md, from bench/vacuum_runs.sh.
#include "test_support.hpp"

#include <aula/belief_t.hpp>
#include <aula/pose3d_t.hpp>
#include <aula/process/child_process.hpp>

#include <lcm/lcm-cpp.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <vector>
#include <regex>
#include <sstream>

using namespace std::chrono_literals;
using aula::testing::readFile;

namespace {


std::string runVacuum(int seed, const std::string& tag) {
  const std::string report = ::testing::TempDir() + "vacuum_" + tag + ".json";
  const std::string log = ::testing::TempDir() + "vacuum_" + tag + ".log";
  std::remove(report.c_str());
  aula::process::ChildProcess run({std::string(AULA_BIN_DIR) + "/aula", "run", "vacuum", "--headless",
                                   "--algorithm=reference", "--seed=" + std::to_string(seed),
                                   "--report=" + report,
                                   "--lcm-url=" + aula::testing::privateLcmUrl()},
                                  log, log);
  const auto code = run.wait(100s);
  EXPECT_TRUE(code.has_value()) << readFile(log);
  EXPECT_EQ(code.value_or(-1), 0) << readFile(log);
  return readFile(report);
}


}  // namespace

TEST(VacuumRun, SameSeedSameReportDifferentSeedDifferentRun) {
  const std::string a = runVacuum(3, "a");
  const std::string b = runVacuum(3, "b");
  const std::string c = runVacuum(4, "c");
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, b) << "the same seed must give a byte-identical report";
  EXPECT_NE(a, c) << "another seed should give another run";
  EXPECT_NE(a.find("\"exercise\": \"vacuum\""), std::string::npos) << a;
  EXPECT_DOUBLE_EQ(aula::testing::jsonNumber(a, "sim_time_s"), 900.0) << a;
  // The bar for one run; the median over seeds is higher (docs/performance.md).
  EXPECT_GE(aula::testing::jsonNumber(a, "coverage_percent"), 55.0) << a;
  EXPECT_GE(aula::testing::jsonNumber(c, "coverage_percent"), 55.0) << c;
  EXPECT_DOUBLE_EQ(aula::testing::jsonNumber(a, "mark"), 10.0) << a;
  // 50 Hz for 900 s, both ends counted: the referee saw every pose message the driver sent.
  EXPECT_DOUBLE_EQ(aula::testing::jsonNumber(a, "pose_messages"), 45001.0) << a;
  EXPECT_NE(a.find("\"coverage_per_100s\": ["), std::string::npos) << a;
}

// Two runs of the same seed at once, each on its own port, contending for the same two cores:
// lockstep makes each report byte-identical to the other and to a run alone.
TEST(VacuumRun, TwoRunsAtOnceGiveTheSameReportAsOneAlone) {
  const std::string alone = runVacuum(5, "alone");
  std::vector<std::unique_ptr<aula::process::ChildProcess>> runs;
  std::vector<std::string> reports, logs;
  for (const char* tag : {"together_a", "together_b"}) {
    reports.push_back(::testing::TempDir() + "vacuum_" + tag + ".json");
    logs.push_back(::testing::TempDir() + "vacuum_" + tag + ".log");
    std::remove(reports.back().c_str());
    const std::string url = "udpm://239.255.76.67:" + std::to_string(aula::testing::freeUdpPort()) + "?ttl=0";
    runs.push_back(std::make_unique<aula::process::ChildProcess>(
        std::vector<std::string>{std::string(AULA_BIN_DIR) + "/aula", "run", "vacuum", "--headless", "--algorithm=reference",
                                 "--seed=5", "--report=" + reports.back(), "--lcm-url=" + url},
        logs.back(), logs.back()));
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto code = runs[i]->wait(200s);
    ASSERT_EQ(code.value_or(-1), 0) << readFile(logs[i]);
  }
  ASSERT_FALSE(alone.empty());
  EXPECT_EQ(readFile(reports[0]), alone) << "a run beside another must grade as a run alone";
  EXPECT_EQ(readFile(reports[1]), alone);
  EXPECT_DOUBLE_EQ(aula::testing::jsonNumber(alone, "pose_messages"), 45001.0) << alone;
}

// The mapping cleaner tells what it believes (api.belief): its own pose, in its own frame (its
// start at 0, 0), every period, and its map now and then. Recorded with the truth in one run's
// log, the two agree over the whole 900 s: the bar is 0.15 m at p95.
TEST(VacuumRun, TheMappingCleanersOwnPoseStaysNearTheTruthAllRun) {
  const std::string dir = aula::testing::privateDir();
  const std::string log = dir + "/run.log", recorded = dir + "/run.lcmlog";
  aula::process::ChildProcess run({std::string(AULA_BIN_DIR) + "/aula", "run", "vacuum", "--headless", "--algorithm=reference",
                                   "--seed=1", "--record=" + recorded, "--lcm-url=" + aula::testing::privateLcmUrl()},
                                  log, log);
  ASSERT_EQ(run.wait(200s).value_or(-1), 0) << readFile(log);
  // The truth at each belief's sim time (poses come at 50 Hz, beliefs after each 80 ms execute).
  std::map<int64_t, std::pair<double, double>> truth;
  std::vector<aula::belief_t> beliefs;
  lcm::LogFile in(recorded, "r");
  ASSERT_TRUE(in.good()) << recorded;
  for (const lcm::LogEvent* e = in.readNextEvent(); e != nullptr; e = in.readNextEvent()) {
    aula::pose3d_t pose{};
    aula::belief_t belief{};
    if (e->channel == "ROOMBA_POSE" && pose.decode(e->data, 0, e->datalen) > 0) truth[pose.utime] = {pose.x, pose.y};
    if (e->channel == "VACUUM_BELIEF" && belief.decode(e->data, 0, e->datalen) > 0) beliefs.push_back(belief);
  }
  ASSERT_GT(beliefs.size(), 10000u) << "a belief after each execute() of the 900 s";
  auto truthAt = [&](int64_t utime) { return std::prev(truth.upper_bound(utime))->second; };
  // Its frame is its start's: the first belief is put on the truth of its time.
  const auto start = truthAt(beliefs.front().utime);
  const double dx = start.first - beliefs.front().x_m, dy = start.second - beliefs.front().y_m;
  std::vector<double> errors_m;
  int maps = 0;
  for (const aula::belief_t& b : beliefs) {
    const auto [x, y] = truthAt(b.utime);
    errors_m.push_back(std::hypot(b.x_m + dx - x, b.y_m + dy - y));
    if (b.map_width > 0) {
      ++maps;
      EXPECT_EQ(b.map_cells_count, b.map_width * b.map_height);
    }
  }
  std::sort(errors_m.begin(), errors_m.end());
  const double p95_m = errors_m[errors_m.size() * 95 / 100], max_m = errors_m.back();
  std::cout << "mapping cleaner, vacuum.world seed 1: " << beliefs.size() << " beliefs, pose error p50 "
            << errors_m[errors_m.size() / 2] << " m, p95 " << p95_m << " m, max " << max_m << " m; " << maps << " maps\n";
  EXPECT_LE(p95_m, 0.15);
  EXPECT_GE(maps, 80) << "its map every 10 s of the 900 s";
  std::filesystem::remove_all(dir);
}
