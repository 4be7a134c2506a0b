// `aula run EXERCISE --headless --picture=FILE.png`: each referee writes its picture of the run
// beside the report (short runs, each on its own random LCM port), the same run gives the same
// bytes, and a picture path in a missing folder is refused at once (exit code 2, naming it).
#include "test_support.hpp"

#include <aula/autopark/parking_picture.hpp>
#include <aula/process/child_process.hpp>
#include <aula/referee/run_picture.hpp>
#include <aula/teletaxi/taxi_picture.hpp>
#include <aula/vacuum/coverage_picture.hpp>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

using namespace std::chrono_literals;
using aula::testing::readFile;

namespace {

std::string randomLcmUrl() {
  std::random_device device;
  const int port = std::uniform_int_distribution<int>(20000, 40000)(device);
  return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";
}

struct PictureRun {
  int code = -1;
  std::string log, report, picture_path;
};

PictureRun aulaRun(const std::string& exercise, const std::string& tag, const std::vector<std::string>& extra) {
  PictureRun run;
  run.picture_path = ::testing::TempDir() + "picture_" + tag + ".png";
  const std::string report = ::testing::TempDir() + "picture_" + tag + ".json";
  const std::string log = ::testing::TempDir() + "picture_" + tag + ".log";
  std::remove(run.picture_path.c_str());
  std::remove(report.c_str());
  std::vector<std::string> args{std::string(AULA_BIN_DIR) + "/aula", "run", exercise, "--headless",
                                "--picture=" + run.picture_path, "--report=" + report, "--lcm-url=" + randomLcmUrl()};
  args.insert(args.end(), extra.begin(), extra.end());
  aula::process::ChildProcess child(args, log, log);
  const auto code = child.wait(120s);
  EXPECT_TRUE(code.has_value()) << "the run did not end\n" << readFile(log);
  run.code = code.value_or(-1);
  run.log = readFile(log);
  run.report = readFile(report);
  return run;
}

int countColour(const cv::Mat& image, const cv::Scalar& colour) {
  cv::Mat mask;
  cv::inRange(image, colour, colour, mask);
  return cv::countNonZero(mask);
}

// The picture is there, a colour PNG about 800 px wide with a caption above the map.
cv::Mat loadPicture(const PictureRun& run) {
  const cv::Mat image = cv::imread(run.picture_path, cv::IMREAD_COLOR);
  EXPECT_FALSE(image.empty()) << run.picture_path << " is missing or not a PNG\n" << run.log;
  if (image.empty()) return image;
  EXPECT_GE(image.cols, 640);
  EXPECT_LE(image.cols, 800);
  EXPECT_GE(image.rows, 300);
  EXPECT_LE(image.rows, 800 + 250);
  return image;
}

}  // namespace

TEST(RefereePicture, VacuumShowsTheCleanedFloorAndTheSameRunGivesTheSameBytes) {
  const std::vector<std::string> args{"--algorithm=reference", "--seed=3", "--Vacuum.Referee.Duration=20"};
  const PictureRun a = aulaRun("vacuum", "vacuum_a", args);
  ASSERT_EQ(a.code, 0) << a.log;
  const cv::Mat image = loadPicture(a);
  ASSERT_FALSE(image.empty());
  // 20 s of a roomba: roughly 0.3 m/s x 20 s x 0.33 m, at (790 px / 10 m)^2 per m2.
  EXPECT_GT(countColour(image, aula::vacuum::kCleanedColour), 5000) << a.picture_path;
  EXPECT_GT(countColour(image, aula::referee::colour::kOrange), 100) << "the robot at the end";
  const PictureRun b = aulaRun("vacuum", "vacuum_b", args);
  ASSERT_EQ(b.code, 0) << b.log;
  EXPECT_EQ(readFile(a.picture_path), readFile(b.picture_path)) << "the same run must give a byte-identical picture";
}

TEST(RefereePicture, AutoparkShowsTheCarItsTrailAndTheSlot) {
  const PictureRun run = aulaRun("autopark", "autopark", {"--algorithm=reactive", "--seed=5", "--Autopark.Referee.Timeout=30"});
  ASSERT_EQ(run.code, 0) << run.log;
  const cv::Mat image = loadPicture(run);
  ASSERT_FALSE(image.empty());
  EXPECT_GT(countColour(image, aula::autopark::kTrailColour), 500) << run.picture_path;
  EXPECT_GT(countColour(image, aula::autopark::kCarColour), 300) << run.picture_path;  // its outline
  EXPECT_GT(countColour(image, aula::referee::colour::kGreen), 300) << "the ideal pose";
}

TEST(RefereePicture, TeleTaxiShowsThePathFromTheStartToTheDestination) {
  const PictureRun run = aulaRun("teletaxi", "teletaxi", {"--algorithm=reference", "--TeleTaxi.Referee.Timeout=20"});
  ASSERT_EQ(run.code, 0) << run.log;
  const cv::Mat image = loadPicture(run);
  ASSERT_FALSE(image.empty());
  // The default destination is about 130 m of streets away: a 3 px line of some 200 px.
  EXPECT_GT(countColour(image, aula::teletaxi::kTaxiPathColour), 400) << run.picture_path;
  EXPECT_GT(countColour(image, aula::referee::colour::kGreen), 100) << "the start";
  EXPECT_GT(countColour(image, aula::referee::colour::kRed), 100) << "the destination";
}

TEST(RefereePicture, APictureInAMissingFolderIsRefusedAtOnceNamingThePath) {
  const std::string bad = ::testing::TempDir() + "no_such_folder/run.png";
  const std::string log = ::testing::TempDir() + "picture_bad.log";
  // The launcher refuses it before any process starts.
  aula::process::ChildProcess launcher({std::string(AULA_BIN_DIR) + "/aula", "run", "vacuum", "--headless",
                                        "--picture=" + bad, "--lcm-url=" + randomLcmUrl()},
                                       log, log);
  const auto code = launcher.wait(30s);
  ASSERT_TRUE(code.has_value());
  EXPECT_EQ(*code, 2) << readFile(log);
  EXPECT_NE(readFile(log).find("--picture=" + bad), std::string::npos) << readFile(log);
  EXPECT_EQ(readFile(log).find("aula-sim"), std::string::npos) << "nothing should have started\n" << readFile(log);
  // So does each referee on its own, before it joins the run.
  for (const char* referee : {"vacuum-cleaner-referee", "teletaxi-referee", "autopark-referee"}) {
    aula::process::ChildProcess alone({std::string(AULA_BIN_DIR) + "/" + referee, "--headless", "--picture=" + bad,
                                       "--lcm-url=" + randomLcmUrl()},
                                      log, log);
    const auto referee_code = alone.wait(30s);
    ASSERT_TRUE(referee_code.has_value()) << referee;
    EXPECT_EQ(*referee_code, 2) << referee << "\n" << readFile(log);
    EXPECT_NE(readFile(log).find("no_such_folder' does not exist"), std::string::npos) << referee << "\n" << readFile(log);
  }
}
