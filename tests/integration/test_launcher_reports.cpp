// The launcher's report rules: a stale report never passes for a new run's, a dead referee
// leaves a report that says so (and no mark), Ctrl-C is exit 130, a headless run past its
// wall-clock budget ends with the reason, and a graded run never goes on without a client that
// stopped acking (the simulator ends it, and the report says which and for how long); outside
// grading, the simulator waits for a stopped client as long as its process lives. A headless
// run's three processes share one CPU (--cpu), or go where the kernel puts them (--cpu=any), as
// batch tasks.
#include <aula/process/child_process.hpp>
#include <aula/process/cpu_affinity.hpp>
#include <aula/process/exit_codes.hpp>

#include "test_support.hpp"

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>

#include <sched.h>

namespace fs = std::filesystem;
using aula::process::ChildProcess;
using aula::testing::privateDir;
using aula::testing::privateLcmUrl;
using aula::testing::readFile;
using namespace std::chrono_literals;

namespace {

const std::string kAula = std::string(AULA_BIN_DIR) + "/aula";

// The pid of `parent`'s child whose program is `name` (its path's last part), or -1.
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
    const std::string cmdline = readFile((entry.path() / "cmdline").string());
    const std::string program = cmdline.substr(0, cmdline.find('\0'));
    if (fs::path(program).filename() == name) return std::stoi(pid);
  }
  return -1;
}

// Stops `pid` (SIGSTOP) for `how_long`: a breakpoint, a machine that stalls a process.
void stopFor(pid_t pid, std::chrono::milliseconds how_long) {
  ::kill(pid, SIGSTOP);
  std::this_thread::sleep_for(how_long);
  ::kill(pid, SIGCONT);
}

pid_t waitForChild(pid_t parent, const std::string& name) {
  pid_t child = -1;
  for (int i = 0; i < 100 && child < 0; ++i) {
    std::this_thread::sleep_for(100ms);
    child = childNamed(parent, name);
  }
  return child;
}

std::vector<std::string> slowRun(const std::string& report) {
  return {kAula, "run", "vacuum", "--headless", "--rtf=1", "--Vacuum.Referee.Duration=60", "--report=" + report,
          "--lcm-url=" + privateLcmUrl()};
}

}  // namespace

// /proc/PID/status's Cpus_allowed_list: "1", "0-1"...
std::string cpusAllowed(pid_t pid) {
  std::smatch m;
  const std::string status = readFile("/proc/" + std::to_string(pid) + "/status");
  return std::regex_search(status, m, std::regex("Cpus_allowed_list:\\s*(\\S+)")) ? m[1].str() : "?";
}

TEST(LauncherReports, AHeadlessRunsProcessesShareOneCpu) {
  const std::vector<int> allowed = aula::process::allowedCpus();
  ASSERT_FALSE(allowed.empty());
  const std::string dir = privateDir(), report = dir + "/r.json", out = dir + "/out.txt";
  for (const std::string& choice : {std::to_string(allowed.back()), std::string("any")}) {
    std::vector<std::string> argv = slowRun(report);
    argv.push_back("--cpu=" + choice);
    ChildProcess run(argv, out, out);
    for (const char* program : {"aula-sim", "vacuum-cleaner", "vacuum-cleaner-referee"}) {
      const pid_t child = waitForChild(run.pid(), program);
      ASSERT_GT(child, 0) << program << " never started:\n" << readFile(out);
      EXPECT_EQ(sched_getscheduler(child), SCHED_BATCH) << program << ": woken, it would preempt the one that woke it";
      const std::string cpus = cpusAllowed(child);
      if (choice == "any") {
        EXPECT_EQ(cpus, cpusAllowed(getpid())) << program << ": --cpu=any leaves the processes where they may go";
      } else {
        EXPECT_EQ(cpus, choice) << program << " does not run on the one CPU asked for";
      }
    }
    run.stop();
  }
  ChildProcess wrong({kAula, "run", "vacuum", "--headless", "--cpu=" + std::to_string(CPU_SETSIZE + 1)}, out, out);
  EXPECT_EQ(wrong.wait(30s).value_or(-1), 2) << readFile(out);
  EXPECT_NE(readFile(out).find("one of the CPUs this process may use (" + aula::process::cpuList(allowed) + ")"),
            std::string::npos)
      << readFile(out);
  fs::remove_all(dir);
}

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
  EXPECT_EQ(run.wait(30s).value_or(-1), aula::process::kExitMachine) << readFile(out);
  const std::string json = readFile(report);
  EXPECT_NE(json.find("\"aborted\": \"the machine's reason: vacuum-cleaner-referee died (SIGKILL)\""), std::string::npos) << json;
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
  ChildProcess run(argv, out, out);
  EXPECT_EQ(run.wait(120s).value_or(-1), aula::process::kExitMachine) << readFile(out);
  const std::string json = readFile(report);
  EXPECT_NE(json.find("the machine's reason: the run's wall-clock backstop of 3 s ran out"), std::string::npos)
      << json << readFile(out);
  EXPECT_NE(json.find("\"finished\": false"), std::string::npos) << json;
  fs::remove_all(dir);
}

