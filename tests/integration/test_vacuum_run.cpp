// The vacuum cleaner exercise, headless in lockstep: `aula run vacuum` with the reference
// solution, shortened to 120 s of sim time to keep CI quick (the 900 s figures are in
// docs/performance.md, from bench/vacuum_runs.sh).
#include "test_support.hpp"

#include <aula/process/child_process.hpp>

#include <gtest/gtest.h>

#include <fstream>
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
                                   "--Vacuum.Referee.Duration=120", "--report=" + report,
                                   "--lcm-url=" + aula::testing::privateLcmUrl()},
                                  log, log);
  const auto code = run.wait(90s);
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
  EXPECT_DOUBLE_EQ(aula::testing::jsonNumber(a, "sim_time_s"), 120.0) << a;
  EXPECT_GT(aula::testing::jsonNumber(a, "coverage_percent"), 10.0) << "the reference cleans in 120 s\n" << a;
  EXPECT_NE(a.find("\"coverage_per_100s\": ["), std::string::npos) << a;
}
