#include <aula/referee/report.hpp>
#include <aula/teletaxi/taxi_grade.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

using aula::teletaxi::gradeTaxi;
using aula::teletaxi::TaxiGradeInput;

namespace {
TaxiGradeInput arrived(double distance_m, double path_m = 260.0, double time_s = 100.0) {
  TaxiGradeInput in;
  in.final_distance_m = distance_m;
  in.path_length_m = path_m;
  in.driving_time_s = time_s;
  in.stopped = true;
  return in;
}
}  // namespace

TEST(TaxiGrade, BaseMarkEdgesAtTwoFourAndFiveMetres) {
  EXPECT_DOUBLE_EQ(gradeTaxi(arrived(0.0)).base_mark, 8.0);
  EXPECT_DOUBLE_EQ(gradeTaxi(arrived(2.0)).base_mark, 8.0);
  EXPECT_DOUBLE_EQ(gradeTaxi(arrived(2.0001)).base_mark, 7.5);
  EXPECT_DOUBLE_EQ(gradeTaxi(arrived(4.0)).base_mark, 7.5);
  EXPECT_DOUBLE_EQ(gradeTaxi(arrived(4.0001)).base_mark, 7.0);
  EXPECT_DOUBLE_EQ(gradeTaxi(arrived(5.0)).base_mark, 7.0);
  EXPECT_TRUE(gradeTaxi(arrived(5.0)).reached);
  EXPECT_FALSE(gradeTaxi(arrived(5.0001)).reached);
  EXPECT_DOUBLE_EQ(gradeTaxi(arrived(5.0001)).mark, 0.0);
}

TEST(TaxiGrade, SpeedAlongThePathAddsUpToTwoPoints) {
  // 260 m in 100 s = 2.6 m/s: full speed mark.
  auto g = gradeTaxi(arrived(1.0, 260.0, 100.0));
  EXPECT_NEAR(g.average_speed_mps, 2.6, 1e-12);
  EXPECT_NEAR(g.speed_mark, 10.0, 1e-12);
  EXPECT_NEAR(g.mark, 10.0, 1e-12);
  // 1.3 m/s: half the speed mark, one point.
  g = gradeTaxi(arrived(1.0, 130.0, 100.0));
  EXPECT_NEAR(g.mark, 9.0, 1e-12);
  // Faster than the reference: capped.
  g = gradeTaxi(arrived(4.5, 1000.0, 100.0));
  EXPECT_NEAR(g.speed_mark, 10.0, 1e-12);
  EXPECT_NEAR(g.mark, 9.0, 1e-12);
}

TEST(TaxiGrade, TimeoutAndMovingAreNotReached) {
  auto in = arrived(1.0);
  in.timed_out = true;
  EXPECT_FALSE(gradeTaxi(in).reached);
  EXPECT_EQ(gradeTaxi(in).mark, 0.0);
  EXPECT_NE(gradeTaxi(in).verdict.find("timeout"), std::string::npos);
  in = arrived(1.0);
  in.stopped = false;  // passing through the destination is not arriving
  EXPECT_FALSE(gradeTaxi(in).reached);
}

TEST(TaxiGrade, NoDivisionByZero) {
  const auto g = gradeTaxi(arrived(0.5, 0.0, 0.0));  // destination at the start, GO! and stop
  EXPECT_TRUE(std::isfinite(g.mark));
  EXPECT_DOUBLE_EQ(g.average_speed_mps, 0.0);
  EXPECT_DOUBLE_EQ(g.mark, 0.0);  // it never drove: no distance mark
  EXPECT_NE(g.verdict.find("without driving"), std::string::npos) << g.verdict;
  auto in = arrived(NAN);
  EXPECT_FALSE(gradeTaxi(in).reached);
}

TEST(Report, JsonIsOrderedFixedFormatAndAtomic) {
  aula::referee::Report r;
  r.set("exercise", "teletaxi");
  r.set("mark", 9.25);
  r.set("seed", 3LL);
  r.set("reached", true);
  r.set("per_100s", std::vector<double>{1.0, 2.5});
  r.set("mark", 9.5);  // replaced in place
  r.set("nan", NAN);
  EXPECT_EQ(r.toJson(),
            "{\n  \"exercise\": \"teletaxi\",\n  \"mark\": 9.5,\n  \"seed\": 3,\n"
            "  \"reached\": true,\n  \"per_100s\": [1.0, 2.5],\n  \"nan\": null\n}\n");
  const std::string path = ::testing::TempDir() + "aula_report_test.json";
  r.writeAtomically(path);
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(), r.toJson());
  EXPECT_THROW(r.writeAtomically("/nonexistent/dir/report.json"), std::runtime_error);
}

TEST(Report, NestedObjectsAndListsOfNamesIndentWithTheirDepth) {
  aula::referee::Report inner, deeper;
  deeper.set("x", 1.0);
  inner.set("preset", "default");
  inner.set("bands", std::vector<double>{1.0, 1.5});
  inner.set("deeper", deeper);
  aula::referee::Report r;
  r.set("mark", 7.0);
  r.set("rubric", inner);
  r.set("measures", std::vector<std::string>{"a", "b\"c"});
  EXPECT_EQ(r.toJson(),
            "{\n  \"mark\": 7.0,\n  \"rubric\": {\n    \"preset\": \"default\",\n    \"bands\": [1.0, 1.5],\n"
            "    \"deeper\": {\n      \"x\": 1.0\n    }\n  },\n  \"measures\": [\"a\", \"b\\\"c\"]\n}\n");
}
