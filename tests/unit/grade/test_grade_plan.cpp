// aula grade's plan for a Python submission: a folder with MyAlgorithm.py and no MyAlgorithm.cpp
// is not compiled; its .py files are copied into OUT/build/<student>, and its runs load the copy.
//
// And a submission's files as aula grade takes them (submission_build.hpp) and a student's page's text
// (student_page.hpp): a plain source name is taken, anything else that ends as a source does (a
// quote, a newline), a link or an oversized source refuses the submission with the reason; other
// files are not used; the build project names no file. A student's page keeps no quote of the
// run's world, no teacher's folder, and no more than its cap of the student's text.
#include <aula/config/config.hpp>
#include <aula/grade/grade_plan.hpp>
#include <aula/grade/grades.hpp>
#include <aula/grade/grade_runner.hpp>
#include <aula/grade/run_page.hpp>
#include <aula/grade/student_page.hpp>
#include <aula/grade/submission_build.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

std::string scratch() {
  std::string pattern = (fs::temp_directory_path() / "aula_grade_plan_XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

std::string readAll(const fs::path& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST(GradePlan, APythonFolderIsNotCompiledAndItsRunsLoadACopyOfItsFile) {
  const fs::path root = scratch();
  fs::create_directories(root / "ana");
  std::ofstream(root / "ana" / "MyAlgorithm.py") << "from helpers import speed\n\nclass MyAlgorithm:\n"
                                                  << "    def __init__(self, seed):\n        pass\n\n"
                                                  << "    def execute(self, api):\n        api.motors.sendV(speed)\n";
  std::ofstream(root / "ana" / "helpers.py") << "speed = 0.3\n";
  std::ofstream(root / "ana" / "notes.txt") << "not code\n";
  aula::grade::GradeRequest request;
  request.exercise = "vacuum";
  request.submissions = {(root / "ana").string()};
  request.worlds = {std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world"};
  request.seeds = {1, 2};
  request.out_dir = (root / "out").string();

  // No Aula prefix is needed: nothing is built.
  const auto submissions = aula::grade::compileSubmissions(request, "/nonexistent");
  ASSERT_EQ(submissions.size(), 1u);
  const aula::grade::Submission& ana = submissions[0];
  EXPECT_EQ(ana.language, "Python");
  EXPECT_EQ(ana.compile_error, "");
  EXPECT_EQ(ana.plugin, (root / "out" / "build" / "ana" / "MyAlgorithm.py").string());
  EXPECT_TRUE(fs::is_regular_file(root / "out" / "build" / "ana" / "helpers.py"));  // its own modules too
  EXPECT_FALSE(fs::exists(root / "out" / "build" / "ana" / "notes.txt"));
  EXPECT_EQ(ana.plugin_sha256.size(), 64u);

  // Changing the student's file now does not change what the batch runs.
  std::ofstream(root / "ana" / "MyAlgorithm.py") << "changed\n";
  std::ifstream copy(ana.plugin);
  std::string first_line;
  std::getline(copy, first_line);
  EXPECT_EQ(first_line, "from helpers import speed");

  const aula::grade::Manifest manifest = aula::grade::planRuns(request, submissions, "/bin-of-aula");
  ASSERT_EQ(manifest.runs.size(), 2u);
  for (const auto& run : manifest.runs) {
    ASSERT_FALSE(run.argv.empty());
    EXPECT_NE(std::find(run.argv.begin(), run.argv.end(), "--algorithm=" + ana.plugin), run.argv.end());
    EXPECT_NE(std::find(run.argv.begin(), run.argv.end(), "--sandbox"), run.argv.end());
  }
  fs::remove_all(root);
}

// Two different worlds with one file name (a teacher's house_b.world in two folders) are both
// graded, under names told apart by their content; a world's hash covers its models, so a fixed
// model plans the runs anew (a result with the old hash is not up to date).
TEST(GradePlan, TwoWorldsWithOneFileNameAreNamedApartAndAModelChangesTheHash) {
  const fs::path root = scratch();
  const std::string house = std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world";
  for (const char* folder : {"a", "b"}) {
    fs::create_directories(root / folder);
    fs::copy(fs::path(AULA_SOURCE_DIR) / "worlds" / "models", root / folder / "models", fs::copy_options::recursive);
    fs::copy_file(house, root / folder / "house.world");
  }
  {  // b's sofa box moved: another world under the same name
    std::ifstream in(root / "b" / "house.world");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = text.find("</world>");
    ASSERT_NE(at, std::string::npos);
    text.insert(at, "<model name='extra_box'><static>true</static><pose>0.3 -1.2 0.2 0 0 0</pose><link name='l'>"
                    "<collision name='c'><geometry><box><size>0.2 0.2 0.4</size></box></geometry></collision>"
                    "</link></model>");
    std::ofstream(root / "b" / "house.world") << text;
  }
  aula::grade::GradeRequest request;
  request.exercise = "vacuum";
  request.worlds = {(root / "a" / "house.world").string(), (root / "b" / "house.world").string()};
  request.seeds = {1};
  request.out_dir = (root / "out").string();
  aula::grade::Submission ana;
  ana.student = "ana";
  ana.plugin = "bounce";
  const auto plan = aula::grade::planRuns(request, {ana}, "/bin-of-aula");
  ASSERT_EQ(plan.runs.size(), 2u);
  EXPECT_NE(plan.runs[0].world_name, plan.runs[1].world_name);
  EXPECT_NE(plan.runs[0].result_path, plan.runs[1].result_path);
  EXPECT_EQ(plan.runs[0].world_name, "house-" + plan.runs[0].world_sha256.substr(0, 8) + ".world");

  // A fixed model (the roomba's model.sdf gains a comment) changes a's hash.
  std::ofstream(root / "a" / "models" / "roomba" / "model.sdf", std::ios::app) << "<!-- fixed -->\n";
  request.worlds = {(root / "a" / "house.world").string()};
  const auto again = aula::grade::planRuns(request, {ana}, "/bin-of-aula");
  ASSERT_EQ(again.runs.size(), 1u);
  EXPECT_EQ(again.runs[0].world_name, "house.world");
  EXPECT_NE(again.runs[0].world_sha256, plan.runs[0].world_sha256);
  fs::remove_all(root);
}

// A resumed grade runs again what ended for the machine's reason (a starved process, the wall
// budget), never what the algorithm did: the same run gives the same result, so only time is spent.
// The machine's reason is the grade's own verdict (`machine_reason`), never read from the failure's
// text, which a student's exception or compiler error can write.
TEST(GradePlan, ARunThatFailedForTheMachinesReasonIsNotUpToDate) {
  const std::string dir = scratch();
  aula::grade::PlannedRun run;
  run.result_path = dir + "/r.json";
  run.student = "ada";
  run.seed = 1;
  auto resultFailing = [&](const std::string& failure, bool machine) {
    std::ofstream(run.result_path) << "{\"plugin_sha256\": \"\", \"world_sha256\": \"\", \"seed\": 1, \"student\": \"ada\", "
                                      "\"settings\": [], \"failure\": \"" << failure << "\", \"machine_reason\": "
                                   << (machine ? "true" : "false") << "}";
    return aula::grade::upToDate(run);
  };
  EXPECT_TRUE(resultFailing("", false));
  EXPECT_TRUE(resultFailing("execute() threw std::runtime_error: boom (thrown at MyAlgorithm.cpp:12)", false));
  EXPECT_TRUE(resultFailing("the algorithm used more than 2048 MB of memory", false));
  EXPECT_TRUE(resultFailing("execute() used more than 2 s of CPU time (an endless loop?) (Component.ExecuteBudget)", false));
  // A student's text that says it: their failure, kept.
  EXPECT_TRUE(resultFailing("the machine's reason: the component was killed (SIGKILL) from outside the run", false));
  EXPECT_TRUE(resultFailing("execute() threw Exception: the machine's reason: try again (MyAlgorithm.py:3)", false));
  EXPECT_TRUE(resultFailing("did not compile: MyAlgorithm.cpp:1: #error the machine's reason: ", false));
  EXPECT_FALSE(resultFailing("the machine's reason: the run failed (exit 1): aula-sim: stopped at 674 s", true));
  EXPECT_FALSE(resultFailing("the machine's reason: lockstep client 'vacuum-cleaner' silent for 600.1 s of wall time", true));
  EXPECT_FALSE(resultFailing("the machine's reason: the run's wall-clock backstop of 60 s ran out (--timeout)", true));
  EXPECT_FALSE(resultFailing("the machine's reason: the component was killed (SIGKILL) from outside the run", true));
  fs::remove_all(dir);
}

// Seeds out of a run's range, or more than a grade can mean, are refused at once naming the
// option (--seeds=9223372036854775807 never returned; --seeds=-5 gave every student 0.00).
TEST(GradePlan, SeedsOutOfRangeAreRefusedNamingTheOption) {
  using aula::grade::parseSeeds;
  EXPECT_EQ(parseSeeds("1-3,7", "--seeds"), (std::vector<long long>{1, 2, 3, 7}));
  auto refusal = [](const std::string& text, const std::string& option) {
    try {
      parseSeeds(text, option);
    } catch (const aula::config::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal("-5", "--seeds"), "--seeds=-5: '-5': a seed is 0 or more");
  EXPECT_EQ(refusal("9223372036854775807", "--seeds"),
            "--seeds=9223372036854775807: '9223372036854775807': a seed is at most 9000000000000000000");
  EXPECT_EQ(refusal("9223372036854775807", "--calibration-seeds").rfind("--calibration-seeds=", 0), 0u);
  EXPECT_EQ(refusal("1-200000", "--seeds"), "--seeds=1-200000: '1-200000' is more than 1000 seeds");
  EXPECT_EQ(refusal("1-600,1000-1600", "--seeds"), "--seeds=1-600,1000-1600: more than 1000 seeds in all");
  EXPECT_EQ(refusal("1-1000", "--seeds"), "accepted");
}

TEST(SubmissionFiles, PlainSourcesAreTakenOthersNotUsedAndABadNameRefused) {
  using aula::grade::isPlainSourceName;
  for (const char* plain : {"MyAlgorithm.cpp", "helpers.hpp", "a_b-c.d.cc", "x.h", "_x.hh", "m.py", "m.cxx"}) {
    EXPECT_TRUE(isPlainSourceName(plain)) << plain;
  }
  for (const char* bad : {"MyAlgorithm.cpp\")\nfile(STRINGS x L)\n#.cpp", "my algorithm.cpp", "-x.cpp", ".hidden.cpp",
                          "a$b.cpp", "a;b.cpp", "x.cpp.txt", "x\x01.py", "é.cpp", "x.CPP"}) {
    EXPECT_FALSE(isPlainSourceName(bad)) << bad;
  }
  const fs::path root = scratch();
  fs::create_directories(root / "ana" / "build");
  std::ofstream(root / "ana" / "MyAlgorithm.cpp") << "// ana\n";
  std::ofstream(root / "ana" / "helpers.hpp") << "// helpers\n";
  std::ofstream(root / "ana" / "CMakeLists.txt") << "project(x)\n";
  std::ofstream(root / "ana" / "notes\nfile(x).txt") << "not a source: never used\n";
  const auto ana = aula::grade::submissionFiles((root / "ana").string());
  EXPECT_EQ(ana.refused, "");
  EXPECT_EQ(ana.sources, (std::vector<std::string>{"MyAlgorithm.cpp", "helpers.hpp"}));
  EXPECT_EQ(ana.unused, (std::vector<std::string>{"CMakeLists.txt", "build/", "notes\\x0afile(x).txt"}));

  // Copied, and the copy left as it is when nothing changed (its time too: nothing rebuilds).
  const fs::path copy = root / "out" / "src";
  fs::create_directories(copy);
  std::ofstream(copy / "stale.cpp") << "// a source ana no longer has\n";
  ASSERT_EQ(aula::grade::copySources((root / "ana").string(), ana, copy.string()), "");
  EXPECT_EQ(readAll(copy / "MyAlgorithm.cpp"), "// ana\n");
  EXPECT_FALSE(fs::exists(copy / "stale.cpp"));
  EXPECT_FALSE(fs::exists(copy / "CMakeLists.txt"));
  const auto copied_at = fs::last_write_time(copy / "MyAlgorithm.cpp");
  ASSERT_EQ(aula::grade::copySources((root / "ana").string(), ana, copy.string()), "");
  EXPECT_EQ(fs::last_write_time(copy / "MyAlgorithm.cpp"), copied_at);

  // The build file names nothing of the student's.
  aula::grade::writeBuildProject((root / "out").string(), "vacuum", "/opt/aula/lib/cmake/Aula");
  const std::string project = readAll(root / "out" / "CMakeLists.txt");
  EXPECT_EQ(project.find("MyAlgorithm"), std::string::npos) << project;
  EXPECT_EQ(project.find("ana"), std::string::npos) << project;
  EXPECT_NE(project.find("PATHS [==[/opt/aula/lib/cmake/Aula]==]"), std::string::npos) << project;

  // A name that would end a quoted CMake argument: the whole submission refused, the name escaped.
  fs::create_directories(root / "ben");
  std::ofstream(root / "ben" / "MyAlgorithm.cpp") << "// ben\n";
  std::ofstream(root / "ben" / "MyAlgorithm.cpp\")\ninclude(${L})\n#.cpp") << "// x\n";
  const auto ben = aula::grade::submissionFiles((root / "ben").string());
  EXPECT_EQ(ben.refused,
            "refused: MyAlgorithm.cpp\\x22)\\x0ainclude(${L})\\x0a#.cpp is not a plain source name (letters, digits, '_', "
            "'.', '-' and .cpp, .cc, .cxx, .hpp, .h, .hh or .py)");
  // A link to a classmate's file, and a source too large.
  fs::create_directories(root / "cat");
  fs::create_symlink(root / "ana" / "MyAlgorithm.cpp", root / "cat" / "MyAlgorithm.cpp");
  EXPECT_EQ(aula::grade::submissionFiles((root / "cat").string()).refused,
            "refused: MyAlgorithm.cpp is a symbolic link: a submission's sources are its own files");
  fs::create_directories(root / "dan");
  std::ofstream(root / "dan" / "MyAlgorithm.cpp") << std::string(aula::grade::kMaxSourceBytes + 1, ' ');
  EXPECT_EQ(aula::grade::submissionFiles((root / "dan").string()).refused, "refused: MyAlgorithm.cpp is larger than 1 MiB");

  // In a grade: a Python submission refused the same way, its row's reason, nothing copied.
  fs::create_directories(root / "eve");
  std::ofstream(root / "eve" / "MyAlgorithm.py") << "x = 1\n";
  std::ofstream(root / "eve" / "evil'.py") << "x = 2\n";
  aula::grade::GradeRequest request;
  request.exercise = "vacuum";
  request.submissions = {(root / "eve").string()};
  request.out_dir = (root / "grade").string();
  const auto graded = aula::grade::compileSubmissions(request, "/nonexistent");
  ASSERT_EQ(graded.size(), 1u);
  EXPECT_EQ(graded[0].compile_error.rfind("refused: evil\\x27.py is not a plain source name", 0), 0u) << graded[0].compile_error;
  EXPECT_EQ(graded[0].plugin, "");
  EXPECT_FALSE(fs::exists(root / "grade" / "build" / "eve" / "MyAlgorithm.py"));
  fs::remove_all(root);
}

TEST(StudentPage, KeepsNoQuoteOfTheWorldNoTeachersFolderAndCapsTheStudentsText) {
  const std::string world = "<?xml version='1.0'?>\n<sdf version='1.6'><world name='held_out'><model name='sofa'>"
                            "<pose>1.25 3.5 0 0 0 0.7</pose></model></world></sdf>\n";
  const std::vector<std::string> withheld = {world};
  using aula::grade::forTheStudent;
  EXPECT_EQ(forTheStudent("the algorithm threw std::runtime_error: " + world.substr(40, 40), withheld),
            "(withheld from the student's page: it quotes the run's world)");
  EXPECT_EQ(forTheStudent("the algorithm threw std::runtime_error: a sofa at 1.25 3.5", withheld),
            "the algorithm threw std::runtime_error: a sofa at 1.25 3.5");
  EXPECT_EQ(forTheStudent("cannot open /home/teacher/exam/held_out.world (errno 2)", withheld),
            "cannot open held_out.world (errno 2)");
  EXPECT_EQ(forTheStudent("--calibration=/srv/grades/calibrations/h.rubric.cfg", withheld), "--calibration=h.rubric.cfg");
  EXPECT_EQ(forTheStudent("a speed of 0.3 m/s", withheld), "a speed of 0.3 m/s");
  const std::string long_text(aula::grade::kStudentTextChars + 100, 'x');
  EXPECT_EQ(forTheStudent(long_text, withheld), std::string(aula::grade::kStudentTextChars, 'x') + "... (100 characters more)");

  // Every string of the report and of the trace, however deep.
  aula::grade::RunFiles run;
  run.title = "ana, held_out seed 1";
  run.report = {{"failure", "the algorithm threw: " + world}, {"log", "/srv/grades/runs/ana/held_out-seed1.log"},
                {"mark", 3.5}, {"settings", {"--calibration=/srv/grades/c.rubric.cfg"}}};
  run.trace_json = R"({"events": [{"t_s": 1.5, "kind": "fault", "text": ")" + std::string("<sdf version='1.6'><world name='held_out'>") +
                   R"("}], "samples": {"x_mm": [1, 2]}})";
  run.picture_png = "a picture that writes the failure";
  const aula::grade::RunFiles shown = forTheStudent(run, withheld);
  EXPECT_EQ(shown.report["failure"], "(withheld from the student's page: it quotes the run's world)");
  EXPECT_EQ(shown.report["log"], "held_out-seed1.log");
  EXPECT_EQ(shown.report["mark"], 3.5);
  EXPECT_EQ(shown.report["settings"][0], "--calibration=c.rubric.cfg");
  EXPECT_EQ(shown.trace_json.find("sdf version"), std::string::npos) << shown.trace_json;
  EXPECT_TRUE(shown.picture_png.empty());  // it writes the failure in full
  EXPECT_NE(shown.trace_json.find(R"("x_mm":[1,2])"), std::string::npos) << shown.trace_json;
  // The referee's own data is no one's text: the vacuum's cleaned cells, longer than the text cap, stay whole.
  const std::string cells(aula::grade::kStudentTextChars * 4, 'A');
  run.trace_json = R"({"state": {"cells": ")" + cells + R"("}, "events": []})";
  EXPECT_NE(forTheStudent(run, withheld).trace_json.find(cells), std::string::npos);
  // A failure of the student's own, short and with no path: shown as it is, with the picture.
  run.report["failure"] = "execute() threw std::runtime_error: boom";
  EXPECT_EQ(forTheStudent(run, withheld).picture_png, "a picture that writes the failure");
}

