#include <aula/config/config.hpp>

#include <gtest/gtest.h>

#include <fstream>

using aula::config::CommandLine;
using aula::config::Config;
using aula::config::ConfigError;

namespace {

// Runs f and returns the ConfigError message (fails the test when nothing is thrown).
template <typename F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a ConfigError";
  return "";
}

const char* kSample =
    "# TeleTaxi\n"
    "TeleTaxi.Motors.Channel = TAXI_MOTORS\n"
    "\n"
    "   TeleTaxi.MaxV=50   # m/s\n"
    "TeleTaxi.Period = 80\n"
    "TeleTaxi.Headless = yes\n"
    "TeleTaxi.Destination = 120, -40.5\n"
    "TeleTaxi.Empty =\n";

}  // namespace

TEST(Config, ParsesTypedValues) {
  const Config c = Config::fromString(kSample, "teleTaxi.cfg");
  EXPECT_EQ(c.getString("TeleTaxi.Motors.Channel"), "TAXI_MOTORS");
  EXPECT_DOUBLE_EQ(c.getDouble("TeleTaxi.MaxV"), 50.0);
  EXPECT_EQ(c.getInt("TeleTaxi.Period"), 80);
  EXPECT_TRUE(c.getBool("TeleTaxi.Headless"));
  EXPECT_EQ(c.getDoubleList("TeleTaxi.Destination"), (std::vector<double>{120.0, -40.5}));
  EXPECT_EQ(c.getString("TeleTaxi.Empty"), "");
  EXPECT_EQ(c.origin("TeleTaxi.Period"), "teleTaxi.cfg:5");
}

TEST(Config, DefaultsOnlyForMissingKeys) {
  const Config c = Config::fromString(kSample, "t.cfg");
  EXPECT_EQ(c.getInt("Nope.Key", 7), 7);
  EXPECT_DOUBLE_EQ(c.getDouble("Nope.Key", 1.5), 1.5);
  EXPECT_EQ(c.getString("Nope.Key", "x"), "x");
  EXPECT_FALSE(c.getBool("Nope.Key", false));
  // Present but malformed: the default does not hide the mistake.
  EXPECT_NE(errorOf([&] { c.getInt("TeleTaxi.Motors.Channel", 3); }).find("not an integer"),
            std::string::npos);
}

TEST(Config, ErrorsNameFileLineAndKey) {
  const Config c = Config::fromString(kSample, "teleTaxi.cfg");
  EXPECT_EQ(errorOf([&] { c.getDouble("TeleTaxi.Motors.Channel"); }),
            "teleTaxi.cfg:2: TeleTaxi.Motors.Channel = 'TAXI_MOTORS': not a finite number");
  EXPECT_EQ(errorOf([&] { c.getInt("TeleTaxi.Missing"); }),
            "teleTaxi.cfg: missing key 'TeleTaxi.Missing'");
  EXPECT_NE(errorOf([&] { c.getBool("TeleTaxi.Period"); }).find("teleTaxi.cfg:5"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { c.getInt("TeleTaxi.Destination"); }).find("not an integer"),
            std::string::npos);
}

TEST(Config, MalformedLinesAreRejected) {
  EXPECT_EQ(errorOf([] { Config::fromString("A.B = 1\nno equals here\n", "x.cfg"); }),
            "x.cfg:2: expected 'Key = value', got 'no equals here'");
  EXPECT_NE(errorOf([] { Config::fromString("= 3\n", "x.cfg"); }).find("x.cfg:1: invalid key"),
            std::string::npos);
  EXPECT_NE(errorOf([] { Config::fromString("A..B = 3\n", "x.cfg"); }).find("invalid key"),
            std::string::npos);
  EXPECT_NE(errorOf([] { Config::fromString("A.B = 1\nA.B = 2\n", "x.cfg"); })
                .find("x.cfg:2: key 'A.B' is already set at x.cfg:1"),
            std::string::npos);
}

TEST(Config, NumbersMustBeFiniteAndWhole) {
  const Config c = Config::fromString(
      "A.Nan = nan\nA.Inf = inf\nA.Trail = 3abc\nA.Big = 99999999999\nA.List = 1,,2\n", "n.cfg");
  EXPECT_NE(errorOf([&] { c.getDouble("A.Nan"); }).find("not a finite number"), std::string::npos);
  EXPECT_NE(errorOf([&] { c.getDouble("A.Inf"); }).find("not a finite number"), std::string::npos);
  EXPECT_NE(errorOf([&] { c.getDouble("A.Trail"); }).find("n.cfg:3"), std::string::npos);
  EXPECT_NE(errorOf([&] { c.getInt("A.Big"); }).find("out of range"), std::string::npos);
  EXPECT_EQ(c.getInt64("A.Big"), 99999999999LL);
  EXPECT_NE(errorOf([&] { c.getDoubleList("A.List"); }).find("item ''"), std::string::npos);
}

