// `aula grade` over a class of four, written here: the reference copied as a plugin (good), one
// that does nothing, one that does not compile and one that throws in execute(). Two seeds, two
// runs at once; every row of grades.csv is checked, and a second call resumes (skips them all).
#include <aula/process/child_process.hpp>

#include "test_support.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <vector>

namespace fs = std::filesystem;
using aula::process::ChildProcess;
using aula::testing::jsonNumber;
using aula::testing::privateDir;
using aula::testing::privateLcmUrl;
using aula::testing::csvFields;
using aula::testing::readFile;
using aula::testing::readGrades;

namespace {

constexpr const char* kShortRun = "--Vacuum.Referee.Duration=60";

int runToEnd(const std::vector<std::string>& argv, const std::string& out_path, int timeout_s) {
  ChildProcess child(argv, out_path, out_path);
  const auto code = child.wait(std::chrono::seconds(timeout_s));
  EXPECT_TRUE(code.has_value()) << argv[1] << " did not end within " << timeout_s << " s:\n" << readFile(out_path);
  return code ? *code : child.stop();
}

void writeFile(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

}  // namespace

TEST(GradeAClass, FourSubmissionsTwoSeedsTwoJobs) {
  const fs::path dir = privateDir();
  const fs::path subs = dir / "submissions";
  const std::string data = AULA_TEST_DATA_DIR;
  // The classic reference as a student would hand it in: its file and the header of its steps.
  writeFile(subs / "good" / "roomba_steps.hpp",
            readFile(std::string(AULA_SOURCE_DIR) + "/components/vacuum/reference/roomba_steps.hpp"));
  writeFile(subs / "good" / "MyAlgorithm.cpp",
            readFile(std::string(AULA_SOURCE_DIR) + "/components/vacuum/reference/RoombaReference.cpp") +
                "\nnamespace aula::vacuum {\n"
                "std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t seed) { return makeReferenceAlgorithm(seed); }\n"
                "}  // namespace aula::vacuum\n");
  writeFile(subs / "lazy" / "MyAlgorithm.cpp", readFile(data + "/plugins/does_nothing.cpp"));
  writeFile(subs / "thrower" / "MyAlgorithm.cpp", readFile(data + "/plugins/throws.cpp"));
  writeFile(subs / "broken" / "MyAlgorithm.cpp",
            "#include <aula/vacuum/vacuum_algorithm.hpp>\nint broken( { return 0; }\n");

  const std::string aula = std::string(AULA_BIN_DIR) + "/aula";
  const fs::path out = dir / "out";
  const std::vector<std::string> grade = {aula, "grade", "vacuum", (subs / "good").string(), (subs / "lazy").string(),
                                          (subs / "broken").string(), (subs / "thrower").string(), "--seeds=1-2",
                                          "--jobs=2", "--out=" + out.string(), "--record", kShortRun,
                                          "--calibration-seeds=off"};  // the fixed rubric, as the runs below
  ASSERT_EQ(runToEnd(grade, (dir / "grade1.txt").string(), 300), 0) << readFile((dir / "grade1.txt").string());
  const std::string first_csv = readFile((out / "grades.csv").string());

  // The classic reference's own marks on the same seeds (the good submission is its source).
  std::vector<double> reference, reference_coverage;
  for (int seed : {1, 2}) {
    const std::string report = (dir / ("reference" + std::to_string(seed) + ".json")).string();
    ASSERT_EQ(runToEnd({aula, "run", "vacuum", "--headless", "--algorithm=classic", "--seed=" + std::to_string(seed),
                        "--report=" + report, "--lcm-url=" + privateLcmUrl(), kShortRun},
                       (dir / "reference.txt").string(), 120),
              0);
    reference.push_back(jsonNumber(readFile(report), "mark"));
    reference_coverage.push_back(jsonNumber(readFile(report), "coverage_percent"));
  }
  char reference_median[32], coverage_median[32];
  std::snprintf(reference_median, sizeof reference_median, "%.2f", 0.5 * (reference[0] + reference[1]));
  std::snprintf(coverage_median, sizeof coverage_median, "%.2f", 0.5 * (reference_coverage[0] + reference_coverage[1]));

  auto rows = readGrades((out / "grades.csv").string());
  ASSERT_EQ(rows.size(), 4u) << first_csv;
  // Beside the mark, the raw measure the referee's report names (its "measures").
  EXPECT_EQ(first_csv.substr(0, first_csv.find('\n')),
            "student,lms_id,median,min,max,median_vacuum,median_coverage_percent,runs,runs_failed,runs_tampered,"
            "runs_retried,runs_incomplete,failures,retries,incomplete,language,hand_in,aula_version");

  EXPECT_EQ(rows["good"]["median"], reference_median) << first_csv;
  EXPECT_EQ(rows["good"]["median_coverage_percent"], coverage_median) << first_csv;
  EXPECT_EQ(rows["broken"]["median_coverage_percent"], "") << "it never ran: nothing measured\n" << first_csv;
  EXPECT_EQ(rows["good"]["runs"], "2");
  EXPECT_EQ(rows["good"]["runs_failed"], "0");
  EXPECT_EQ(rows["good"]["runs_tampered"], "0") << "nobody forged anything";
  EXPECT_EQ(rows["good"]["failures"], "");

  EXPECT_LT(std::stod(rows["lazy"]["median"]), 0.1);  // the start footprint only
  EXPECT_EQ(rows["lazy"]["runs_failed"], "0") << "doing nothing is not an error";

  EXPECT_EQ(rows["broken"]["median"], "0.00");
  EXPECT_EQ(rows["broken"]["runs_failed"], "2");
  EXPECT_EQ(rows["broken"]["failures"].rfind("did not compile: MyAlgorithm.cpp:2:", 0), 0u) << rows["broken"]["failures"];
  EXPECT_NE(rows["broken"]["failures"].find("error"), std::string::npos);

  EXPECT_EQ(rows["thrower"]["runs_failed"], "2");
  // Where it threw, in the student's file (tests/data/plugins/throws.cpp, line 12), even sandboxed.
  EXPECT_EQ(rows["thrower"]["failures"], "execute() threw std::runtime_error: boom (thrown at MyAlgorithm.cpp:12) (x2)");

  // Once every run is done, each build keeps its sources, project and log, not its objects and
  // plugin (a class that travels); the broken one's log says why it did not compile.
  for (const char* student : {"good", "lazy", "broken", "thrower"}) {
    EXPECT_FALSE(fs::exists(out / "build" / student / "build")) << student;
    EXPECT_TRUE(fs::is_regular_file(out / "build" / student / "src" / "MyAlgorithm.cpp")) << student;
  }
  EXPECT_NE(readFile((out / "build" / "broken" / "compile.log").string()).find("error"), std::string::npos);

  // Each run's result: the referee's report plus who, what and how long.
  const std::string good1 = readFile((out / "runs" / "good" / "vacuum-seed1.json").string());
  EXPECT_NE(good1.find("\"student\": \"good\""), std::string::npos) << good1;
  EXPECT_NE(good1.find("\"plugin_sha256\": \""), std::string::npos) << good1;
  EXPECT_NE(good1.find("\"world_sha256\": \""), std::string::npos) << good1;
  EXPECT_GE(jsonNumber(good1, "wall_time_s"), 0.0);
  EXPECT_DOUBLE_EQ(jsonNumber(good1, "mark"), reference[0]);
  const std::string thrower2 = readFile((out / "runs" / "thrower" / "vacuum-seed2.json").string());
  EXPECT_NE(thrower2.find("\"failure\": \"execute() threw std::runtime_error: boom (thrown at MyAlgorithm.cpp:12)\""),
            std::string::npos)
      << thrower2;

  // The teacher's page: every student in the table, a link to the referee's picture of each run
  // that ran (the file beside it, not inlined), and each run's log (--record).
  const std::string html = readFile((out / "report.html").string());
  for (const char* student : {"good", "lazy", "broken", "thrower"}) {
    EXPECT_NE(html.find(std::string("<td class='name'><a href='#") + student + "'>"), std::string::npos) << student;
  }
  size_t pictures = 0;
  for (size_t at = html.find("<img class='still' alt="); at != std::string::npos;
       at = html.find("<img class='still' alt=", at + 1)) {
    ++pictures;
  }
  EXPECT_EQ(pictures, 6u) << "one picture per run that ran (the broken submission never ran)";
  EXPECT_NE(html.find("data-src='runs/good/vacuum-seed1.png'>"), std::string::npos) << "a file beside report.html";
  EXPECT_EQ(html.find("data:image/png"), std::string::npos) << "no picture inlined in the class's page";
  EXPECT_NE(html.find("the referee's rubric: default"), std::string::npos) << "the preset the reports name";
  EXPECT_NE(html.find("<th>coverage_percent</th>"), std::string::npos);
  EXPECT_NE(html.find("<div>coverage_percent "), std::string::npos) << "each run's raw measure";
  EXPECT_TRUE(fs::is_regular_file(out / "runs" / "good" / "vacuum-seed1.png"));
  EXPECT_GT(fs::file_size(out / "runs" / "good" / "vacuum-seed1.lcmlog"), 100000u);

  // Again with the same folder: every run is up to date (same plugin, world, seed and settings).
  ASSERT_EQ(runToEnd(grade, (dir / "grade2.txt").string(), 120), 0);
  const std::string second = readFile((dir / "grade2.txt").string());
  // The class's 8, and the 6 of the vacuum's three built-ins (similarity compares the class with them).
  EXPECT_NE(second.find("14 runs already done"), std::string::npos) << second;
  EXPECT_EQ(readFile((out / "grades.csv").string()), first_csv);
  // Under other settings no result is this grade's: every run runs again (the broken submission's
  // two never ran: nothing to run again).
  std::vector<std::string> shorter = grade;
  std::replace(shorter.begin(), shorter.end(), std::string(kShortRun), std::string("--Vacuum.Referee.Duration=50"));
  ASSERT_EQ(runToEnd(shorter, (dir / "grade3.txt").string(), 300), 0);
  const std::string third = readFile((dir / "grade3.txt").string());
  EXPECT_NE(third.find("2 runs already done"), std::string::npos) << third;
  EXPECT_NE(third.find("good vacuum.world seed 1: "), std::string::npos) << third;
  EXPECT_NE(readFile((out / "runs" / "good" / "vacuum-seed1.json").string()).find("\"--Vacuum.Referee.Duration=50\""),
            std::string::npos);
  fs::remove_all(dir);
}

// A class as it comes: two Python and two C++ students, one of each broken, an empty
// MyAlgorithm.cpp, a folder with no submission and a link to /etc. Every row of grades.csv is
// there, each failure with its own whole reason, and each row names its language.
// Students are named after their folders, whatever the folder's name: UTF-8, spaces, quotes.
TEST(GradeAClass, AMixedClassOfPythonAndCppStudents) {
  const fs::path dir = privateDir();
  const fs::path subs = dir / "submissions";
  const std::string data = AULA_TEST_DATA_DIR;
  writeFile(subs / "mar\u00eda jos\u00e9" / "MyAlgorithm.py", readFile(data + "/python/vacuum_bounce/MyAlgorithm.py"));
  writeFile(subs / "ana \"la\" raises" / "MyAlgorithm.py", readFile(data + "/python/raises/MyAlgorithm.py"));
  writeFile(subs / "Zo\u00eb O'Brien" / "MyAlgorithm.cpp", readFile(data + "/plugins/vacuum_bounce.cpp"));
  writeFile(subs / "\u00fcn\u00ef \U0001F4C1" / "MyAlgorithm.cpp", readFile(data + "/plugins/throws.cpp"));
  writeFile(subs / "cpp_broken" / "MyAlgorithm.cpp", "#include <aula/vacuum/vacuum_algorithm.hpp>\nint broken( { return 0; }\n");
  writeFile(subs / "empty_cpp" / "MyAlgorithm.cpp", "");
  fs::create_directories(subs / "nothing");
  fs::create_directory_symlink("/etc", subs / "etc_link");
  std::vector<std::string> grade = {std::string(AULA_BIN_DIR) + "/aula", "grade", "vacuum"};
  for (const char* name : {"mar\u00eda jos\u00e9", "ana \"la\" raises", "Zo\u00eb O'Brien", "\u00fcn\u00ef \U0001F4C1", "cpp_broken",
                           "empty_cpp", "nothing", "etc_link"}) {
    grade.push_back((subs / name).string());
  }
  const fs::path out = dir / "out \u00f1 \U0001F4C1";  // the teacher's folder too
  grade.insert(grade.end(), {"--seeds=1", "--jobs=2", "--out=" + out.string(), kShortRun, "--calibration-seeds=off"});
  ASSERT_EQ(runToEnd(grade, (dir / "grade.txt").string(), 300), 0) << readFile((dir / "grade.txt").string());
  auto rows = readGrades((out / "grades.csv").string());
  ASSERT_EQ(rows.size(), 8u) << readFile((out / "grades.csv").string());
  const std::map<std::string, std::pair<std::string, std::string>> expected = {
      {"mar\u00eda jos\u00e9", {"Python", ""}},
      {"Zo\u00eb O'Brien", {"C++", ""}},
      {"ana \"la\" raises", {"Python", "MyAlgorithm.py:"}},
      {"\u00fcn\u00ef \U0001F4C1", {"C++", "thrown at MyAlgorithm.cpp:12"}},  // the crash's line, whatever the folder
      {"cpp_broken", {"C++", "did not compile: "}},
      {"empty_cpp", {"C++", "undefined symbol"}},
      {"nothing", {"", "nothing handed in"}},
      {"etc_link", {"", "refused: the hand-in is a symbolic link"}}};
  for (const auto& [student, want] : expected) {
    SCOPED_TRACE(student);
    EXPECT_EQ(rows[student]["language"], want.first);
    if (want.second.empty()) {
      EXPECT_EQ(rows[student]["failures"], "");
      EXPECT_GT(std::stod(rows[student]["median"]), 0.0);
    } else {
      EXPECT_NE(rows[student]["failures"].find(want.second), std::string::npos) << rows[student]["failures"];
      EXPECT_EQ(rows[student]["failures"].find("the reason is above"), std::string::npos) << rows[student]["failures"];
    }
  }
  // One API: the Python bounce is the C++ bounce, mark for mark.
  EXPECT_EQ(rows["mar\u00eda jos\u00e9"]["median"], rows["Zo\u00eb O'Brien"]["median"]);
  fs::remove_all(dir);
}

// Similar work in a class of six: a renamed and reordered copy of a C++ bounce is flagged on its
// code, the bounce's Python transliteration on its code across the languages and its behaviour
// (the same path on the same seed), and three independent solutions are flagged with nobody. Marks are never changed.
std::string disguise(std::string source) {
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"Bounce", "Roomba"}, {"phase_start_", "since_"}, {"phase_", "state_"}, {"turns_", "count_"},
           {"target_", "goal_"}, {"front_mm", "ahead"}, {"beamAt", "rangeToward"}, {"wrap", "normalize"},
           {"scan", "sweep"}, {"yaw", "heading"}, {"error", "miss"}, {"side", "dir"}, {"t_", "clock_"}}) {
    source = std::regex_replace(source, std::regex("\\b" + from + "\\b"), to);
  }
  source = std::regex_replace(source, std::regex("//[^\n]*"), "");  // other comments
  // The class's parts reordered: its private part first.
  const size_t pub = source.find(" public:\n"), priv = source.find(" private:\n"), end = source.find("};\n", priv);
  return source.substr(0, pub) + source.substr(priv, end - priv) + source.substr(pub, priv - pub) + source.substr(end);
}