// Stopped for 3 s (SIGSTOP, then SIGCONT: a starved machine, a debugger), any of the three
// processes of a graded run is waited for, and its report is byte-identical to the same run's
// undisturbed, which runs beside it on a bus of its own (the default): no wall-clock limit decides
// a run, and two runs on one machine never meet.
class StoppedProcess : public ::testing::TestWithParam<const char*> {};

TEST_P(StoppedProcess, IsWaitedForAndTheReportIsTheSame) {
  const std::string dir = privateDir();
  auto runTo = [](const std::string& report) {
    return std::vector<std::string>{kAula, "run", "vacuum", "--headless", "--rtf=1", "--Vacuum.Referee.Duration=8",
                                    "--algorithm=reference", "--seed=1", "--report=" + report};
  };
  ChildProcess calm(runTo(dir + "/calm.json"), dir + "/calm.txt", dir + "/calm.txt");
  ChildProcess stopped(runTo(dir + "/stopped.json"), dir + "/stopped.txt", dir + "/stopped.txt");
  // "a/b": the child b of the launcher's child a (the algorithm's own process, the component's child).
  const std::string path = GetParam();
  pid_t process = stopped.pid();
  for (size_t from = 0; from != std::string::npos && process > 0;) {
    const size_t to = path.find('/', from);
    process = waitForChild(process, path.substr(from, to == std::string::npos ? std::string::npos : to - from));
    from = to == std::string::npos ? to : to + 1;
  }
  ASSERT_GT(process, 0) << readFile(dir + "/stopped.txt");
  std::this_thread::sleep_for(1s);
  stopFor(process, 3s);
  EXPECT_EQ(calm.wait(300s).value_or(-1), 0) << readFile(dir + "/calm.txt");
  EXPECT_EQ(stopped.wait(300s).value_or(-1), 0) << readFile(dir + "/stopped.txt");
  const std::string report = readFile(dir + "/calm.json");
  EXPECT_NE(report.find("\"finished\": true"), std::string::npos) << report;
  EXPECT_EQ(report.find("tampering"), std::string::npos) << report;
  EXPECT_EQ(readFile(dir + "/stopped.json"), report);
  fs::remove_all(dir);
}

std::string stoppedName(size_t index) {
  const char* names[] = {"Simulator", "Component", "Referee", "AlgorithmsOwnProcess"};
  return names[index];
}

INSTANTIATE_TEST_SUITE_P(LauncherReports, StoppedProcess,
                         ::testing::Values("aula-sim", "vacuum-cleaner", "vacuum-cleaner-referee", "vacuum-cleaner/vacuum-cleaner"),
                         [](const auto& info) { return stoppedName(info.index); });

