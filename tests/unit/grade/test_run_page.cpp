// The run page's text: a report's diagnostics (each one, once, for people and for the class
// table's flags), and a student's page cut of the teacher's paths.
#include <aula/grade/report_html.hpp>
#include <aula/grade/run_page.hpp>

#include <gtest/gtest.h>

using aula::grade::runDiagnostics;
using aula::grade::withoutPaths;

TEST(RunPageText, PathsAreCutToTheirFileNames) {
  EXPECT_EQ(withoutPaths("/home/teacher/out/runs/alice/vacuum-seed1.log"), "vacuum-seed1.log");
  EXPECT_EQ(withoutPaths("{\"log\": \"/srv/x/y.log\", \"n\": 1}"), "{\"log\": \"y.log\", \"n\": 1}");
  EXPECT_EQ(withoutPaths("thrown at /tmp/aula-grade-1/alice/MyAlgorithm.cpp:12 (boom)"), "thrown at MyAlgorithm.cpp:12 (boom)");
  EXPECT_EQ(withoutPaths("--Vacuum.World=/usr/share/aula/worlds/vacuum.world"), "--Vacuum.World=vacuum.world");
  // Not paths: a unit, a fraction, a lone root.
  EXPECT_EQ(withoutPaths("0.35 m/s, 3/4 of it, / alone, /x"), "0.35 m/s, 3/4 of it, / alone, /x");
}

TEST(RunPageText, EveryDiagnosticOfAReport) {
  const auto r = nlohmann::json::parse(R"JSON({"mark": 1.0, "finished": false,
    "failure": "execute() threw std::runtime_error: boom", "algorithm_error": "execute() threw std::runtime_error: boom",
    "aborted": "component crashed (SIGSEGV)", "non_finite_commands": 2628, "tampering": {"VACUUM_POSE": 3},
    "escape_attempts": {"connect": 2}, "truth_gaps": {"VACUUM_BUMPER": 1}, "reloads": 1})JSON");
  const auto d = runDiagnostics(r);
  std::vector<std::string> kinds;
  for (const auto& x : d) kinds.push_back(x.kind);
  EXPECT_EQ(kinds, (std::vector<std::string>{"failed", "failed", "non-finite commands", "tampering", "escape", "lost messages",
                                             "reloaded"}));
  EXPECT_NE(d[0].text.find("boom"), std::string::npos);
  EXPECT_NE(d[1].text.find("aborted: component crashed (SIGSEGV)"), std::string::npos) << "the fault is said once, the abort too";
  EXPECT_NE(d[2].text.find("2628 motor commands were not finite numbers"), std::string::npos);
  EXPECT_NE(d[3].text.find("3 on VACUUM_POSE"), std::string::npos);
  EXPECT_NE(d[4].text.find("2 x connect"), std::string::npos);
  EXPECT_NE(d[5].text.find("1 on VACUUM_BUMPER"), std::string::npos);
  // A clean run: nothing; one that stopped early with no reason given: that it did.
  EXPECT_TRUE(runDiagnostics(nlohmann::json::parse(R"JSON({"mark": 7.0, "finished": true})JSON")).empty());
  EXPECT_EQ(runDiagnostics(nlohmann::json::parse(R"JSON({"mark": 7.0, "finished": false})JSON")).at(0).kind, "ended early");
}

// The class page flags a run with any diagnostic (non-finite commands too, not only a failure),
// links its picture beside it instead of inlining it, and sorts only the tables that sort.
TEST(RunPageText, TheClassPageFlagsEveryDiagnostic) {
  auto nan = nlohmann::json::parse(R"JSON({"student": "nina", "mark": 0.0, "finished": true, "world": "vacuum.world", "seed": 1,
    "non_finite_commands": 12, "log": "/t/out/runs/nina/vacuum-seed1.log"})JSON");
  auto good = nlohmann::json::parse(R"JSON({"student": "gus", "mark": 7.0, "finished": true, "world": "vacuum.world", "seed": 1,
    "log": "/t/out/runs/gus/vacuum-seed1.log"})JSON");
  aula::grade::StudentGrade g1, g2;
  g1.student = "gus";
  g2.student = "nina";
  const std::string html = aula::grade::reportHtml({g1, g2}, {good, nan});
  EXPECT_NE(html.find("Flagged runs (1)"), std::string::npos);
  EXPECT_NE(html.find("<tr data-student='nina' class='flagged'>"), std::string::npos);
  EXPECT_NE(html.find("<td class='why'>non-finite commands</td>"), std::string::npos);
  EXPECT_NE(html.find("12 motor commands were not finite numbers"), std::string::npos);
  EXPECT_NE(html.find("<a href='runs/nina/vacuum-seed1.html'>its page</a>"), std::string::npos);
  EXPECT_NE(html.find("name='viewport'"), std::string::npos);
  EXPECT_NE(html.find("table.sortable th:after"), std::string::npos);
  EXPECT_EQ(html.find("\nth:after"), std::string::npos) << "sort arrows on every table";
}

// A student's page names no path of the teacher's, and says what it can of a run that never ran.
TEST(RunPageText, AStudentsPage) {
  aula::grade::RunFiles run;
  run.report = nlohmann::json::parse(R"JSON({"student": "bea", "mark": 0.0, "finished": false, "world": "vacuum.world", "seed": 2,
    "failure": "compile error: /home/teacher/class/bea/MyAlgorithm.cpp:3: expected ';'", "log": "/home/teacher/out/runs/bea/x.log"})JSON");
  run.title = "bea, vacuum seed 2";
  const std::string html = aula::grade::runPageHtml(run);
  EXPECT_EQ(html.find("/home/teacher"), std::string::npos) << html;
  EXPECT_NE(html.find("MyAlgorithm.cpp:3: expected"), std::string::npos);
  EXPECT_EQ(html.find(": ?,"), std::string::npos) << "no '?' for an exercise the result does not name";
  EXPECT_NE(html.find("it stopped before the referee could trace it"), std::string::npos);
  EXPECT_NE(html.find("name='viewport'"), std::string::npos);
}