TEST(GradeAClass, SimilarWorkIsFlaggedByCodeAndByBehaviour) {
  const fs::path dir = privateDir();
  const fs::path subs = dir / "class";
  const std::string data = AULA_TEST_DATA_DIR;
  const std::string bounce = readFile(data + "/plugins/vacuum_bounce.cpp");
  writeFile(subs / "ana" / "MyAlgorithm.cpp", bounce);
  writeFile(subs / "ben" / "MyAlgorithm.cpp", disguise(bounce));
  writeFile(subs / "carla" / "MyAlgorithm.py", readFile(data + "/python/vacuum_bounce/MyAlgorithm.py"));
  writeFile(subs / "dani" / "roomba_steps.hpp",
            readFile(std::string(AULA_SOURCE_DIR) + "/components/vacuum/reference/roomba_steps.hpp"));
  writeFile(subs / "dani" / "MyAlgorithm.cpp",
            readFile(std::string(AULA_SOURCE_DIR) + "/components/vacuum/reference/RoombaReference.cpp") +
                "\nnamespace aula::vacuum {\n"
                "std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t seed) { return makeReferenceAlgorithm(seed); }\n"
                "}  // namespace aula::vacuum\n");
  writeFile(subs / "eli" / "MyAlgorithm.cpp",
            "#include <aula/vacuum/vacuum_algorithm.hpp>\nnamespace aula::vacuum {\nclass Spiral : public VacuumAlgorithm {\n"
            " public:\n  void execute(VacuumApi& api) override {\n    elapsed_s_ += api.period_s;\n"
            "    if (api.bumper.getBumperData().state == 1) back_until_s_ = elapsed_s_ + 1.0;\n"
            "    const bool back = elapsed_s_ < back_until_s_;\n    api.motors.sendV(back ? -0.2 : 0.4);\n"
            "    api.motors.sendW(back ? 1.5 : 2.0 / (1.0 + 0.2 * elapsed_s_));\n  }\n"
            " private:\n  double elapsed_s_ = 0, back_until_s_ = 0;\n};\n"
            "std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<Spiral>(); }\n}\n");
  writeFile(subs / "fran" / "MyAlgorithm.py",
            "class MyAlgorithm:\n    def __init__(self, seed):\n        self.t = 0.0\n        self.turn_until = -1.0\n\n"
            "    def execute(self, api):\n        self.t += api.period_s\n        ranges = api.laser.getLaserData().values_m\n"
            "        if min(ranges[85:95]) < 0.5:\n            self.turn_until = self.t + 1.2\n"
            "        turning = self.t < self.turn_until\n        api.motors.sendV(0.0 if turning else 0.3)\n"
            "        api.motors.sendW(-1.3 if turning else 0.25)\n");
  // Two students who both started from `aula new`'s template, each with code of their own: what
  // the template gives everyone is no likeness.
  const std::string templ = readFile(std::string(AULA_SOURCE_DIR) + "/components/vacuum/student/MyAlgorithm.cpp");
  auto fromTemplate = [&](const std::string& body, const std::string& members) {
    std::string source = templ;
    const std::string todo = "    // TODO: your cleaning strategy.\n    api.motors.sendV(0.0);\n    api.motors.sendW(0.0);\n  }\n";
    const size_t at = source.find(todo);
    EXPECT_NE(at, std::string::npos) << "the template changed";
    return at == std::string::npos ? source : source.replace(at, todo.size(), body + "  }\n private:\n" + members);
  };
  writeFile(subs / "gina" / "MyAlgorithm.cpp",
            fromTemplate("    t_ += api.period_s;\n    if (api.bumper.getBumperData().state == 1) until_ = t_ + 0.8;\n"
                         "    const bool turning = t_ < until_;\n    api.motors.sendV(turning ? -0.1 : 0.25);\n"
                         "    api.motors.sendW(turning ? -2.0 : 0.0);\n",
                         "  double t_ = 0, until_ = 0;\n"));
  writeFile(subs / "hugo" / "MyAlgorithm.cpp",
            fromTemplate("    since_bump_s_ += api.period_s;\n    if (api.bumper.getBumperData().state == 1) since_bump_s_ = 0;\n"
                         "    api.motors.sendV(since_bump_s_ < 1.0 ? -0.15 : 0.35);\n"
                         "    api.motors.sendW(since_bump_s_ < 1.0 ? 1.2 : 1.8 / (1.0 + 0.1 * since_bump_s_));\n",
                         "  double since_bump_s_ = 0;\n"));
  // The teacher's own solution, which eli copied: --known compares it with everyone, by code too.
  fs::create_directories(dir / "known" / "spiral");
  fs::copy_file(subs / "eli" / "MyAlgorithm.cpp", dir / "known" / "spiral" / "MyAlgorithm.cpp");
  std::vector<std::string> grade = {std::string(AULA_BIN_DIR) + "/aula", "grade", "vacuum"};
  for (const char* name : {"ana", "ben", "carla", "dani", "eli", "fran", "gina", "hugo"}) grade.push_back((subs / name).string());
  grade.insert(grade.end(), {"--seeds=1", "--jobs=2", "--out=" + (dir / "out").string(), "--Vacuum.Referee.Duration=60",
                             "--known=" + (dir / "known").string(), "--calibration-seeds=off"});
  ASSERT_EQ(runToEnd(grade, (dir / "grade.txt").string(), 300), 0) << readFile((dir / "grade.txt").string());
  const std::string csv = readFile((dir / "out" / "similarity.csv").string());
  std::map<std::string, std::vector<std::string>> pairs;
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  while (std::getline(lines, line)) {
    const auto fields = csvFields(line);
    pairs[fields[0] + "~" + fields[1]] = fields;
  }
  // Every pair of the eight, and each of them with each of the vacuum's three built-ins and the
  // teacher's solution (never two known algorithms together).
  ASSERT_EQ(pairs.size(), 28u + 8u * 4u) << csv;
  auto flagged = [&](const std::string& pair) { return pairs.count(pair) != 0 && pairs[pair][2] == "yes"; };
  EXPECT_TRUE(flagged("ana~ben")) << csv;
  EXPECT_GE(std::stod(pairs["ana~ben"][3]), 0.6) << csv;
  EXPECT_NE(pairs["ana~ben"][6].find("ana/MyAlgorithm.cpp:"), std::string::npos) << csv;
  // The Python port: flagged on its code too, compared across the two languages in the common
  // form; and independent programs across the languages are not.
  EXPECT_TRUE(flagged("ana~carla")) << csv;
  EXPECT_GE(std::stod(pairs["ana~carla"][3]), 0.6) << "across C++ and Python, in the common form\n" << csv;
  EXPECT_NE(pairs["ana~carla"][6].find("across C++ and Python: ana/MyAlgorithm.cpp:"), std::string::npos) << csv;
  EXPECT_LE(std::stod(pairs["ana~carla"][4]), 0.05) << csv;
  for (const char* pair : {"carla~eli", "carla~gina", "carla~hugo", "eli~fran", "fran~gina", "fran~hugo"}) {
    EXPECT_EQ(pairs[pair][2], "no") << pair << ": independent programs in the two languages\n" << csv;
  }
  auto rows = readGrades((dir / "out" / "grades.csv").string());
  for (const char* student : {"gina", "hugo"}) EXPECT_EQ(rows[student]["runs_failed"], "0") << student << ": it built and ran";
  EXPECT_EQ(pairs["gina~hugo"][2], "no") << "both from the template, each with code of its own\n" << csv;
  // dani handed in the classic reference's source: flagged with it, by the path its robot drove
  // and by its code (the built-ins' installed sources); the bounce's sources are the same file.
  EXPECT_TRUE(flagged("dani~reference 'classic'")) << csv;
  EXPECT_LE(std::stod(pairs["dani~reference 'classic'"][4]), 0.05) << csv;
  EXPECT_GE(std::stod(pairs["dani~reference 'classic'"][3]), 0.9) << csv;
  EXPECT_TRUE(flagged("dani~reference 'bounce'")) << csv;
  EXPECT_TRUE(flagged("eli~known 'spiral'")) << csv;
  EXPECT_GE(std::stod(pairs["eli~known 'spiral'"][3]), 0.6) << "its code, which the teacher gave\n" << csv;
  for (const auto& [pair, fields] : pairs) {
    const bool independent = pair.find("dani") != std::string::npos || pair.find("eli") != std::string::npos ||
                             pair.find("fran") != std::string::npos || pair.find("gina") != std::string::npos ||
                             pair.find("hugo") != std::string::npos;
    if (independent && pair != "dani~reference 'classic'" && pair != "dani~reference 'bounce'" && pair != "eli~known 'spiral'") {
      EXPECT_EQ(fields[2], "no") << pair << "\n" << csv;
    }
  }
  const std::string html = readFile((dir / "out" / "report.html").string());
  EXPECT_NE(html.find("<b>ana ~ ben</b>"), std::string::npos);
  EXPECT_NE(html.find("<b>dani matches reference &#39;classic&#39;</b>"), std::string::npos);
  EXPECT_NE(html.find("Flagged: a code score of 0.60 or more with 25 shared fingerprints or more"), std::string::npos);
  EXPECT_NE(html.find("paths 0.050 m apart or less"), std::string::npos);

  // The thresholds are the teacher's: the same class again (every run already done), its robots
  // "similar" when their paths are 100 m apart or less on average, and the code rule out of reach.
  grade.insert(grade.end(), {"--similarity-path=100", "--similarity-shared=1000000"});
  ASSERT_EQ(runToEnd(grade, (dir / "again.txt").string(), 300), 0) << readFile((dir / "again.txt").string());
  const std::string again = readFile((dir / "out" / "similarity.csv").string());
  EXPECT_NE(again.find("dani,eli,yes,"), std::string::npos) << again;
  const std::string rules = readFile((dir / "out" / "report.html").string());
  EXPECT_NE(rules.find("with 1000000 shared fingerprints or more"), std::string::npos);
  EXPECT_NE(rules.find("paths 100.000 m apart or less"), std::string::npos);

  // Collecting alone (after a Slurm job) compares the class as the grade did: the manifest keeps
  // the folders and the rules.
  fs::remove(dir / "out" / "similarity.csv");
  ASSERT_EQ(runToEnd({std::string(AULA_BIN_DIR) + "/aula", "grade", "--collect=" + (dir / "out").string()},
                     (dir / "collect.txt").string(), 120), 0)
      << readFile((dir / "collect.txt").string());
  EXPECT_EQ(readFile((dir / "out" / "similarity.csv").string()), again);
  fs::remove_all(dir);
}

