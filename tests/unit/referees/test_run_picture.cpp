// The referees' pictures of a run (--picture), on plain data: the shared canvas (world -> pixel
// through the MapTransform, caption, atomic PNG), the bounded trail, and each exercise's picture.
#include <aula/autopark/parking_picture.hpp>
#include <aula/autopark/parking_referee.hpp>
#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>
#include <aula/referee/run_picture.hpp>
#include <aula/teletaxi/taxi_picture.hpp>
#include <aula/teletaxi/taxi_referee.hpp>
#include <aula/vacuum/coverage_picture.hpp>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

using aula::referee::PicturePoint;
using aula::referee::RunPicture;
using aula::referee::Trail;
namespace colour = aula::referee::colour;

namespace {

aula::geometry::MapTransform grid(double resolution_m, double left_x_m, double top_y_m, int width_px, int height_px) {
  return aula::geometry::MapTransform{resolution_m, left_x_m, top_y_m, width_px, height_px};
}

// 10 m x 5 m at 0.1 m/px, its top-left corner at world (-2, 3).
aula::geometry::MapTransform grid100x50() { return grid(0.1, -2, 3, 100, 50); }

cv::Vec3b bgr(const cv::Scalar& s) {
  return cv::Vec3b(static_cast<uchar>(s[0]), static_cast<uchar>(s[1]), static_cast<uchar>(s[2]));
}

int countColour(const cv::Mat& image, const cv::Scalar& colour) {
  cv::Mat mask;
  cv::inRange(image, colour, colour, mask);
  return cv::countNonZero(mask);
}

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST(RunPicture, ScalesTheMapToFitAndDrawsInWorldCoordinates) {
  const cv::Mat map(50, 100, CV_8UC1, cv::Scalar(255));
  RunPicture picture(map, grid100x50(), 800);
  ASSERT_EQ(picture.canvas().cols, 800);
  ASSERT_EQ(picture.canvas().rows, 400);
  EXPECT_DOUBLE_EQ(picture.transform().resolution_m, 0.1 / 8);
  // World (3, 0.5) is 5 m right of the left edge and 2.5 m below the top: the canvas centre.
  EXPECT_EQ(picture.pixel(3, 0.5), cv::Point(400, 200));
  picture.box({{3, 0.5, 0}, 1.0, 0.5}, colour::kRed, cv::FILLED);
  EXPECT_EQ(picture.canvas().at<cv::Vec3b>(200, 400), bgr(colour::kRed));
  EXPECT_EQ(picture.canvas().at<cv::Vec3b>(200, 400 + 60), bgr(colour::kWhite));  // 0.75 m right: outside
}

TEST(RunPicture, KeepsTheMapsObstaclesSharp) {
  cv::Mat map(50, 100, CV_8UC1, cv::Scalar(255));
  map.at<uchar>(10, 20) = 0;
  const RunPicture picture(RunPicture::occupancyInColour(map, colour::kBlack, colour::kWhite), grid100x50(), 800);
  EXPECT_EQ(countColour(picture.canvas(), colour::kBlack), 64);  // one map pixel = 8 x 8 canvas pixels
  EXPECT_EQ(picture.canvas().at<cv::Vec3b>(10 * 8 + 4, 20 * 8 + 4), bgr(colour::kBlack));
}

TEST(RunPicture, ComposePutsTheCaptionAboveTheMap) {
  const cv::Mat map(50, 100, CV_8UC1, cv::Scalar(255));
  RunPicture picture(map, grid100x50(), 400);
  picture.addLegend(colour::kOrange, "path");
  const cv::Mat out = picture.compose("Title: mark 7.00 / 10", {"one line", "another line"});
  ASSERT_EQ(out.cols, 640);  // at least the caption's width, the map centred
  const int caption_px = out.rows - picture.canvas().rows;
  EXPECT_GT(caption_px, 3 * 24);
  EXPECT_GT(countColour(out(cv::Rect(0, 0, out.cols, caption_px)), colour::kBlack), 100);  // the text
  EXPECT_GT(countColour(out(cv::Rect(0, 0, out.cols, caption_px)), colour::kOrange), 100);  // the swatch
  cv::Mat map_part = out(cv::Rect((640 - 400) / 2, caption_px, 400, 200));
  EXPECT_EQ(countColour(map_part, colour::kWhite), 400 * 200);
}

TEST(RunPicture, LongCaptionLinesWrap) {
  const cv::Mat map(50, 100, CV_8UC1, cv::Scalar(255));
  RunPicture picture(map, grid100x50(), 400);
  const int short_rows = picture.compose("T", {"short"}).rows;
  const int long_rows = picture.compose("T", {std::string(40, 'x') + " " + std::string(40, 'y') + " " + std::string(40, 'z')}).rows;
  EXPECT_GE(long_rows - short_rows, 2 * 24);
}

TEST(RunPicture, WritesAByteIdenticalPngAtomicallyAndNamesABadPath) {
  const cv::Mat map(50, 100, CV_8UC1, cv::Scalar(255));
  RunPicture picture(map, grid100x50(), 400);
  picture.polyline({{0, 0}, {5, 1}, {6, -1}}, colour::kOrange, 3);
  const cv::Mat image = picture.compose("T", {"line"});
  const std::string dir = ::testing::TempDir();
  aula::referee::writePngAtomically(image, dir + "pic_a.png");
  aula::referee::writePngAtomically(image, dir + "pic_b.png");
  EXPECT_EQ(fileBytes(dir + "pic_a.png"), fileBytes(dir + "pic_b.png"));
  const cv::Mat back = cv::imread(dir + "pic_a.png", cv::IMREAD_COLOR);
  ASSERT_EQ(back.size(), image.size());
  EXPECT_EQ(cv::norm(back, image, cv::NORM_INF), 0.0);
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename().string().find("pic_a.png.tmp"), std::string::npos) << "a temporary file was left";
  }
  try {
    aula::referee::writePngAtomically(image, dir + "no_such_folder/pic.png");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_folder/pic.png"), std::string::npos) << e.what();
  }
}

