// Sensor realism (issue 27): the `realistic` preset of Simulator.Noise.* is seeded (the same seed
// gives the same report byte for byte, and the noise does change the run), and each exercise's
// reference keeps its median mark over seeds 1-5 within 0.5 of its noiseless one: the exercises
// stay solvable with a 2D lidar's noise, lost beams and slipping wheels.
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace std::chrono_literals;
using aula::testing::jsonNumber;
using aula::testing::readFile;
using aula::testing::runToEnd;

namespace {

const std::string kAula = std::string(AULA_BIN_DIR) + "/aula";

// One headless run's report.
std::string report(const std::string& dir, const std::string& exercise, const std::string& algorithm, int seed,
                   const std::string& noise) {
  const std::string path = dir + "/" + exercise + "-" + noise + "-" + std::to_string(seed) + ".json";
  const auto run = runToEnd({kAula, "run", exercise, "--headless", "--algorithm=" + algorithm, "--seed=" + std::to_string(seed),
                             "--Simulator.Noise=" + noise, "--report=" + path, "--lcm-url=" + aula::testing::privateLcmUrl()},
                            180s);
  EXPECT_EQ(run.code.value_or(-1), 0) << run.output;
  return readFile(path);
}

}  // namespace

TEST(Noise, TheRealisticPresetIsSeededAndChangesTheRun) {
  const std::string dir = aula::testing::privateDir();
  const std::string first = report(dir, "vacuum", "reference", 3, "realistic");
  std::filesystem::create_directories(dir + "/again");
  const std::string again = report(dir + "/again", "vacuum", "reference", 3, "realistic");
  EXPECT_EQ(first, again) << "the same seed must give the same run";
  const std::string exact = report(dir, "vacuum", "reference", 3, "off");
  EXPECT_NE(jsonNumber(first, "coverage_percent"), jsonNumber(exact, "coverage_percent")) << "the noise changed nothing";
  std::filesystem::remove_all(dir);
}

class NoisyReference : public ::testing::TestWithParam<std::pair<std::string, std::string>> {};

// The median over seeds 1-5: a vacuum's coverage is chaotic (a centimetre of noise sends the
// robot another way, as another seed does: seed 2 of the shipped house covers 64.5 % exactly and
// 54.9 % with the noise), so it is the median mark that must hold, as a grade takes it.
TEST_P(NoisyReference, KeepsItsMedianMarkWithinHalfAPoint) {
  const auto& [exercise, algorithm] = GetParam();
  const std::string dir = aula::testing::privateDir();
  std::vector<double> exact, noisy;
  std::string seeds;
  for (int seed = 1; seed <= 5; ++seed) {
    exact.push_back(jsonNumber(report(dir, exercise, algorithm, seed, "off"), "mark"));
    noisy.push_back(jsonNumber(report(dir, exercise, algorithm, seed, "realistic"), "mark"));
    seeds += " seed " + std::to_string(seed) + ": " + std::to_string(exact.back()) + " -> " + std::to_string(noisy.back()) + ";";
  }
  std::sort(exact.begin(), exact.end());
  std::sort(noisy.begin(), noisy.end());
  EXPECT_LE(std::abs(noisy[2] - exact[2]), 0.5) << exercise << " " << algorithm << ": median " << exact[2]
                                                 << " without noise, " << noisy[2] << " with;" << seeds;
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Exercises, NoisyReference,
                         ::testing::Values(std::make_pair(std::string("vacuum"), std::string("reference")),
                                           std::make_pair(std::string("teletaxi"), std::string("reference")),
                                           std::make_pair(std::string("autopark"), std::string("reactive")),
                                           std::make_pair(std::string("autopark"), std::string("planner"))),
                         [](const auto& info) { return info.param.first + "_" + info.param.second; });
