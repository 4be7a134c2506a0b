// Declared settings: unknown keys, wrong types and out-of-range values are errors that name
// the file and line (or the command-line argument); defaults come from the table alone.
#include <aula/config/settings.hpp>

#include <gtest/gtest.h>

using aula::config::Config;
using aula::config::ConfigError;
using aula::config::SettingsTable;

namespace {

SettingsTable table() {
  SettingsTable t("vacuum-cleaner");
  t.real("Vacuum.MaxV", 0.5, "m/s", 0, 2, "speed limit", true);
  t.integer("Vacuum.Retries", 3, "", 0, 10, "retries");
  t.flag("Vacuum.Autostart", false, "start at once");
  t.choice("Vacuum.Algorithm", "student", {"student", "reference"}, "which algorithm");
  t.reals("Vacuum.Destination", "1, 2", 2, "m", -100, 100, "x, y");
  return t;
}

std::string errorOf(const SettingsTable& t, const Config& cfg, const std::vector<const SettingsTable*>& siblings = {}) {
  try {
    t.resolve(cfg, siblings);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(Settings, DefaultsComeFromTheTableAndSayWhereTheyCameFrom) {
  const Config effective = table().resolve(Config::fromString("Vacuum.MaxV = 1.5\n", "v.cfg"));
  EXPECT_DOUBLE_EQ(effective.getDouble("Vacuum.MaxV"), 1.5);
  EXPECT_EQ(effective.origin("Vacuum.MaxV"), "v.cfg:1");
  EXPECT_EQ(effective.getInt("Vacuum.Retries"), 3);
  EXPECT_EQ(effective.origin("Vacuum.Retries"), "default");
  EXPECT_FALSE(effective.getBool("Vacuum.Autostart"));
  EXPECT_EQ(effective.getDoubleList("Vacuum.Destination"), (std::vector<double>{1, 2}));
}

TEST(Settings, AnUnknownKeyInAFileNamesFileLineAndTheNearestKey) {
  const auto cfg = Config::fromString("# comment\nVacuum.MaxVV = 9\n", "config/vacuumCleaner.cfg");
  EXPECT_EQ(errorOf(table(), cfg),
            "config/vacuumCleaner.cfg:2: unknown key 'Vacuum.MaxVV' (did you mean 'Vacuum.MaxV'?); "
            "`vacuum-cleaner --help` lists the settings");
}

TEST(Settings, AnUnknownKeyOnTheCommandLineNamesTheArgument) {
  Config cfg;
  cfg.set("Vacuum.Autostrat", "true", "command line --Vacuum.Autostrat");
  EXPECT_EQ(errorOf(table(), cfg),
            "command line --Vacuum.Autostrat: unknown key 'Vacuum.Autostrat' (did you mean 'Vacuum.Autostart'?); "
            "`vacuum-cleaner --help` lists the settings");
  cfg = Config();
  cfg.set("Totally.Different", "1", "command line --Totally.Different");
  EXPECT_EQ(errorOf(table(), cfg),
            "command line --Totally.Different: unknown key 'Totally.Different'; `vacuum-cleaner --help` lists the settings");
}

TEST(Settings, WrongTypesAreNamed) {
  EXPECT_EQ(errorOf(table(), Config::fromString("Vacuum.MaxV = fast\n", "v.cfg")),
            "v.cfg:1: Vacuum.MaxV = 'fast': not a finite number");
  EXPECT_EQ(errorOf(table(), Config::fromString("Vacuum.Retries = 2.5\n", "v.cfg")),
            "v.cfg:1: Vacuum.Retries = '2.5': not an integer");
  EXPECT_EQ(errorOf(table(), Config::fromString("Vacuum.Autostart = maybe\n", "v.cfg")),
            "v.cfg:1: Vacuum.Autostart = 'maybe': not a boolean (true/false, yes/no, on/off, 1/0)");
  EXPECT_EQ(errorOf(table(), Config::fromString("Vacuum.Algorithm = mine\n", "v.cfg")),
            "v.cfg:1: Vacuum.Algorithm = 'mine': expected one of: student, reference");
  EXPECT_EQ(errorOf(table(), Config::fromString("Vacuum.Destination = 1\n", "v.cfg")),
            "v.cfg:1: Vacuum.Destination = '1': expected 2 comma-separated numbers (m), got 1");
}

TEST(Settings, OutOfRangeValuesAreNamedWithTheRange) {
  EXPECT_EQ(errorOf(table(), Config::fromString("Vacuum.MaxV = 9\n", "v.cfg")),
            "v.cfg:1: Vacuum.MaxV = '9': out of range (0, 2] m/s");
  EXPECT_EQ(errorOf(table(), Config::fromString("Vacuum.MaxV = 0\n", "v.cfg")),
            "v.cfg:1: Vacuum.MaxV = '0': out of range (0, 2] m/s");
  EXPECT_EQ(errorOf(table(), Config::fromString("Vacuum.Retries = -1\n", "v.cfg")),
            "v.cfg:1: Vacuum.Retries = '-1': out of range [0, 10]");
  EXPECT_EQ(errorOf(table(), Config::fromString("Vacuum.Destination = 1, 200\n", "v.cfg")),
            "v.cfg:1: Vacuum.Destination = '1, 200': out of range [-100, 100] m");
}

TEST(Settings, KeysOfTheOtherProcessesOfTheSameFileAreLeftToThem) {
  SettingsTable referee("vacuum-cleaner-referee");
  referee.real("Vacuum.Referee.Duration", 900, "s", 0, 1e6, "run length", true);
  const auto cfg = Config::fromString("Vacuum.MaxV = 1\nVacuum.Referee.Duration = 60\n", "v.cfg");
  const Config mine = table().resolve(cfg, {&referee});
  EXPECT_FALSE(mine.has("Vacuum.Referee.Duration"));
  EXPECT_EQ(errorOf(table(), cfg), "v.cfg:2: unknown key 'Vacuum.Referee.Duration'; `vacuum-cleaner --help` lists the settings");
}

TEST(Settings, KeyFamiliesAndHelp) {
  SettingsTable t("aula-sim");
  aula::config::SettingSpec start;
  start.key = "Simulator.StartPose.*";
  start.type = aula::config::SettingType::DoubleList;
  start.list_size = 3;
  start.help = "where a robot starts";
  t.add(start);
  const Config ok = t.resolve(Config::fromString("Simulator.StartPose.car = 1, 2, 0\n", "s.cfg"));
  EXPECT_EQ(ok.getDoubleList("Simulator.StartPose.car").size(), 3u);
  EXPECT_EQ(errorOf(t, Config::fromString("Simulator.StartPose.car = 1, 2\n", "s.cfg")),
            "s.cfg:1: Simulator.StartPose.car = '1, 2': expected 3 comma-separated numbers, got 2");
  const std::string help = table().help();
  EXPECT_NE(help.find("Vacuum.MaxV  (number, default '0.5', (0, 2] m/s)\n      speed limit"), std::string::npos) << help;
}

TEST(Settings, DeclaringAKeyTwiceOrABadDefaultIsAProgrammingError) {
  SettingsTable t("x");
  t.real("A.B", 1, "", 0, 2, "");
  EXPECT_THROW(t.real("A.B", 1, "", 0, 2, ""), std::logic_error);
  EXPECT_THROW(t.real("A.C", 5, "", 0, 2, ""), ConfigError);
}

namespace {

// A referee's rubric: two numbers and a preset over them.
SettingsTable rubricTable() {
  SettingsTable t("vacuum-cleaner-referee");
  t.real("Vacuum.Referee.HalfMark", 40, "%", 0, 100, "worth a 5");
  t.real("Vacuum.Referee.FullMark", 60, "%", 0, 100, "worth a 10");
  t.presets("Vacuum.Referee.Rubric", "default", {"Vacuum.Referee.HalfMark", "Vacuum.Referee.FullMark"},
            {{"default", "calibrated", {}}, {"original", "the thesis's", {{"Vacuum.Referee.FullMark", "30"}, {"Vacuum.Referee.HalfMark", "15"}}}},
            "the grading scale");
  return t;
}

}  // namespace

TEST(SettingsPresets, APresetFillsWhatItGovernsAndAnExplicitValueStillWins) {
  const SettingsTable t = rubricTable();
  Config effective = t.resolve(Config());
  EXPECT_EQ(effective.getString("Vacuum.Referee.Rubric"), "default");
  EXPECT_DOUBLE_EQ(effective.getDouble("Vacuum.Referee.FullMark"), 60);
  EXPECT_EQ(effective.origin("Vacuum.Referee.FullMark"), "preset default (Vacuum.Referee.Rubric)");

  effective = t.resolve(Config::fromString("Vacuum.Referee.Rubric = original\n", "v.cfg"));
  EXPECT_DOUBLE_EQ(effective.getDouble("Vacuum.Referee.HalfMark"), 15);
  EXPECT_DOUBLE_EQ(effective.getDouble("Vacuum.Referee.FullMark"), 30);
  EXPECT_EQ(effective.origin("Vacuum.Referee.FullMark"), "preset original (Vacuum.Referee.Rubric)");

  // The .cfg picks the preset, the command line one of its numbers.
  Config cfg = Config::fromString("Vacuum.Referee.Rubric = original\n", "v.cfg");
  cfg.set("Vacuum.Referee.FullMark", "50", "command line --Vacuum.Referee.FullMark");
  effective = t.resolve(cfg);
  EXPECT_DOUBLE_EQ(effective.getDouble("Vacuum.Referee.HalfMark"), 15);
  EXPECT_DOUBLE_EQ(effective.getDouble("Vacuum.Referee.FullMark"), 50);
  EXPECT_EQ(effective.origin("Vacuum.Referee.FullMark"), "command line --Vacuum.Referee.FullMark");
}

TEST(SettingsPresets, AnUnknownPresetIsNamedWithTheChoices) {
  const std::string error = errorOf(rubricTable(), Config::fromString("\nVacuum.Referee.Rubric = thesis\n", "v.cfg"));
  EXPECT_NE(error.find("v.cfg:2: Vacuum.Referee.Rubric = 'thesis': expected one of: default, original"), std::string::npos)
      << error;
}

TEST(SettingsPresets, HelpAndMarkdownShowEveryPresetsNumbers) {
  const SettingsTable t = rubricTable();
  const std::string help = t.help();
  EXPECT_NE(help.find("Vacuum.Referee.FullMark  (number, default '60', [0, 100] %, set by Vacuum.Referee.Rubric)"),
            std::string::npos) << help;
  EXPECT_NE(help.find("original: the thesis's; Vacuum.Referee.FullMark = 30, Vacuum.Referee.HalfMark = 15"), std::string::npos)
      << help;
  const std::string page = t.markdown(t.resolve(Config()), "Vacuum.Referee.");
  EXPECT_NE(page.find("| `Vacuum.Referee.FullMark` | 60 %; `original`: 30 % |"), std::string::npos) << page;
  EXPECT_NE(page.find("the grading scale; `default`: calibrated; `original`: the thesis's"), std::string::npos) << page;
}

TEST(SettingsPresets, APresetOverUndeclaredKeysOrWithABadValueIsAProgrammingError) {
  SettingsTable t("p");
  t.real("A.X", 1, "", 0, 10, "x");
  EXPECT_THROW(t.presets("A.Rubric", "default", {"A.Y"}, {{"default", "", {}}}, "?"), std::logic_error);
  EXPECT_THROW(t.presets("A.Rubric", "default", {"A.X"}, {{"default", "", {{"A.X", "11"}}}}, "?"), ConfigError);
  EXPECT_THROW(t.presets("A.Rubric", "default", {"A.X"}, {{"default", "", {{"A.Z", "1"}}}}, "?"), std::logic_error);
  EXPECT_THROW(t.presets("A.Rubric", "neither", {"A.X"}, {{"default", "", {}}}, "?"), ConfigError);
}