// One copy of each trace (issue 58): a trace the student's page needs unchanged is the page's
// alone, the referee's bytes read back from it; one the page had to change stays beside it, compact.
TEST(StudentPage, TheGradeKeepsOneCopyOfEachTrace) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("aula-one-trace-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string world = "<?xml version='1.0'?>\n<sdf version='1.6'><world name='held_out'></world></sdf>\n";
  const std::string plain = "{\"trace\": 1,\n \"events\": [{\"t_s\": 1.5, \"kind\": \"bump\", \"text\": \"a bump\"}],\n"
                            " \"samples\": {\"x_mm\": [1,2,3]}}\n";
  const std::string quoting = "{\"trace\": 1,\n \"events\": [{\"t_s\": 1.5, \"kind\": \"fault\", \"text\": \"" +
                              std::string("<sdf version='1.6'><world name='held_out'>") + "\"}],\n \"samples\": {\"x_mm\": [1]}}\n";
  for (const std::string& referees : {plain, quoting}) {
    const std::string stem = (dir / (referees == plain ? "plain" : "quoting")).string();
    std::ofstream(stem + ".trace.json", std::ios::binary) << referees;
    aula::grade::RunFiles run;
    run.report = {{"mark", 1.0}, {"log", stem + ".log"}};
    run.trace_json = aula::grade::traceOfRun(stem);
    ASSERT_EQ(run.trace_json, referees);
    const aula::grade::RunFiles theirs = aula::grade::forTheStudent(run, {world});
    const bool page_has_it = aula::grade::withoutPaths(theirs.trace_json) == referees;
    EXPECT_EQ(page_has_it, referees == plain) << "unchanged, the student's copy is the referee's bytes";
    const std::string html = aula::grade::runPageHtml(theirs);
    std::ofstream(stem + ".html", std::ios::binary) << html;
    aula::grade::keepOneTrace(stem, page_has_it);
    EXPECT_FALSE(fs::exists(stem + ".trace.json"));
    EXPECT_EQ(fs::exists(stem + ".trace.z"), !page_has_it);
    EXPECT_EQ(aula::grade::traceOfRun(stem), referees) << "nothing lost: the referee's trace, byte for byte";
    EXPECT_EQ(aula::grade::traceOfPage(html).find("sdf version"), std::string::npos) << "the page's copy withholds the world";
  }
  EXPECT_EQ(aula::grade::inflated(aula::grade::deflated(std::string(300000, 'x'))), std::string(300000, 'x'));
  EXPECT_EQ(aula::grade::inflated("not a zlib stream"), "");
  EXPECT_EQ(aula::grade::traceOfRun((dir / "none").string()), "");
  fs::remove_all(dir);
}

