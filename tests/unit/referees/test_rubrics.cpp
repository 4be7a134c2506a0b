// The referees' rubric presets, resolved from the shipped settings tables as a referee process
// resolves them, on hand-made measurements: the default preset separates good from bad, the
// original keeps the thesis's scales, and an explicit value wins over either.
#include <aula/autopark/parking_referee.hpp>
#include <aula/config/config.hpp>
#include <aula/referee/rubric.hpp>
#include <aula/scoring/parking_geometry.hpp>
#include <aula/settings/tables.hpp>
#include <aula/teletaxi/taxi_referee.hpp>
#include <aula/vacuum/coverage_referee.hpp>

#include <gtest/gtest.h>

using aula::config::Config;

namespace {

// The referee's effective settings with `Rubric = preset` and any more `KEY = value` lines.
Config effective(const std::string& program, const std::string& rubric_key, const std::string& preset,
                 const std::string& more = "") {
  const Config cfg = Config::fromString(rubric_key + " = " + preset + "\n" + more, "test.cfg");
  return aula::settings::tableOf(program).resolve(cfg);
}

Config vacuum(const std::string& preset, const std::string& more = "") {
  return effective("vacuum-cleaner-referee", "Vacuum.Referee.Rubric", preset, more);
}

double vacuumMark(const Config& cfg, double coverage_percent) {
  const auto s = aula::vacuum::coverageSettings(cfg);
  return aula::vacuum::coverageMark(coverage_percent, s.half_mark_coverage_percent, s.full_mark_coverage_percent);
}

// A street like the shipped one (cars 4.5 m long at y = -3, the curb face at y = -4.25) with a
// slot of `slot_m` for a 4 x 2 m car, the rear car's end at x = 2.75.
aula::autopark::ParkingScene street(double slot_m) {
  aula::autopark::ParkingScene s;
  s.rear_car = {{0.5, -3, 0}, 4.5, 1.8};
  s.front_car = {{2.75 + slot_m + 2.25, -3, 0}, 4.5, 1.8};
  s.curb_y_m = -4.25;
  s.ideal_x_m = 2.75 + slot_m / 2;
  s.ideal_y_m = -3;
  s.car_length_m = 4;
  s.car_width_m = 2;
  return s;
}

// Parked in 60 s with no collision, the car's centre `offset_m` ahead of the slot's centre.
double parkingMark(const std::string& preset, double slot_m, double offset_m = 0) {
  const auto settings = aula::autopark::parkingRefereeSettings(effective("autopark-referee", "Autopark.Referee.Rubric", preset));
  const auto scene = street(slot_m);
  const auto m = aula::autopark::measureParking(scene, scene.ideal_x_m + offset_m, -3, 0);
  return aula::autopark::scoreParking(m, true, 60, 0, settings).mark;
}

}  // namespace