TEST(GradeAClass, BadRequestsAreUsageErrors) {
  const fs::path dir = privateDir();
  const std::string aula = std::string(AULA_BIN_DIR) + "/aula";
  const std::string out = (dir / "out.txt").string();
  EXPECT_EQ(runToEnd({aula, "grade", "vacuum", (dir / "nobody").string()}, out, 30), 2);
  EXPECT_NE(readFile(out).find("not a folder"), std::string::npos) << readFile(out);
  writeFile(dir / "alice" / "MyAlgorithm.cpp", "");
  EXPECT_EQ(runToEnd({aula, "grade", "vacuum", (dir / "alice").string(), "--seeds=5-1"}, out, 30), 2);
  EXPECT_NE(readFile(out).find("--seeds=5-1: '5-1' counts down"), std::string::npos) << readFile(out);
  EXPECT_EQ(runToEnd({aula, "grade", "vacuum", (dir / "alice").string(), "--engine=cloud"}, out, 30), 2);
  EXPECT_NE(readFile(out).find("--engine=cloud: local or slurm"), std::string::npos) << readFile(out);
  // The teacher's world or setting cannot run: the grade stops before any student's run.
  writeFile(dir / "broken.world", "<sdf version='1.9'><world name='x'><model");
  EXPECT_EQ(runToEnd({aula, "grade", "vacuum", (dir / "alice").string(), "--worlds=" + (dir / "broken.world").string(),
                      "--out=" + (dir / "broken").string()},
                     out, 60),
            2);
  EXPECT_NE(readFile(out).find("no run can start on " + (dir / "broken.world").string()), std::string::npos) << readFile(out);
  EXPECT_NE(readFile(out).find("malformed XML"), std::string::npos) << readFile(out);
  EXPECT_FALSE(fs::exists(dir / "broken" / "runs"));
  EXPECT_EQ(runToEnd({aula, "grade", "teletaxi", (dir / "alice").string(), "--TeleTaxi.Destination=9999,0",
                      "--out=" + (dir / "far").string()},
                     out, 60),
            2);
  EXPECT_NE(readFile(out).find("TeleTaxi.Destination = 9999,0"), std::string::npos) << readFile(out);
  EXPECT_FALSE(fs::exists(dir / "far" / "runs"));
  EXPECT_EQ(runToEnd({aula, "grade-task", (dir / "missing.json").string(), "0"}, out, 30), 2);
  EXPECT_NE(readFile(out).find("cannot read the manifest"), std::string::npos) << readFile(out);
  fs::remove_all(dir);
}