// The picture the grade keeps and inlines (issue 58): the same filtered rows, deflated at zlib's
// best in one IDAT, the other chunks as they were; anything else left as it is.
TEST(StudentPage, ThePictureIsKeptSmallerPixelForPixel) {
  auto u32 = [](uint32_t v) { return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; };
  auto chunk = [&](const std::string& type, const std::string& data) {  // the CRC is not read back here
    return u32(static_cast<uint32_t>(data.size())) + type + data + u32(0);
  };
  std::string rows;  // 64 rows of 200 grey pixels, filter byte 0
  for (int y = 0; y < 64; ++y) rows += '\0' + std::string(200, static_cast<char>(y % 7 ? 200 : 30));
  const std::string packed = aula::grade::deflated(rows);
  const std::string header = u32(200) + u32(64) + std::string{8, 0, 0, 0, 0};
  const std::string signature("\x89PNG\r\n\x1a\n", 8);
  // Three IDATs in a row (as encoders write them), around them IHDR, a text chunk and IEND.
  const std::string png = signature + chunk("IHDR", header) + chunk("tEXt", std::string("a\0b", 3)) + chunk("IDAT", packed.substr(0, 10)) +
                          chunk("IDAT", packed.substr(10, 20)) + chunk("IDAT", packed.substr(30)) +
                          std::string("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  const std::string smaller = aula::grade::smallerPng(png);
  ASSERT_LT(smaller.size(), png.size());
  EXPECT_EQ(smaller.substr(0, 8 + 12 + 13), png.substr(0, 8 + 12 + 13)) << "the signature and IHDR as they were";
  const size_t idat = smaller.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  EXPECT_EQ(smaller.find("IDAT", idat + 1), std::string::npos) << "one IDAT";
  const auto length = [&](size_t at) {
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(smaller[at + i]);
    return v;
  };
  EXPECT_EQ(aula::grade::inflated(smaller.substr(idat + 4, length(idat - 4))), rows) << "pixel for pixel";
  EXPECT_EQ(smaller.substr(smaller.size() - 12), png.substr(png.size() - 12)) << "IEND as it was";
  EXPECT_NE(smaller.find(std::string("tEXta\0b", 7)), std::string::npos) << "the other chunks kept";
  EXPECT_EQ(aula::grade::smallerPng(smaller), smaller) << "once is enough";
  EXPECT_EQ(aula::grade::smallerPng("not a picture"), "not a picture");
  EXPECT_EQ(aula::grade::smallerPng(png.substr(0, png.size() - 30)), png.substr(0, png.size() - 30)) << "cut short";
}

// A retry is said in its row, and a run that never completed (the machine's reason on every try)
// is left out of the marks and named, never a 0 in the median (issue 57).
TEST(GradePlan, RetriesAreSaidAndARunNeverCompletedIsLeftOutAndNamed) {
  const auto retried = nlohmann::json::parse(R"JSON({"student": "ada", "mark": 6.0, "seed": 1, "world": "house.world",
    "machine_reason": false, "retried": 1, "retried_because": ["the machine's reason: aula-sim died (SIGKILL)"]})JSON");
  const auto never = nlohmann::json::parse(R"JSON({"student": "ada", "mark": 0.0, "seed": 2, "world": "house.world",
    "machine_reason": true, "failure": "the machine's reason: the grade's wall-clock backstop of 3600 s ran out"})JSON");
  // A student's failure that says the words is theirs: a 0 in the median, no retry.
  const auto theirs = nlohmann::json::parse(R"JSON({"student": "bo", "mark": 0.0, "seed": 1, "world": "house.world",
    "machine_reason": false, "failure": "MyAlgorithm.py:3: RuntimeError: the machine's reason: please"})JSON");
  const auto grades = aula::grade::gradeStudents({retried, never, theirs});
  ASSERT_EQ(grades.size(), 2u);
  const auto& ada = grades[0];
  EXPECT_EQ(ada.runs, 1);
  EXPECT_DOUBLE_EQ(ada.median, 6.0);
  EXPECT_EQ(ada.runs_retried, 1);
  EXPECT_EQ(ada.retries, "the machine's reason: aula-sim died (SIGKILL)");
  EXPECT_EQ(ada.runs_incomplete, 1);
  EXPECT_EQ(ada.incomplete, "house seed 2");
  const auto& bo = grades[1];
  EXPECT_EQ(bo.runs, 1);
  EXPECT_EQ(bo.runs_failed, 1);
  EXPECT_EQ(bo.runs_incomplete, 0);
  const std::string csv = aula::grade::gradesCsv(grades);
  EXPECT_NE(csv.find(",1,1,,the machine's reason: aula-sim died (SIGKILL),house seed 2,"), std::string::npos) << csv;
}