// Measured on the shipped house, 900 s, seeds 1-20 (bench/vacuum_runs.sh): the random-bounce
// baseline's median coverage 38.9 % (40.6 % over seeds 11-20 alone), its best 55.9 %; the
// reference's median 65.9 %, p10 59.8 %, worst 57.1 %.
TEST(VacuumRubric, TheDefaultSeparatesTheBaselineFromTheReference) {
  const Config cfg = vacuum("default");
  EXPECT_LE(vacuumMark(cfg, 38.9), 6.0);
  EXPECT_LE(vacuumMark(cfg, 40.6), 6.0);
  EXPECT_GE(vacuumMark(cfg, 65.9), 9.0);
  EXPECT_GE(vacuumMark(cfg, 59.8), 9.0);
  EXPECT_DOUBLE_EQ(vacuumMark(cfg, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(vacuumMark(cfg, 40.0), 5.0);
  EXPECT_DOUBLE_EQ(vacuumMark(cfg, 60.0), 10.0);
}

TEST(VacuumRubric, TheOriginalIsTheThesisLinearScale) {
  const Config cfg = vacuum("original");
  for (double coverage : {0.0, 7.5, 15.0, 22.5, 29.9}) EXPECT_NEAR(vacuumMark(cfg, coverage), coverage * 10 / 30, 1e-12) << coverage;
  EXPECT_DOUBLE_EQ(vacuumMark(cfg, 38.9), 10.0);  // the baseline: a 10, the bug this preset keeps
}

TEST(VacuumRubric, AnExplicitValueWinsOverThePresetAndTheReportSaysSo) {
  const Config cfg = vacuum("original", "Vacuum.Referee.FullMarkCoverage = 50\n");
  EXPECT_DOUBLE_EQ(vacuumMark(cfg, 15.0), 5.0);   // the preset's half mark
  EXPECT_DOUBLE_EQ(vacuumMark(cfg, 50.0), 10.0);  // the file's full mark
  const auto rubric = aula::referee::rubricReport(cfg, aula::settings::tableOf("vacuum-cleaner-referee"), "Vacuum.Referee.Rubric");
  EXPECT_EQ(rubric.raw("preset"), "\"original\"");
  EXPECT_EQ(rubric.raw("Vacuum.Referee.HalfMarkCoverage"), "15.0");
  EXPECT_EQ(rubric.raw("Vacuum.Referee.FullMarkCoverage"), "50.0");
  EXPECT_EQ(rubric.raw("overridden"), "[\"Vacuum.Referee.FullMarkCoverage\"]");
  EXPECT_EQ(aula::referee::rubricReport(vacuum("default"), aula::settings::tableOf("vacuum-cleaner-referee"),
                                        "Vacuum.Referee.Rubric").raw("overridden"), "");
}

TEST(VacuumRubric, AHalfMarkAboveTheFullMarkIsRefusedNamingBoth) {
  try {
    aula::vacuum::coverageSettings(vacuum("default", "Vacuum.Referee.HalfMarkCoverage = 70\n"));
    FAIL() << "accepted";
  } catch (const aula::config::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Vacuum.Referee.FullMarkCoverage = 60 % must be above Vacuum.Referee.HalfMarkCoverage = 70 % (test.cfg:2)"),
              std::string::npos) << what;
  }
}

TEST(AutoparkRubric, ACentredCarGetsTenWithTheDefaultInAnySlotAndTheOriginalsMarksInShortOnes) {
  const double length_m = 4.0;
  EXPECT_DOUBLE_EQ(parkingMark("default", 1.3 * length_m), 10.0);
  EXPECT_NEAR(parkingMark("original", 1.3 * length_m), 8.33, 0.005);   // both gaps under 1 m: D = 33.3
  EXPECT_NEAR(parkingMark("original", 1.6 * length_m), 9.17, 0.005);   // both 1.2 m: half marks
  EXPECT_DOUBLE_EQ(parkingMark("original", 2.25 * length_m), 10.0);    // the shipped slot: 2.5 m each
  for (double k : {1.2, 1.25, 1.4, 1.6, 2.25, 3.0}) EXPECT_DOUBLE_EQ(parkingMark("default", k * length_m), 10.0) << k;
}

TEST(AutoparkRubric, TheDefaultsToleranceIsHalfTheCentredGap) {
  // A 1.3 L slot: 0.6 m each side when centred. 0.3 m off centre still has 0.3 m (50 %) on the
  // near side; 0.4 m off has 0.2 m (33 %): half marks there, D = (50 + 100 + 100) / 3.
  EXPECT_DOUBLE_EQ(parkingMark("default", 5.2, 0.3), 10.0);
  EXPECT_NEAR(parkingMark("default", 5.2, 0.4), 0.025 * (300 + 250.0 / 3), 1e-9);
  EXPECT_NEAR(parkingMark("default", 5.2, -0.5), 0.025 * (300 + 200.0 / 3), 1e-9);  // 0.1 m: nothing
}

TEST(TeleTaxiRubric, ATaxiThatNeverDroveGetsNoDistanceMarkUnlessTheOriginal) {
  aula::teletaxi::TaxiGradeInput stood;  // the destination beside the start: GO!, and stop
  stood.final_distance_m = 1.5;
  stood.path_length_m = 0.3;
  stood.driving_time_s = 3;
  stood.stopped = true;
  const auto grade = [&](const std::string& preset) {
    const auto s = aula::teletaxi::taxiRefereeSettings(effective("teletaxi-referee", "TeleTaxi.Referee.Rubric", preset));
    return aula::teletaxi::gradeTaxi(stood, s.scale);
  };
  EXPECT_NEAR(grade("default").mark, 0.2 * 10 * 0.1 / 2.6, 1e-12);  // only the speed part: 0.1 m/s
  EXPECT_DOUBLE_EQ(grade("default").base_mark, 0.0);
  EXPECT_DOUBLE_EQ(grade("original").base_mark, 8.0);
  // A real trip is graded the same by both.
  stood.path_length_m = 260;
  stood.driving_time_s = 100;
  EXPECT_DOUBLE_EQ(grade("default").mark, 10.0);
  EXPECT_DOUBLE_EQ(grade("original").mark, 10.0);
}

TEST(Rubric, AValueEqualToThePresetsIsNotAnOverrideWhateverItsSpelling) {
  // A regrade hands the referee every recorded value explicitly: the same numbers, no override.
  const auto& table = aula::settings::tableOf("autopark-referee");
  const Config cfg = effective("autopark-referee", "Autopark.Referee.Rubric", "original",
                               "Autopark.Referee.FullMarkTime = 170.0\nAutopark.Referee.GapBands = 1, 1.50, 3.5\n");
  EXPECT_EQ(aula::referee::rubricReport(cfg, table, "Autopark.Referee.Rubric").raw("overridden"), "");
  EXPECT_EQ(aula::referee::rubricReport(cfg, table, "Autopark.Referee.Rubric").raw("Autopark.Referee.GapRule"), "\"absolute\"");
}
