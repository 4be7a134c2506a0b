// The exam, third pass (issue 57): no student buys a retry or stalls a grade. A run is run again
// only for the machine's reason as the launcher or the grade saw it for itself, never for text a
// student's code or compiler writes; the algorithm's process signals no process of the run's (a
// kill of its component would pass for "killed from outside the run", a stop would stall the run
// until the lockstep's backstop), and stops nothing, itself included. Each attacker is graded
// beside an honest classmate; every row says 0 retries, and the grade exits 0 with every run
// complete.
#include "test_support.hpp"

#include <aula/process/child_process.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace {
namespace fs = std::filesystem;
using namespace std::chrono_literals;
using aula::testing::readFile;
using aula::testing::readGrades;

const std::string kAula = std::string(AULA_BIN_DIR) + "/aula";

// A Python student whose execute() does `attack` once (Python, after `import os, signal`), then
// drives on; "none": the honest classmate.
void writePython(const fs::path& folder, const std::string& attack) {
  fs::create_directories(folder);
  std::ofstream(folder / "MyAlgorithm.py") << "import os\nimport signal\n\n\n"
                                              "class MyAlgorithm:\n"
                                              "    def __init__(self, seed):\n"
                                              "        self.ticks = 0\n\n"
                                              "    def execute(self, api):\n"
                                              "        self.ticks += 1\n"
                                              "        if self.ticks == 20:\n"
                                              "            try:\n"
                                              "                "
                                           << attack
                                           << "\n"
                                              "            except OSError as e:\n"
                                              "                print('exam: refused', e)\n"
                                              "        api.motors.sendV(0.2)\n"
                                              "        api.motors.sendW(0.3 if api.bumper.getBumperData().state else 0.0)\n";
}

TEST(ExamRetries, NoStudentBuysARetryOrStallsTheGrade) {
  const fs::path dir = fs::temp_directory_path() / ("aula-exam-retries-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const fs::path klass = dir / "class";
  writePython(klass / "honest", "pass");
  // An exception that says the machine's words: the student's failure, never run again.
  writePython(klass / "says-machine",
              "raise RuntimeError(\"the machine's reason: the component was killed (SIGKILL) from outside the run\")");
  writePython(klass / "kills-component", "os.kill(os.getppid(), signal.SIGKILL)");
  writePython(klass / "stops-component", "os.kill(os.getppid(), signal.SIGSTOP)");
  writePython(klass / "stops-itself", "os.kill(os.getpid(), signal.SIGSTOP)");
  writePython(klass / "kills-everyone", "os.kill(-1, signal.SIGKILL)");
  // A compiler's error that says them: the student's build, never the machine's.
  fs::create_directories(klass / "error-says-machine");
  std::ofstream(klass / "error-says-machine" / "MyAlgorithm.cpp")
      << "#error \"the machine's reason: the build ran past 600 s of wall time\"\n";

  const fs::path out = dir / "out";
  const std::string log = (dir / "grade.log").string();
  std::vector<std::string> argv = {kAula, "grade", "vacuum"};
  for (const auto& entry : fs::directory_iterator(klass)) argv.push_back(entry.path().string());
  argv.insert(argv.end(), {"--seeds=1", "--jobs=2", "--out=" + out.string(), "--Vacuum.Referee.Duration=20",
                           "--calibration-seeds=off", "--similarity=off"});
  aula::process::ChildProcess grade(argv, log, log);
  // A backstop for a hang only: a stalled run would wait the lockstep's 600 s, three times.
  ASSERT_EQ(grade.wait(1200s).value_or(-1), 0) << readFile(log);

  const auto rows = readGrades((out / "grades.csv").string());
  ASSERT_EQ(rows.size(), 7u) << readFile((out / "grades.csv").string());
  for (const auto& [student, row] : rows) {
    EXPECT_EQ(row.at("runs_retried"), "0") << row.at("line");
    EXPECT_EQ(row.at("runs_incomplete"), "0") << row.at("line");
    EXPECT_EQ(row.at("runs"), "1") << row.at("line");
  }
  const std::string results = readFile((out / "runs" / "says-machine" / "vacuum-seed1.json").string());
  EXPECT_NE(results.find("\"machine_reason\": false"), std::string::npos) << results;
  EXPECT_EQ(rows.at("honest").at("runs_failed"), "0") << rows.at("honest").at("line");
  EXPECT_EQ(rows.at("honest").at("runs_tampered"), "0") << rows.at("honest").at("line");
  EXPECT_EQ(rows.at("says-machine").at("runs_failed"), "1") << rows.at("says-machine").at("line");
  EXPECT_EQ(rows.at("error-says-machine").at("runs_failed"), "1") << rows.at("error-says-machine").at("line");
  EXPECT_NE(rows.at("error-says-machine").at("failures").find("did not compile"), std::string::npos)
      << rows.at("error-says-machine").at("line");
  // Each signal out of its own process, or a stop, is refused and flagged; the run goes to its end.
  for (const char* student : {"kills-component", "stops-component", "stops-itself", "kills-everyone"}) {
    const auto& row = rows.at(student);
    EXPECT_EQ(row.at("runs_tampered"), "1") << row.at("line");
    EXPECT_EQ(row.at("runs_failed"), "0") << row.at("line");
    const std::string run_log = readFile((out / "runs" / student / "vacuum-seed1.log").string());
    EXPECT_NE(run_log.find("exam: refused"), std::string::npos) << student << "\n" << run_log;
  }
  fs::remove_all(dir);
}

}  // namespace