// --worlds=generate:house:3,seed=1 (issue 27): three held-out houses written into OUT/worlds,
// each with its map, each calibrated (its own file, named by every run on it and on its histogram
// in report.html) and graded; the same command into another folder writes the same bytes and
// the same grades. Generated streets grade Autopark; a kind of another exercise, a count out of
// range and a city are refused before any run.
TEST(GradeAClass, GeneratedHeldOutWorldsAreCalibratedAndTheSameTwice) {
  const fs::path dir = privateDir();
  fs::create_directories(dir / "class");
  fs::copy(std::string(AULA_TEST_DATA_DIR) + "/python/vacuum_bounce", dir / "class" / "ana", fs::copy_options::recursive);
  fs::copy(std::string(AULA_TEST_DATA_DIR) + "/python/autopark_reverse", dir / "class" / "bob", fs::copy_options::recursive);
  const std::string aula = std::string(AULA_BIN_DIR) + "/aula";
  auto grade = [&](const std::string& out) {
    return runToEnd({aula, "grade", "vacuum", (dir / "class" / "ana").string(), "--worlds=generate:house:3,seed=1", "--seeds=1-2",
                     "--calibration-seeds=1-3", "--jobs=2", "--out=" + (dir / out).string(), "--Vacuum.Referee.Duration=120"},
                    (dir / (out + ".txt")).string(), 600);
  };
  ASSERT_EQ(grade("first"), 0) << readFile((dir / "first.txt").string());
  ASSERT_EQ(grade("second"), 0) << readFile((dir / "second.txt").string());
  EXPECT_EQ(readFile((dir / "first" / "grades.csv").string()), readFile((dir / "second" / "grades.csv").string()));
  int worlds = 0, maps = 0;
  for (const auto& entry : fs::directory_iterator(dir / "first" / "worlds")) {
    EXPECT_EQ(readFile(entry.path().string()), readFile((dir / "second" / "worlds" / entry.path().filename()).string()))
        << entry.path();
    worlds += entry.path().extension() == ".world" ? 1 : 0;
    maps += entry.path().extension() == ".png" ? 1 : 0;
  }
  EXPECT_EQ(worlds, 3);
  EXPECT_EQ(maps, 3);
  const std::string html = readFile((dir / "first" / "report.html").string());
  for (const std::string world : {"house-seed1-1", "house-seed1-2", "house-seed1-3"}) {
    const std::string result = readFile((dir / "first" / "runs" / "ana" / (world + "-seed1.json")).string());
    EXPECT_NE(result.find("\"calibration\": \"" + world + "-"), std::string::npos) << result;
    EXPECT_NE(html.find("calibrated (" + world + "-"), std::string::npos) << world;
  }
  EXPECT_NE(html.find("5: the baseline&#39;s median, coverage_percent"), std::string::npos) << html.substr(0, 4000);

  ASSERT_EQ(runToEnd({aula, "grade", "autopark", (dir / "class" / "bob").string(), "--worlds=generate:street:2,seed=4",
                      "--seeds=1", "--calibration-seeds=1-2", "--out=" + (dir / "streets").string()},
                     (dir / "streets.txt").string(), 600),
            0)
      << readFile((dir / "streets.txt").string());
  const auto streets = readGrades((dir / "streets" / "grades.csv").string());
  EXPECT_EQ(streets.at("bob").at("runs"), "2");
  EXPECT_EQ(streets.at("bob").at("runs_failed"), "0") << readFile((dir / "streets" / "grades.csv").string());
  // Each street's time allowance is the reactive parker's there: parked as fast, it gets a 10.
  for (const auto& entry : fs::directory_iterator(dir / "streets" / "calibrations")) {
    if (entry.path().extension() != ".cfg") continue;
    const std::string street = entry.path().filename().string().substr(0, std::string("street-seed4-1").size());
    const std::string report = (dir / (street + "-reactive.json")).string();
    ASSERT_EQ(runToEnd({aula, "run", "autopark", "--headless", "--algorithm=reactive", "--seed=1",
                        "--world=" + (dir / "streets" / "worlds" / (street + ".world")).string(),
                        "--calibration=" + entry.path().string(), "--report=" + report, "--lcm-url=" + privateLcmUrl()},
                       (dir / "reactive.txt").string(), 300),
              0)
        << readFile((dir / "reactive.txt").string());
    EXPECT_GE(jsonNumber(readFile(report), "mark"), 9.5) << readFile(report);
    EXPECT_NE(readFile(entry.path().string()).find("Autopark.Referee.FullMarkTime = "), std::string::npos);
  }

  for (const auto& [worlds_option, said] : std::vector<std::pair<std::string, std::string>>{
           {"--worlds=generate:street:2", "a street is a world of autopark, not of vacuum"},
           {"--worlds=generate:house:0,seed=1", "expected generate:KIND:N[,seed=S]"},
           {"--worlds=generate:house:2,seed=x", "expected generate:KIND:N[,seed=S]"}}) {
    const std::string log = (dir / "refused.txt").string();
    EXPECT_EQ(runToEnd({aula, "grade", "vacuum", (dir / "class" / "ana").string(), worlds_option, "--out=" + (dir / "no").string()},
                       log, 60),
              2)
        << readFile(log);
    EXPECT_NE(readFile(log).find(said), std::string::npos) << readFile(log);
  }
  EXPECT_FALSE(fs::exists(dir / "no" / "runs"));
  fs::remove_all(dir);
}

