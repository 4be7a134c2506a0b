// The trace's pieces on plain values: sampling on sim time, the delta and run-length encodings,
// and the vacuum's cleaned cells, decoded here as the player decodes them.
#include <aula/referee/run_trace.hpp>
#include <aula/scoring/coverage_grid.hpp>
#include <aula/vacuum/cleaned_cells_trace.hpp>

#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <utility>

using aula::referee::RunTrace;

TEST(RunTrace, SamplesTheLatestPoseAtEachPeriodOfSimTime) {
  RunTrace trace(0.1);
  trace.onPose(0, 9, 9, 0);  // before the start: not traced
  EXPECT_EQ(trace.samples(), 0u);
  trace.start(1'000'000);
  // 50 Hz from the start, x = 1 mm per pose; the poses at 0.16 s and 0.2 s are lost.
  for (int i = 0; i <= 12; ++i) {
    if (i == 8 || i == 10) continue;
    trace.onPose(1'000'000 + i * 20'000, i * 0.001, -i * 0.002, i * 0.01);
  }
  ASSERT_EQ(trace.samples(), 3u);  // 0, 0.1, 0.2 s
  aula::referee::Report out;
  trace.addTo(out);
  const std::string samples = out.raw("samples");
  // x at 0 s: 0 mm; 0.1 s: 5 mm; 0.2 s: the latest before it (0.18 s, 9 mm). Delta-encoded.
  EXPECT_NE(samples.find("\"x_mm\": [0,5,4]"), std::string::npos) << samples;
  EXPECT_NE(samples.find("\"y_mm\": [0,-10,-8]"), std::string::npos) << samples;
  EXPECT_NE(samples.find("\"yaw_mrad\": [0,50,40]"), std::string::npos) << samples;
  trace.stop(0);
  trace.onPose(2'000'000, 1, 1, 0);
  EXPECT_EQ(trace.samples(), 3u) << "nothing after the end of the graded episode";
  const auto& e = trace.addEvent(1'150'000, "bump", "bump 1", "none");
  EXPECT_DOUBLE_EQ(e.t_s, 0.15);
  EXPECT_TRUE(e.placed);
  EXPECT_DOUBLE_EQ(e.x_m, 0.012);
}

TEST(RunTrace, MapIsRunLengthEncodedRowByRowStartingWithFree) {
  cv::Mat map(2, 4, CV_8UC1, cv::Scalar(255));
  map.at<uint8_t>(0, 0) = 0;
  map.at<uint8_t>(1, 2) = 0;
  map.at<uint8_t>(1, 3) = 0;
  aula::geometry::MapTransform t;
  t.resolution_m = 0.5;
  const std::string json = aula::referee::traceMap(map, t).raw("rle");
  EXPECT_EQ(json, "[0,1,5,2]");
  EXPECT_EQ(aula::referee::deltaArray({5, 7, 6}), "[5,2,-1]");
  EXPECT_EQ(aula::referee::milli(-0.0015), -2);
}

namespace {

// The player's decoding of the cells string: per sample, the cells listed.
std::vector<std::vector<std::pair<int, int>>> decodeCells(const std::string& text) {
  auto digit = [](char c) { return static_cast<int>(std::strchr(aula::vacuum::kCellDigits, c) - aula::vacuum::kCellDigits); };
  std::vector<std::vector<std::pair<int, int>>> samples(1);
  int col = 0, row = 0;
  for (size_t i = 0; i < text.size();) {
    if (text[i] == ' ') {
      samples.emplace_back();
      ++i;
    } else if (text[i] == '~') {
      col = (digit(text[i + 1]) * 62 + digit(text[i + 2])) * 62 + digit(text[i + 3]);
      row = (digit(text[i + 4]) * 62 + digit(text[i + 5])) * 62 + digit(text[i + 6]);
      samples.back().emplace_back(col, row);
      i += 7;
    } else {
      col += digit(text[i]) - 31;
      row += digit(text[i + 1]) - 31;
      samples.back().emplace_back(col, row);
      i += 2;
    }
  }
  return samples;
}

}  // namespace

TEST(CleanedCellsTrace, ListsEachCellOnceWhenHalfItsFloorIsCleaned) {
  // A 10 x 6 m room at 2 cm, walls 10 cm thick.
  cv::Mat map(300, 500, CV_8UC1, cv::Scalar(255));
  cv::rectangle(map, cv::Rect(0, 0, 500, 300), cv::Scalar(0), 10);
  aula::geometry::MapTransform t;
  t.resolution_m = 0.02;
  t.origin_x_m = 0;
  t.origin_y_m = 6;
  t.width_px = 500;
  t.height_px = 300;
  aula::vacuum::CoverageGrid grid(map, t, 5, 3);
  aula::vacuum::CleanedCellsTrace cells(grid, 0.165);
  EXPECT_EQ(cells.cellPx(), 3);
  auto paint = [&](double x, double y) {
    grid.markDisc(x, y, 0.165);
    cells.touched(x, y);
  };
  // Along a row, then a jump far away (the '~' form), then nothing new.
  for (int i = 0; i < 50; ++i) {
    paint(1 + i * 0.02, 3);
    if (i % 5 == 4) cells.sample();
  }
  paint(9, 5.5);
  cells.sample();
  paint(9, 5.5);
  cells.sample();
  const auto decoded = decodeCells(cells.cells());
  ASSERT_EQ(decoded.size(), cells.samples());
  EXPECT_TRUE(decoded.back().empty());
  EXPECT_NE(cells.cells().find('~'), std::string::npos);
  std::set<std::pair<int, int>> listed;
  for (const auto& sample : decoded) {
    for (const auto& cell : sample) EXPECT_TRUE(listed.insert(cell).second) << "listed twice";
  }
  EXPECT_EQ(static_cast<long long>(listed.size()), cells.cellsCleaned());
  // Exactly the cells with at least half their floor cleaned.
  std::set<std::pair<int, int>> expected;
  for (int row = 0; row < 100; ++row) {
    for (int col = 0; col < 167; ++col) {
      int floor = 0, clean = 0;
      for (int r = row * 3; r < std::min(300, row * 3 + 3); ++r) {
        for (int c = col * 3; c < std::min(500, col * 3 + 3); ++c) {
          floor += grid.floor().at<uint8_t>(r, c) != 0;
          clean += grid.cleaned().at<uint8_t>(r, c) != 0;
        }
      }
      if (floor > 0 && 2 * clean >= floor) expected.emplace(col, row);
    }
  }
  EXPECT_EQ(listed, expected);
  EXPECT_EQ(cells.coverageCentiPercent().back(), std::llround(grid.coveragePercent() * 100));
}
