// The launcher's report rules: a stale report never passes for a new run's, a dead referee
// leaves a report that says so (and no mark), Ctrl-C is exit 130, and a headless run past its
// wall-clock budget ends with the reason.
#include <aula/process/child_process.hpp>

#include "test_support.hpp"

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

namespace fs = std::filesystem;
using aula::process::ChildProcess;
using aula::testing::privateDir;
using aula::testing::privateLcmUrl;
using aula::testing::readFile;
using namespace std::chrono_literals;

namespace {

const std::string kAula = std::string(AULA_BIN_DIR) + "/aula";

// The pid of `parent`'s child whose command line contains `name`, or -1.
pid_t childNamed(pid_t parent, const std::string& name) {
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string pid = entry.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(entry.path() / "stat");
    std::string line;
    std::getline(stat, line);
    const auto close_paren = line.rfind(')');
    if (close_paren == std::string::npos) continue;
    std::istringstream rest(line.substr(close_paren + 2));
    char state = 0;
    pid_t ppid = -1;
    rest >> state >> ppid;
    if (ppid != parent) continue;
    if (readFile((entry.path() / "cmdline").string()).find(name) != std::string::npos) return std::stoi(pid);
  }
  return -1;
}

std::vector<std::string> slowRun(const std::string& report) {
  return {kAula, "run", "vacuum", "--headless", "--rtf=1", "--Vacuum.Referee.Duration=60", "--report=" + report,
          "--lcm-url=" + privateLcmUrl()};
}

}  // namespace

TEST(LauncherReports, AStaleReportIsRemovedEvenWhenTheRunNeverStarts) {
  const std::string dir = privateDir(), report = dir + "/r.json", out = dir + "/out.txt";
  std::ofstream(report) << "{\"mark\": 10}\n";
  ChildProcess run({kAula, "run", "vacuum", "--headless", "--Vacuum.MaxV=9", "--report=" + report}, out, out);
  EXPECT_EQ(run.wait(30s).value_or(-1), 2) << readFile(out);
  EXPECT_FALSE(fs::exists(report)) << "the old report is still there: " << readFile(report);
  fs::remove_all(dir);
}

TEST(LauncherReports, ADeadRefereeLeavesAReportWithoutAMark) {
  const std::string dir = privateDir(), report = dir + "/r.json", out = dir + "/out.txt";
  ChildProcess run(slowRun(report), out, out);
  pid_t referee = -1;
  for (int i = 0; i < 100 && referee < 0; ++i) {
    std::this_thread::sleep_for(100ms);
    referee = childNamed(run.pid(), "vacuum-cleaner-referee");
  }
  ASSERT_GT(referee, 0) << readFile(out);
  std::this_thread::sleep_for(1s);
  ::kill(referee, SIGKILL);
  EXPECT_EQ(run.wait(30s).value_or(-1), 1) << readFile(out);
  const std::string json = readFile(report);
  EXPECT_NE(json.find("\"aborted\": \"vacuum-cleaner-referee died (SIGKILL)\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"finished\": false"), std::string::npos) << json;
  EXPECT_EQ(json.find("\"mark\""), std::string::npos) << json;
  EXPECT_NE(readFile(out).find("died (SIGKILL): the run has no mark"), std::string::npos) << readFile(out);
  fs::remove_all(dir);
}

TEST(LauncherReports, CtrlCIsExit130) {
  const std::string dir = privateDir(), report = dir + "/r.json", out = dir + "/out.txt";
  ChildProcess run(slowRun(report), out, out);
  std::this_thread::sleep_for(3s);
  ::kill(run.pid(), SIGINT);
  EXPECT_EQ(run.wait(30s).value_or(-1), 130) << readFile(out);
  EXPECT_EQ(childNamed(run.pid(), "aula-sim"), -1);
  fs::remove_all(dir);
}

TEST(LauncherReports, ARunPastItsWallClockBudgetEndsWithTheReason) {
  const std::string dir = privateDir(), report = dir + "/r.json", out = dir + "/out.txt";
  auto argv = slowRun(report);
  argv.push_back("--timeout=3");
  const auto started = std::chrono::steady_clock::now();
  ChildProcess run(argv, out, out);
  EXPECT_EQ(run.wait(60s).value_or(-1), 1) << readFile(out);
  EXPECT_LT(std::chrono::steady_clock::now() - started, 30s);
  const std::string json = readFile(report);
  EXPECT_NE(json.find("wall-clock budget of 3 s ran out"), std::string::npos) << json << readFile(out);
  EXPECT_NE(json.find("\"finished\": false"), std::string::npos) << json;
  fs::remove_all(dir);
}
