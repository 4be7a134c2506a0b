// The `aula` front door as a user meets it: every command's --help from its declaration, an
// undeclared option refused naming the command and the nearest option, `aula` alone, --version,
// check-world's exit status, and --duration honoured by `aula run` for every exercise.
#include "test_support.hpp"

#include <aula/version.hpp>

#include <regex>
#include <set>

namespace {
namespace fs = std::filesystem;
using namespace std::chrono_literals;
using aula::testing::jsonNumber;
using aula::testing::Outcome;
using aula::testing::readFile;
using aula::testing::runToEnd;

const std::string kBin = AULA_BIN_DIR;
const std::string kWorlds = std::string(AULA_SOURCE_DIR) + "/worlds/";

// The commands `aula --help` lists (its table), in order.
std::vector<std::string> commands() {
  const Outcome help = runToEnd({kBin + "/aula", "--help"}, 10s);
  EXPECT_EQ(help.code.value_or(-1), 0) << help.output;
  std::vector<std::string> names;
  const std::string list = help.output.substr(0, help.output.find("usage of each:"));
  const std::regex line("\n  ([a-z][a-z-]*)  ");
  for (auto it = std::sregex_iterator(list.begin(), list.end(), line); it != std::sregex_iterator(); ++it) {
    names.push_back((*it)[1]);
  }
  return names;
}

// The options a command's --help lists ("--world=FILE" -> "world").
std::vector<std::string> optionsOf(const std::string& help) {
  std::vector<std::string> names;
  const std::regex line("\n  --([a-z][a-z-]*)");
  for (auto it = std::sregex_iterator(help.begin(), help.end(), line); it != std::sregex_iterator(); ++it) {
    if ((*it)[1] != "help") names.push_back((*it)[1]);
  }
  return names;
}

TEST(Commands, EveryCommandOfTheTableHasItsHelp) {
  const auto names = commands();
  for (const char* expected : {"run", "config", "check-world", "new", "grade", "grade-task", "regrade", "replay"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
  for (const std::string& name : names) {
    const Outcome out = runToEnd({kBin + "/aula", name, "--help"}, 10s);
    EXPECT_EQ(out.code.value_or(-1), 0) << name << "\n" << out.output;
    EXPECT_NE(out.output.find("usage: aula " + name), std::string::npos) << out.output;
    EXPECT_NE(out.output.find("  --help"), std::string::npos) << out.output;
  }
  // The run's own options, each with its help line.
  const auto run = optionsOf(runToEnd({kBin + "/aula", "run", "--help"}, 10s).output);
  for (const char* option : {"headless", "world", "algorithm", "seed", "report", "duration", "timeout", "cpu", "record"}) {
    EXPECT_NE(std::find(run.begin(), run.end(), option), run.end()) << option;
  }
}

TEST(Commands, AnOptionACommandDoesNotDeclareIsRefusedWithTheNearest) {
  for (const std::string& name : commands()) {
    const auto options = optionsOf(runToEnd({kBin + "/aula", name, "--help"}, 10s).output);
    // A misspelling of its first option (one letter doubled), or a foreign option when it has none.
    const std::string wrong = options.empty() ? "headless" : options.front() + options.front().back();
    const Outcome out = runToEnd({kBin + "/aula", name, "x", "y", "--" + wrong}, 10s);
    EXPECT_EQ(out.code.value_or(-1), 2) << name << "\n" << out.output;
    EXPECT_NE(out.output.find("aula " + name + ": unknown option '--" + wrong + "'"), std::string::npos) << out.output;
    if (!options.empty()) {
      EXPECT_NE(out.output.find("did you mean '--" + options.front() + "'?"), std::string::npos) << out.output;
    }
  }
  // --3d opens a window: refused headless.
  const Outcome three_d = runToEnd({kBin + "/aula", "run", "vacuum", "--headless", "--3d"}, 10s);
  EXPECT_EQ(three_d.code.value_or(-1), 2) << three_d.output;
  // What the old shared option list let through.
  const Outcome world = runToEnd({kBin + "/aula", "check-world", kWorlds + "vacuum.world", "--headless"}, 10s);
  EXPECT_EQ(world.code.value_or(-1), 2) << world.output;
}

TEST(Commands, AulaAloneListsTheCommands) {
  const Outcome out = runToEnd({kBin + "/aula"}, 10s);
  EXPECT_EQ(out.code.value_or(-1), 2) << out.output;
  EXPECT_NE(out.output.find("commands:"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("  check-world  "), std::string::npos) << out.output;
  const Outcome typo = runToEnd({kBin + "/aula", "rnu"}, 10s);
  EXPECT_EQ(typo.code.value_or(-1), 2) << typo.output;
  EXPECT_NE(typo.output.find("unknown command 'rnu' (did you mean 'run'?)"), std::string::npos) << typo.output;
}

TEST(Commands, VersionIsPrintedAndNamedInReports) {
  const Outcome out = runToEnd({kBin + "/aula", "--version"}, 10s);
  EXPECT_EQ(out.code.value_or(-1), 0) << out.output;
  EXPECT_EQ(out.output, std::string("aula ") + aula::kVersion + "\n");
}

TEST(Commands, CheckWorldExitsNonZeroWhenTheExerciseCannotRun) {
  const Outcome suits = runToEnd({kBin + "/aula", "check-world", kWorlds + "vacuum.world", "--exercise=vacuum"}, 20s);
  EXPECT_EQ(suits.code.value_or(-1), 0) << suits.output;
  const Outcome not_a_city = runToEnd({kBin + "/aula", "check-world", kWorlds + "vacuum.world", "--exercise=teletaxi"}, 20s);
  EXPECT_EQ(not_a_city.code.value_or(-1), 1) << not_a_city.output;
  EXPECT_NE(not_a_city.output.find("teletaxi: cannot run"), std::string::npos) << not_a_city.output;
}

// A plugin older than its sources (a failed build, or none) is refused, naming the file; the
// component says which file and build it runs.
TEST(Commands, AStaleBuildIsRefusedWithItsReason) {
  const std::string dir = aula::testing::privateDir() + "/mine";
  ASSERT_EQ(runToEnd({kBin + "/aula", "new", "vacuum", dir}, 20s).code.value_or(-1), 0);
  ASSERT_EQ(runToEnd({"cmake", "-S", dir, "-B", dir + "/build"}, 120s).code.value_or(-1), 0);
  ASSERT_EQ(runToEnd({"cmake", "--build", dir + "/build"}, 300s).code.value_or(-1), 0);
  const std::string plugin = dir + "/build/libmy_algorithm.so";
  const std::vector<std::string> run = {kBin + "/aula", "run", "vacuum", "--headless", "--duration=2", "--algorithm=" + plugin,
                                        "--lcm-url=" + aula::testing::privateLcmUrl()};
  const Outcome fresh = runToEnd(run, 60s);
  EXPECT_EQ(fresh.code.value_or(-1), 0) << fresh.output;
  EXPECT_NE(fresh.output.find("vacuum-cleaner: running " + plugin + " (libmy_algorithm.so (built "), std::string::npos)
      << fresh.output;
  std::filesystem::last_write_time(dir + "/MyAlgorithm.cpp",
                                   std::filesystem::last_write_time(plugin) + std::chrono::seconds(5));
  const Outcome stale = runToEnd(run, 60s);
  EXPECT_EQ(stale.code.value_or(-1), 2) << stale.output;
  EXPECT_NE(stale.output.find("MyAlgorithm.cpp changed after libmy_algorithm.so was built"), std::string::npos) << stale.output;
}

// --algorithm=reference runs each exercise's default reference: its built-in of that name, or the
// one its calibration anchors on (Autopark's reactive parker; it exited 2 before).
TEST(Commands, ReferenceNamesEachExercisesDefaultReference) {
  const std::string dir = aula::testing::privateDir();
  const std::map<std::string, std::string> expected = {{"vacuum", "reference"}, {"teletaxi", "reference"}, {"autopark", "reactive"}};
  for (const auto& [exercise, algorithm] : expected) {
    const std::string report = dir + "/" + exercise + ".json";
    const Outcome out = runToEnd({kBin + "/aula", "run", exercise, "--headless", "--duration=2", "--algorithm=reference",
                                  "--report=" + report, "--lcm-url=" + aula::testing::privateLcmUrl()},
                                 120s);
    EXPECT_EQ(out.code.value_or(-1), 0) << exercise << "\n" << out.output;
    EXPECT_NE(readFile(report).find("\"algorithm\": \"" + algorithm + "\""), std::string::npos) << exercise << "\n" << readFile(report);
  }
}

// --duration is the referee's episode length: each exercise's run ends there, in sim time.
TEST(Commands, RunHonoursDurationForEveryExercise) {
  const std::string dir = aula::testing::privateDir();
  for (const std::string exercise : {"vacuum", "teletaxi", "autopark"}) {
    const std::string report = dir + "/" + exercise + ".json";
    const Outcome out = runToEnd({kBin + "/aula", "run", exercise, "--headless", "--duration=4", "--algorithm=student",
                                  "--report=" + report, "--lcm-url=" + aula::testing::privateLcmUrl()},
                                 120s);
    const std::string json = readFile(report);
    EXPECT_NEAR(jsonNumber(json, "sim_time_s"), 4.0, 0.05) << exercise << "\n" << out.output << json;
    EXPECT_NE(json.find(std::string("\"aula_version\": \"") + aula::kVersion + "\""), std::string::npos) << json;
  }
}

}  // namespace

// `aula help run` is `aula run --help`; an error names the command once ("aula run: ...").
TEST(Commands, HelpOfACommandAndErrorsNameItOnce) {
  const Outcome help = runToEnd({kBin + "/aula", "help", "run"}, 60s);
  EXPECT_EQ(help.code.value_or(-1), 0) << help.output;
  EXPECT_EQ(help.output, runToEnd({kBin + "/aula", "run", "--help"}, 60s).output);
  const Outcome unknown = runToEnd({kBin + "/aula", "help", "rnu"}, 60s);
  EXPECT_EQ(unknown.code.value_or(-1), 2) << unknown.output;
  const Outcome wrong = runToEnd({kBin + "/aula", "run", "vacuum", "--wrold=x"}, 60s);
  EXPECT_EQ(wrong.code.value_or(-1), 2) << wrong.output;
  EXPECT_NE(wrong.output.find("aula run: unknown option '--wrold'"), std::string::npos) << wrong.output;
  EXPECT_EQ(wrong.output.find("aula: aula run"), std::string::npos) << wrong.output;
}

// Bad input a grade meets is refused at once with exit 2, naming the argument: a file that never
// ends (/dev/zero), a folder where a file belongs, seeds out of a run's range, a corrupt result,
// a project in the other language. (Each hung or was accepted silently before.)
TEST(Commands, InputThatNeverEndsOrIsOutOfRangeIsRefusedNamingIt) {
  const std::string dir = aula::testing::privateDir();
  fs::create_directories(dir + "/ana");
  std::ofstream(dir + "/ana/MyAlgorithm.py") << "class MyAlgorithm:\n    def execute(self, api):\n        pass\n";
  fs::create_directories(dir + "/collect/runs/ana");
  std::ofstream(dir + "/collect/runs/ana/vacuum-seed1.json") << "{\"mark\": 3.2, ";  // cut short
  const std::string aula = kBin + "/aula";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{aula, "run", "vacuum", "--headless", "--config=/dev/zero"}, "config file /dev/zero: not a regular file"},
      {{aula, "run", "vacuum", "--headless", "--config=" + dir}, "config file " + dir + ": a folder, not a file"},
      {{aula, "grade", "vacuum", dir + "/ana", "--out=" + dir + "/out", "--seeds=9223372036854775807"},
       "--seeds=9223372036854775807: '9223372036854775807': a seed is at most"},
      {{aula, "grade", "vacuum", dir + "/ana", "--out=" + dir + "/out", "--seeds=-5"}, "--seeds=-5: '-5': a seed is 0 or more"},
      {{aula, "grade", "vacuum", dir + "/ana", "--out=" + dir + "/out", "--seeds=1-200000"}, "is more than 1000 seeds"},
      {{aula, "grade", "vacuum", dir + "/ana", "--out=" + dir + "/out", "--calibration-seeds=9223372036854775807"},
       "--calibration-seeds=9223372036854775807"},
      {{aula, "grade", "--collect=" + dir + "/collect"}, "vacuum-seed1.json: not a result"},
      {{aula, "new", "vacuum", dir + "/ana"}, "MyAlgorithm.py already exists: " + dir + "/ana is a Python project"},
      // An output that is not a file is never replaced: a link (its target stays), a pipe.
      {{aula, "run", "vacuum", "--headless", "--report=" + dir + "/link.json"}, "is a symbolic link, not a file"},
      {{aula, "run", "vacuum", "--headless", "--trace=" + dir + "/pipe.json"}, "is a named pipe, not a file"},
      // A key set twice, by its option and by name: neither wins unchecked.
      {{aula, "run", "vacuum", "--headless", "--duration=5", "--Vacuum.Referee.Duration=abc"},
       "--duration=5 and --Vacuum.Referee.Duration=abc set the same setting"},
      {{aula, "run", "vacuum", "--headless", "--algorithm=reference", "--Vacuum.Algorithm=bounce"},
       "--algorithm=reference and --Vacuum.Algorithm=bounce set the same setting"},
  };
  std::ofstream(dir + "/target.json") << "the teacher's file\n";
  fs::create_symlink(dir + "/target.json", dir + "/link.json");
  ASSERT_EQ(::mkfifo((dir + "/pipe.json").c_str(), 0600), 0);
  for (const auto& [args, said] : cases) {
    const Outcome out = runToEnd(args, 60s);  // a backstop: each is refused before anything runs
    EXPECT_EQ(out.code.value_or(-1), 2) << args.back() << "\n" << out.output;
    EXPECT_NE(out.output.find(said), std::string::npos) << args.back() << "\n" << out.output;
  }
  EXPECT_FALSE(fs::exists(dir + "/ana/MyAlgorithm.cpp"));  // aula new wrote nothing
  EXPECT_EQ(readFile(dir + "/target.json"), "the teacher's file\n");
  EXPECT_TRUE(fs::is_symlink(dir + "/link.json"));
  fs::remove_all(dir);
}