// Simulator.Lockstep.DropAfterMs is only a starved machine's backstop: past it a graded run ends
// for the machine's reason, never the student's (aula grade runs it again).
TEST(LauncherReports, ASilentClientPastTheBackstopIsTheMachinesReason) {
  const std::string dir = privateDir(), report = dir + "/r.json", out = dir + "/out.txt";
  auto argv = slowRun(report);
  argv.push_back("--Simulator.Lockstep.DropAfterMs=1000");
  ChildProcess run(argv, out, out);
  const pid_t client = waitForChild(run.pid(), "vacuum-cleaner");
  ASSERT_GT(client, 0) << readFile(out);
  std::this_thread::sleep_for(1s);
  stopFor(client, 4s);
  EXPECT_EQ(run.wait(120s).value_or(-1), aula::process::kExitMachine) << readFile(out);
  const std::string json = readFile(report);
  EXPECT_NE(json.find("\"aborted\": \"the machine's reason: lockstep client 'vacuum-cleaner' silent for 1."), std::string::npos)
      << json << readFile(out);
  EXPECT_NE(json.find("\"finished\": false"), std::string::npos) << json;
  fs::remove_all(dir);
}

// A component killed from outside the run (SIGKILL: the out-of-memory killer) is the machine's
// reason, never the student's crash.
TEST(LauncherReports, AComponentKilledFromOutsideIsTheMachinesReason) {
  const std::string dir = privateDir(), report = dir + "/r.json", out = dir + "/out.txt";
  ChildProcess run(slowRun(report), out, out);
  const pid_t component = waitForChild(run.pid(), "vacuum-cleaner");
  ASSERT_GT(component, 0) << readFile(out);
  std::this_thread::sleep_for(1s);
  ::kill(component, SIGKILL);
  EXPECT_EQ(run.wait(120s).value_or(-1), aula::process::kExitMachine) << readFile(out);
  const std::string json = readFile(report);
  EXPECT_NE(json.find("\"aborted\": \"the machine's reason: the component was killed (SIGKILL) from outside the run\""),
            std::string::npos)
      << json << readFile(out);
  EXPECT_EQ(json.find("algorithm_error"), std::string::npos) << json;
  fs::remove_all(dir);
}

// Outside grading (three terminals, windows: no key), a component stopped in a debugger is waited
// for as long as its process lives: the run goes on when it resumes and finishes as usual.
TEST(LauncherReports, OutsideGradingAStoppedComponentIsWaitedFor) {
  const std::string dir = privateDir(), report = dir + "/r.json";
  const std::string bin = AULA_BIN_DIR, url = "--lcm-url=" + privateLcmUrl();
  const std::string worlds = std::string(AULA_SOURCE_DIR) + "/worlds/";
  ChildProcess sim({bin + "/aula-sim", worlds + "vacuum.world", "--lockstep", "--Simulator.Lockstep.WaitForClients=2",
                    "--Simulator.Lockstep.DropAfterMs=1000", "--rtf=1", url},
                   dir + "/sim.log", dir + "/sim.log");
  ChildProcess component({bin + "/vacuum-cleaner", "--headless", url, "--Vacuum.Algorithm=reference",
                          "--Vacuum.Autostart=true"},
                         dir + "/component.log", dir + "/component.log");
  ChildProcess referee({bin + "/vacuum-cleaner-referee", "--headless", url, "--Vacuum.Referee.Duration=6",
                        "--report=" + report},
                       dir + "/referee.log", dir + "/referee.log");
  std::this_thread::sleep_for(1500ms);
  stopFor(component.pid(), 3500ms);  // 3.5 times Simulator.Lockstep.DropAfterMs
  EXPECT_EQ(referee.wait(60s).value_or(-1), 0) << readFile(dir + "/referee.log") << readFile(dir + "/sim.log")
                                               << readFile(dir + "/component.log");
  const std::string json = readFile(report);
  EXPECT_NE(json.find("\"finished\": true"), std::string::npos) << json;
  EXPECT_EQ(json.find("aborted"), std::string::npos) << json;
  const std::string sim_log = readFile(dir + "/sim.log");
  EXPECT_NE(sim_log.find("silent for"), std::string::npos) << sim_log;
  EXPECT_NE(sim_log.find("waiting while its process"), std::string::npos) << sim_log;
  EXPECT_EQ(sim_log.find("dropped"), std::string::npos) << sim_log;
  component.stop();
  sim.stop();
  fs::remove_all(dir);
}