TEST(Config, MissingFileIsNamed) {
  EXPECT_EQ(errorOf([] { Config::fromFile("/nonexistent/a.cfg"); }), "config file /nonexistent/a.cfg: no such file");
}

// A device that never ends (/dev/zero) or a folder named as the file: refused at once, never read
// (reading /dev/zero grew a process by 0.5 GB/s; a folder read as empty ran on defaults).
TEST(Config, AFileThatIsNotARegularFileIsRefusedAtOnce) {
  EXPECT_EQ(errorOf([] { Config::fromFile("/dev/zero"); }),
            "config file /dev/zero: not a regular file (a device or a pipe may never end)");
  EXPECT_EQ(errorOf([] { Config::fromFile(::testing::TempDir()); }),
            "config file " + ::testing::TempDir() + ": a folder, not a file");
  const std::string big = ::testing::TempDir() + "aula_config_big.cfg";
  std::ofstream(big) << std::string(Config::kMaxConfigBytes + 1, '#');
  EXPECT_NE(errorOf([&] { Config::fromFile(big); }).find("larger than"), std::string::npos);
}

TEST(Config, ReadsRealFiles) {
  const std::string path = ::testing::TempDir() + "aula_config_test.cfg";
  std::ofstream(path) << "Sim.Step = 0.005\n";
  EXPECT_DOUBLE_EQ(Config::fromFile(path).getDouble("Sim.Step"), 0.005);
}

TEST(CommandLine, SplitsPositionalOptionsAndOverrides) {
  const char* argv[] = {"prog", "worlds/a.world", "--headless", "--seed=4", "--config",
                        "x.cfg", "--TeleTaxi.Destination=120,-40"};
  const CommandLine cl = CommandLine::parse(7, argv, {"config"});
  ASSERT_EQ(cl.positional.size(), 1u);
  EXPECT_EQ(cl.positional[0], "worlds/a.world");
  EXPECT_TRUE(cl.flag("headless"));
  EXPECT_EQ(cl.option("seed"), "4");
  EXPECT_EQ(cl.option("config"), "x.cfg");
  ASSERT_EQ(cl.overrides.size(), 1u);

  Config c = Config::fromString("TeleTaxi.Destination = 0,0\n", "t.cfg");
  cl.applyOverrides(c);
  EXPECT_EQ(c.getDoubleList("TeleTaxi.Destination"), (std::vector<double>{120, -40}));
  EXPECT_EQ(c.origin("TeleTaxi.Destination"), "command line --TeleTaxi.Destination");
}

TEST(CommandLine, NumberOptions) {
  const char* argv[] = {"prog", "--screenshot-at=12.5", "--bad=12s", "--nan=nan"};
  const CommandLine cl = CommandLine::parse(4, argv);
  EXPECT_DOUBLE_EQ(cl.optionDouble("screenshot-at", 40), 12.5);
  EXPECT_DOUBLE_EQ(cl.optionDouble("absent", 40), 40);
  EXPECT_NE(errorOf([&] { cl.optionDouble("bad", 0); }).find("--bad=12s is not a number"), std::string::npos);
  EXPECT_NE(errorOf([&] { cl.optionDouble("nan", 0); }).find("not a number"), std::string::npos);
}

TEST(CommandLine, RejectsMalformedAndUnknown) {
  const char* bad1[] = {"prog", "--=3"};
  EXPECT_NE(errorOf([&] { CommandLine::parse(2, bad1); }).find("malformed"), std::string::npos);
  const char* bad2[] = {"prog", "--A.B"};
  EXPECT_NE(errorOf([&] { CommandLine::parse(2, bad2); }).find("needs =value"), std::string::npos);
  const char* bad3[] = {"prog", "--config"};
  EXPECT_NE(errorOf([&] { CommandLine::parse(2, bad3, {"config"}); }).find("needs a value"),
            std::string::npos);
  const char* bad4[] = {"prog", "-x"};
  EXPECT_NE(errorOf([&] { CommandLine::parse(2, bad4); }).find("unknown argument"),
            std::string::npos);
  const char* ok[] = {"prog", "--headles"};
  const CommandLine cl = CommandLine::parse(2, ok);
  EXPECT_EQ(errorOf([&] { cl.requireKnown({"headless"}); }),
            "command line: unknown option(s) --headles");
}