TEST(OutputFolder, AMissingOrUnwritableFolderIsAConfigErrorNamingThePath) {
  EXPECT_NO_THROW(aula::config::requireWritableFolder(::testing::TempDir() + "fine.png", "--picture"));
  EXPECT_NO_THROW(aula::config::requireWritableFolder("relative.png", "--picture"));  // the current folder
  try {
    aula::config::requireWritableFolder("/no/such/folder/run.png", "--picture=/no/such/folder/run.png");
    FAIL() << "expected an error";
  } catch (const aula::config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("--picture=/no/such/folder/run.png"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'/no/such/folder' does not exist"), std::string::npos) << e.what();
  }
  EXPECT_THROW(aula::config::requireWritableFolder(::testing::TempDir(), "--picture"), aula::config::ConfigError);
  EXPECT_THROW(aula::config::requireWritableFolder("", "--picture"), aula::config::ConfigError);
}

TEST(Trail, KeepsAPointOnlyWhenItMovedFarEnough) {
  Trail trail(0.25);
  for (int i = 0; i <= 64; ++i) trail.add(i / 64.0, 0);  // 1 m in steps a double holds exactly
  ASSERT_EQ(trail.points().size(), 5u);                // 0, 0.25, 0.5, 0.75, 1.0
  EXPECT_NEAR(trail.points()[4].x_m, 1.0, 1e-9);
  trail.add(1.0, 0.1);  // too close to the last kept point
  EXPECT_EQ(trail.points().size(), 5u);
}

TEST(TaxiReferee, KeepsThePathFromGoOnlyAndBounded) {
  aula::teletaxi::TaxiReferee r({});
  r.setGoal(100, 0);
  r.onPose(0, -5, 0, 0);  // before GO!: not part of the path
  r.onPose(20'000, -4, 0, 0);
  r.start(40'000);
  for (int i = 1; i <= 640; ++i) r.onPose(40'000 + i * 20'000, -4 + i / 64.0, 0, 0);  // 10 m at 1/64 m a pose
  const auto& path = r.trail().points();
  ASSERT_FALSE(path.empty());
  EXPECT_DOUBLE_EQ(path.front().x_m, -4);  // where the taxi stood at GO!
  EXPECT_EQ(path.size(), 41u);             // one point per 25 cm
  EXPECT_NEAR(path.back().x_m, 6, 1e-9);
}

TEST(ParkingReferee, KeepsTheCarsTrailUntilTheEnd) {
  aula::autopark::ParkingScene scene;
  scene.rear_car = {{0.5, -3, 0}, 4.5, 1.8};
  scene.front_car = {{14, -3, 0}, 4.5, 1.8};
  scene.curb_y_m = -4.25;
  scene.ideal_x_m = 7.25;
  scene.ideal_y_m = -3;
  aula::autopark::ParkingReferee r(scene, {});
  r.start(0);
  for (int i = 0; i <= 160; ++i) r.onPose(i * 20'000, i / 32.0, 2.5, 0);  // 5 m
  EXPECT_EQ(r.trail().points().size(), 41u);  // a point per 4 poses: 12.5 cm, the first step past 10 cm
}

TEST(CoveragePicture, ShowsTheCleanedFloorWallsAndTheRobot) {
  // A 2 m x 1 m room at 2 cm/px with a wall column in the middle of its right half.
  const aula::geometry::MapTransform t = grid(0.02, 0, 1, 100, 50);
  cv::Mat map(50, 100, CV_8UC1, cv::Scalar(255));
  map(cv::Rect(70, 0, 5, 50)).setTo(0);
  aula::vacuum::CoverageGrid grid(map, t, 0.3, 0.5);
  grid.markDisc(0.3, 0.5, 0.165);
  aula::vacuum::CoverageRunSummary run;
  run.mark = 1.5;
  run.coverage_percent = grid.coveragePercent();
  run.have_pose = true;
  run.x_m = 1.0;
  run.y_m = 0.5;
  const cv::Mat a = aula::vacuum::coveragePicture(map, grid, run);
  const cv::Mat b = aula::vacuum::coveragePicture(map, grid, run);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0) << "the same run, the same picture";
  // The cleaned disc: about pi * 0.165^2 m2 at (800 / 100)^2 canvas px per map px.
  const double expected_px = M_PI * 0.165 * 0.165 / (0.02 * 0.02) * 64;
  EXPECT_NEAR(countColour(a, aula::vacuum::kCleanedColour), expected_px, 0.15 * expected_px);
  EXPECT_GE(countColour(a, colour::kBlack), 5 * 50 * 64);               // the wall (and the text)
  EXPECT_GT(countColour(a, aula::vacuum::kNotFloorColour), 20 * 50 * 64);  // right of the wall: not reachable
  EXPECT_GT(countColour(a, colour::kOrange), 500);                        // the robot at the end
}

TEST(TaxiPicture, DrawsThePathTheStartAndTheDestination) {
  const aula::geometry::MapTransform t = grid(1.0, -50, 50, 100, 100);
  cv::Mat city(100, 100, CV_8UC1, cv::Scalar(255));
  city(cv::Rect(10, 10, 30, 30)).setTo(0);
  aula::teletaxi::TaxiRunSummary run;
  run.have_goal = true;
  run.goal_x_m = 30;
  run.goal_y_m = 30;
  run.have_pose = true;
  run.x_m = 29;
  run.y_m = 29;
  run.path = {{-30, -30}, {30, -30}, {30, 29}};
  run.grade.mark = 9.2;
  run.grade.reached = true;
  run.finished = true;
  const cv::Mat picture = aula::teletaxi::taxiPicture(city, t, run);
  EXPECT_GT(countColour(picture, aula::teletaxi::kTaxiPathColour), 2 * 110 * 8);  // ~110 m of 3 px line at 8 px/m
  EXPECT_GT(countColour(picture, colour::kGreen), 100);                          // the start
  EXPECT_GT(countColour(picture, colour::kRed), 100);                            // the destination
  run.path.clear();
  EXPECT_LT(countColour(aula::teletaxi::taxiPicture(city, t, run), aula::teletaxi::kTaxiPathColour), 200)
      << "no path, only the legend's swatch";
}

TEST(ParkingPicture, TheViewHoldsTheSlotAndTheTrailAndTheGapsAreColouredByScore) {
  aula::autopark::ParkingRunSummary run;
  auto& s = run.scene;
  s.rear_car = {{0.5, -3, 0}, 4.5, 1.8};
  s.front_car = {{14, -3, 0}, 4.5, 1.8};
  s.curb_y_m = -4.25;
  s.ideal_x_m = 7.25;
  s.ideal_y_m = -3;
  run.have_pose = true;
  run.x_m = 7.25;
  run.y_m = -3;
  run.trail = {{-7, 2.5}, {10, 2.5}, {7.25, -3}};
  run.measures = aula::autopark::measureParking(s, run.x_m, run.y_m, 0);
  ASSERT_TRUE(run.measures.inside_slot);
  const aula::geometry::MapTransform view = aula::autopark::parkingView(run);
  EXPECT_EQ(view.width_px, 800);
  EXPECT_LT(view.origin_x_m, -7 - 2);                          // the trail's start and the car around it
  EXPECT_GT(view.origin_x_m + 800 * view.resolution_m, 14 + 2.25);  // the car in front
  EXPECT_LT(view.origin_y_m - view.height_px * view.resolution_m, s.curb_y_m);  // the curb
  const cv::Mat street(view.height_px, view.width_px, CV_8UC1, cv::Scalar(255));
  const cv::Mat good = aula::autopark::parkingPicture(street, view, run);
  const int green = countColour(good, colour::kGreen);
  // Full marks for both gaps (2.5 m) and the curb (0.35 m): green lines and labels, no red.
  EXPECT_EQ(countColour(good, colour::kRed), 0);
  // The same car 2 m from the curb: the curb gap scores nothing, in red.
  run.y_m = -1.0;
  run.measures = aula::autopark::measureParking(s, run.x_m, run.y_m, 0);
  run.measures.inside_slot = true;  // graded anyway, to see the colour
  const cv::Mat bad = aula::autopark::parkingPicture(street, view, run);
  EXPECT_GT(countColour(bad, colour::kRed), 50);
  EXPECT_LT(countColour(bad, colour::kGreen), green);
  EXPECT_GT(countColour(good, aula::autopark::kTrailColour), 500);
}
