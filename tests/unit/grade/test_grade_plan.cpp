// aula grade's plan for a Python submission: a folder with MyAlgorithm.py and no MyAlgorithm.cpp
// is not compiled; its .py files are copied into OUT/build/<student>, and its runs load the copy.
#include <aula/grade/grade_plan.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace {

std::string scratch() {
  std::string pattern = (fs::temp_directory_path() / "aula_grade_plan_XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

}  // namespace

TEST(GradePlan, APythonFolderIsNotCompiledAndItsRunsLoadACopyOfItsFile) {
  const fs::path root = scratch();
  fs::create_directories(root / "ana");
  std::ofstream(root / "ana" / "MyAlgorithm.py") << "from helpers import speed\n";
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