// A teacher's city that declares its own destinations (<aula:destination>), where the shipped
// default (120, -40) is inside a building (issue 27): aula run and aula config drive to its first,
// and aula grade grades over each, each calibrated on its own (the reference's time to it); so is
// a generated city over the two it declares. A malformed declaration stops the grade before any run.
TEST(GradeAClass, ATeachersCityIsGradedOverTheDestinationsItDeclares) {
  const fs::path dir = privateDir();
  std::string city = readFile(std::string(AULA_SOURCE_DIR) + "/worlds/cityLarge.world");
  const std::string declared =
      "\n    <aula:destination name=\"plaza\">-40 40</aula:destination>"
      "\n    <aula:destination name=\"far\">220 240</aula:destination>"
      "\n    <model name=\"new_block\"><static>true</static><pose>120 -40 2.5 0 0 0</pose><link name=\"l\">"
      "<collision name=\"c\"><geometry><box><size>12 12 5</size></box></geometry></collision></link></model>";
  const auto world_open = city.find('>', city.find("<world")) + 1;
  writeFile(dir / "teacher_city.world", city.substr(0, world_open) + declared + city.substr(world_open));
  fs::create_directories(dir / "class");
  fs::copy(std::string(AULA_TEST_DATA_DIR) + "/python/teletaxi_follow", dir / "class" / "bob", fs::copy_options::recursive);
  const std::string aula = std::string(AULA_BIN_DIR) + "/aula";

  const std::string shown = (dir / "config.txt").string();
  ASSERT_EQ(runToEnd({aula, "config", "teletaxi", "--world=" + (dir / "teacher_city.world").string()}, shown, 60), 0)
      << readFile(shown);
  EXPECT_NE(readFile(shown).find("TeleTaxi.Destination = -40, 40 m    [the world's destination 'plaza']"), std::string::npos)
      << readFile(shown);
  // The shipped default is refused there: the test's building is where it should be.
  EXPECT_EQ(runToEnd({aula, "config", "teletaxi", "--world=" + (dir / "teacher_city.world").string(),
                      "--TeleTaxi.Destination=120,-40"},
                     shown, 60),
            2)
      << readFile(shown);

  const std::string log = (dir / "grade.txt").string();
  ASSERT_EQ(runToEnd({aula, "grade", "teletaxi", (dir / "class" / "bob").string(), "--worlds=" + (dir / "teacher_city.world").string(),
                      "--seeds=1", "--calibration-seeds=1", "--out=" + (dir / "out").string()},
                     log, 300),
            0)
      << readFile(log);
  const auto rows = readGrades((dir / "out" / "grades.csv").string());
  EXPECT_EQ(rows.at("bob").at("runs"), "2") << readFile(log);
  EXPECT_EQ(rows.at("bob").at("runs_failed"), "0") << readFile(log);
  for (const std::string destination : {"plaza", "far"}) {
    const std::string result = readFile((dir / "out" / "runs" / "bob" / ("teacher_city-" + destination + "-seed1.json")).string());
    EXPECT_NE(result.find("\"calibration\": \"teacher_city-" + destination + "-"), std::string::npos) << result;
    EXPECT_GT(jsonNumber(result, "mark"), 7.0) << result;
    // Each destination is a world of its own in the grades and the class's page.
    EXPECT_EQ(rows.at("bob").count("median_teacher_city-" + destination), 1u) << readFile((dir / "out" / "grades.csv").string());
    EXPECT_NE(readFile((dir / "out" / "report.html").string()).find("<b>teacher_city-" + destination + "</b>"), std::string::npos);
  }

  // A generated city declares two destinations (road crossings): graded over both, each
  // calibrated; the reference gets at least 9.5 on each, the BFS student (slower) less.
  ASSERT_EQ(runToEnd({aula, "grade", "teletaxi", (dir / "class" / "bob").string(), "--worlds=generate:city:1,seed=5", "--seeds=1",
                      "--calibration-seeds=1", "--out=" + (dir / "generated").string()},
                     log, 300),
            0)
      << readFile(log);
  EXPECT_EQ(readGrades((dir / "generated" / "grades.csv").string()).at("bob").at("runs"), "2") << readFile(log);
  for (const auto& entry : fs::directory_iterator(dir / "generated" / "calibrations")) {
    if (entry.path().extension() != ".cfg") continue;
    const std::string name = entry.path().filename().string();  // city-seed5-1-d1-<key>.rubric.cfg
    const std::string graded = name.substr(0, std::string("city-seed5-1-d1").size());
    const std::string text = readFile(entry.path().string());
    const auto at = text.find("Calibration.Setting.TeleTaxi.Destination = ");
    ASSERT_NE(at, std::string::npos) << text;
    const std::string destination = text.substr(at + 43, text.find('\n', at) - at - 43);
    const std::string report = (dir / (graded + "-reference.json")).string();
    ASSERT_EQ(runToEnd({aula, "run", "teletaxi", "--headless", "--algorithm=reference",
                        "--world=" + (dir / "generated" / "worlds" / "city-seed5-1.world").string(),
                        "--TeleTaxi.Destination=" + destination, "--calibration=" + entry.path().string(), "--report=" + report,
                        "--lcm-url=" + privateLcmUrl()},
                       log, 120),
              0)
        << readFile(log);
    EXPECT_GE(jsonNumber(readFile(report), "mark"), 9.5) << readFile(report);
    const std::string student = readFile((dir / "generated" / "runs" / "bob" / (graded + "-seed1.json")).string());
    EXPECT_LT(jsonNumber(student, "mark"), jsonNumber(readFile(report), "mark")) << student;
  }

  writeFile(dir / "bad_city.world", city.substr(0, world_open) + "\n<aula:destination name=\"x\">1</aula:destination>" +
                                        city.substr(world_open));
  EXPECT_EQ(runToEnd({aula, "grade", "teletaxi", (dir / "class" / "bob").string(), "--worlds=" + (dir / "bad_city.world").string(),
                      "--out=" + (dir / "bad").string()},
                     log, 60),
            2)
      << readFile(log);
  EXPECT_NE(readFile(log).find("<aula:destination name=\"x\">: expected two numbers, X Y in metres"), std::string::npos)
      << readFile(log);
  EXPECT_FALSE(fs::exists(dir / "bad" / "runs"));
  fs::remove_all(dir);
}
