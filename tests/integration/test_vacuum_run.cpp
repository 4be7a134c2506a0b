// The vacuum cleaner exercise, headless in lockstep: `aula run vacuum` with the reference
// solution for the full 900 s of sim time (about 4 s wall each). The figures over many seeds
// are in docs/performance.md, from bench/vacuum_runs.sh.
#include "test_support.hpp"

#include <aula/process/child_process.hpp>

#include <gtest/gtest.h>

#include <fstream>
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
