// The whole TeleTaxi exercise, headless in lockstep: `aula run teletaxi` starts the simulator,
// the component with the reference solution and the referee as real processes.
#include "test_support.hpp"

#include <aula/process/child_process.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

using namespace std::chrono_literals;
using aula::testing::readFile;

namespace {



// Runs one episode; returns the report text.
std::string runTaxi(const std::string& destination, const std::string& tag) {
  const std::string report = ::testing::TempDir() + "teletaxi_" + tag + ".json";
  const std::string log = ::testing::TempDir() + "teletaxi_" + tag + ".log";
  std::remove(report.c_str());
  aula::process::ChildProcess run({std::string(AULA_BIN_DIR) + "/aula", "run", "teletaxi", "--headless",
                                   "--algorithm=reference", "--TeleTaxi.Destination=" + destination,
                                   "--report=" + report, "--lcm-url=" + aula::testing::privateLcmUrl()},
                                  log, log);
  const auto code = run.wait(90s);
  EXPECT_TRUE(code.has_value()) << "the run did not end\n" << readFile(log);
  EXPECT_EQ(code.value_or(-1), 0) << readFile(log);
  const std::string json = readFile(report);
  EXPECT_FALSE(json.empty()) << readFile(log);
  return json;
}

}  // namespace

class TeleTaxiReference : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(TeleTaxiReference, ReachesTheDestinationWithAMarkOfAtLeastNine) {
  const std::string json = runTaxi(GetParam().second, GetParam().first);
  EXPECT_NE(json.find("\"reached\": true"), std::string::npos) << json;
  EXPECT_GE(aula::testing::jsonNumber(json, "mark"), 9.0) << json;
  EXPECT_LE(aula::testing::jsonNumber(json, "final_distance_m"), 2.0) << json;
  EXPECT_EQ(aula::testing::jsonNumber(json, "bumps"), 0.0) << "the taxi touched a wall\n" << json;
  EXPECT_NE(json.find("\"exercise\": \"teletaxi\""), std::string::npos);
  EXPECT_NE(json.find("\"algorithm\": \"reference\""), std::string::npos);
  EXPECT_NE(json.find("\"world\": \"cityLarge.world\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"world_sha256\": \""), std::string::npos) << json;
}

INSTANTIATE_TEST_SUITE_P(Destinations, TeleTaxiReference,
                         ::testing::Values(std::make_pair("far", "220,240"),
                                           std::make_pair("plaza", "-40,40"),
                                           std::make_pair("medium", "120,-40")),
                         [](const auto& info) { return std::string(info.param.first); });

TEST(TeleTaxiRun, TheSameRunTwiceGivesByteIdenticalReports) {
  const std::string first = runTaxi("120,-40", "repeat_a");
  const std::string second = runTaxi("120,-40", "repeat_b");
  EXPECT_FALSE(first.empty());
  EXPECT_EQ(first, second);
}
