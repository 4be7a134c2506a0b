// The supervised run's rules on plain data: budgets, CPU choice, what each exit means, and the
// report written for a referee that cannot write one.
#include <aula/config/config.hpp>
#include <aula/process/exit_codes.hpp>
#include <aula/supervision/rules.hpp>

#include <gtest/gtest.h>

#include <csignal>

namespace {
using namespace aula::supervision;

TEST(SupervisionRules, TheWallBudgetIsTheEpisodeAtRealTimeHalfAgainPlusAMinute) {
  EXPECT_DOUBLE_EQ(defaultWallBudget(900, 0), 60 + 1350);
  EXPECT_DOUBLE_EQ(defaultWallBudget(900, 4), 60 + 1350);   // faster than real time: the same budget
  EXPECT_DOUBLE_EQ(defaultWallBudget(100, 0.5), 60 + 300);  // slower: more
}

TEST(SupervisionRules, CpuChoice) {
  EXPECT_EQ(chooseCpu("auto", {0, 1}, 1), 1);
  EXPECT_EQ(chooseCpu("any", {0, 1}, 1), -1);
  EXPECT_EQ(chooseCpu("0", {0, 1}, 1), 0);
  EXPECT_EQ(chooseCpu("auto", {}, -1), -1);
  try {
    chooseCpu("7", {0, 1}, 1);
    FAIL() << "a CPU not allowed was taken";
  } catch (const aula::config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("--cpu=7: one of the CPUs this process may use (0,1)"), std::string::npos) << e.what();
  }
}

TEST(SupervisionRules, ExitCodesInWords) {
  EXPECT_EQ(signalName(128 + SIGSEGV), "SIGSEGV");
  EXPECT_EQ(signalName(1), "exit code 1");
  EXPECT_EQ(componentFault(128 + SIGSEGV), "component crashed (SIGSEGV)");
  EXPECT_EQ(componentFault(aula::process::kExitAlgorithmHung), "a call into the algorithm overran its budget");
  EXPECT_EQ(componentFault(0), "");
  EXPECT_EQ(componentFault(aula::process::kExitAlgorithmExited), "the algorithm ended the component (exit() inside execute())");
  EXPECT_EQ(componentFault(128 + SIGXFSZ), "the algorithm wrote a file larger than the sandbox allows (SIGXFSZ)");
  EXPECT_EQ(componentFault(aula::process::kExitAlgorithmForbidden), "the algorithm tried what no student's algorithm may");
}

ExitEvent exitOf(Role role, int code) {
  ExitEvent e;
  e.role = role;
  e.code = code;
  return e;
}

TEST(SupervisionRules, ACrashedComponentIsTheRefereesToGrade) {
  const ExitVerdict v = onExit(exitOf(Role::Component, 128 + SIGSEGV), "vacuum-cleaner");
  EXPECT_EQ(v.tell_referee, "component crashed (SIGSEGV)");
  EXPECT_FALSE(v.run_over);  // the referee grades what there is and ends the run
  EXPECT_EQ(v.result.value_or(-1), 1);
  // Once the referee knows, the component's exit is not a failure of its own.
  ExitEvent told = exitOf(Role::Component, 128 + SIGSEGV);
  told.referee_told = true;
  EXPECT_TRUE(onExit(told, "vacuum-cleaner").message.empty());
}

// The component's own line says where its crash struck, in the student's lines: the launcher
// says it and hands it to the referee as the algorithm's fault; the abort's reason stays the
// exit code's. The line is the student's process's: believed only for the signal it died of.
TEST(SupervisionRules, ACrashInTheStudentsLinesIsSaidWhereItStruck) {
  ExitEvent e = exitOf(Role::Component, 128 + SIGSEGV);
  e.crash_line = "crashed (SIGSEGV) at MyAlgorithm.cpp:14 (MyAlgorithm::execute)";
  const ExitVerdict v = onExit(e, "vacuum-cleaner");
  EXPECT_EQ(v.tell_referee, "component crashed (SIGSEGV)");
  EXPECT_EQ(v.algorithm_fault, "component crashed (SIGSEGV) at MyAlgorithm.cpp:14 (MyAlgorithm::execute)");
  EXPECT_EQ(crashInStudentLines("component crashed (SIGBUS)", e.crash_line), "");  // another signal
  EXPECT_EQ(crashInStudentLines("component crashed (SIGSEGV)", "crashed (SIGSEGV)"), "");  // no line found
  EXPECT_EQ(crashInStudentLines("execute() did not return within 2 s", e.crash_line), "");
  EXPECT_EQ(crashInStudentLines("component crashed (SIGSEGV)", "crashed (SIGSEGV) at " + std::string(1000, 'x')).size(),
            std::string("component ").size() + 300);
  EXPECT_EQ(onExit(exitOf(Role::Component, 128 + SIGSEGV), "vacuum-cleaner").algorithm_fault, "");
}

// A call past its budget: the component's watchdog says which budget on its private line, and
// that is the fault handed to the referee (only for the exit code of an overrun).
TEST(SupervisionRules, AnOverrunIsSaidWithTheBudgetItOverran) {
  ExitEvent e = exitOf(Role::Component, aula::process::kExitAlgorithmHung);
  e.crash_line = "overran execute() used more than 2 s of CPU time (an endless loop?) (Component.ExecuteBudget)";
  EXPECT_EQ(onExit(e, "vacuum-cleaner").tell_referee,
            "execute() used more than 2 s of CPU time (an endless loop?) (Component.ExecuteBudget)");
  e.crash_line.clear();
  EXPECT_EQ(onExit(e, "vacuum-cleaner").tell_referee, "a call into the algorithm overran its budget");
  e = exitOf(Role::Component, 128 + SIGSEGV);
  e.crash_line = "overran execute() used more than 2 s of CPU time";  // another exit: not believed
  EXPECT_EQ(onExit(e, "vacuum-cleaner").tell_referee, "component crashed (SIGSEGV)");
}

// _exit(0) or quick_exit(0) in the student's code (no atexit handler runs), or exit(0) from a
// thread of its own: a headless component never ends with 0 on its own in the middle of a run.
TEST(SupervisionRules, AHeadlessComponentEndingWithZeroMidRunIsTheAlgorithms) {
  const ExitVerdict v = onExit(exitOf(Role::Component, 0), "vacuum-cleaner");
  EXPECT_EQ(v.tell_referee, kAlgorithmEndedMidRun);
  EXPECT_NE(v.tell_referee.find("the algorithm ended the component"), std::string::npos);
  EXPECT_FALSE(v.run_over);  // the referee grades what there is and ends the run
  EXPECT_EQ(v.result.value_or(-1), 1);
  // Told to end (the run's end, the limits), its 0 is nobody's fault.
  ExitEvent told = exitOf(Role::Component, 0);
  told.referee_told = true;
  EXPECT_TRUE(onExit(told, "vacuum-cleaner").tell_referee.empty());
  EXPECT_TRUE(onExit(told, "vacuum-cleaner").message.empty());
  // Without a referee (the demo) there is no run to grade.
  ExitEvent demo = exitOf(Role::Component, 0);
  demo.has_referee = false;
  EXPECT_TRUE(onExit(demo, "aula-demo-client").tell_referee.empty());
}

// A component's tripwire (a reference's factory called) said what was tried on its private line:
// the failure names it; a component that did not say keeps the general reason.
TEST(SupervisionRules, AForbiddenTryIsNamedInTheFailure) {
  ExitEvent e = exitOf(Role::Component, aula::process::kExitAlgorithmForbidden);
  e.refused = "call makeReferenceAlgorithm, the reference";
  const ExitVerdict v = onExit(e, "vacuum-cleaner");
  EXPECT_EQ(v.tell_referee, "the algorithm tried to call makeReferenceAlgorithm, the reference, which no student's algorithm may");
  EXPECT_FALSE(v.run_over);  // the referee grades what there is and ends the run
  EXPECT_EQ(onExit(exitOf(Role::Component, aula::process::kExitAlgorithmForbidden), "vacuum-cleaner").tell_referee,
            "the algorithm tried what no student's algorithm may");
  // A refused system call before a crash does not rename the crash.
  ExitEvent crash = exitOf(Role::Component, 128 + SIGSEGV);
  crash.refused = "mount";
  EXPECT_EQ(onExit(crash, "vacuum-cleaner").tell_referee, "component crashed (SIGSEGV)");
}

// Killed from outside the run (the out-of-memory killer), the simulator or the component: the
// machine's reason, which a grade runs again; never a crash of the student's.
TEST(SupervisionRules, AProcessKilledFromOutsideIsTheMachinesReason) {
  EXPECT_EQ(onExit(exitOf(Role::Component, 128 + SIGKILL), "vacuum-cleaner").tell_referee,
            "the machine's reason: the component was killed (SIGKILL) from outside the run");
  const ExitVerdict sim = onExit(exitOf(Role::Simulator, 128 + SIGKILL), "aula-sim");
  EXPECT_EQ(sim.tell_referee, "the machine's reason: aula-sim died (SIGKILL)");
  EXPECT_FALSE(sim.run_over);  // the referee grades what there is and says why, then the run ends
  ExitEvent ended = exitOf(Role::Simulator, 1);
  ended.simulator_ended_run = true;  // it said why it ended the run: that reason stands
  EXPECT_TRUE(onExit(ended, "aula-sim").tell_referee.empty());
}

TEST(SupervisionRules, ADeadRefereeLeavesAReportWithNoMark) {
  const ExitVerdict v = onExit(exitOf(Role::Referee, 128 + SIGKILL), "vacuum-cleaner-referee");
  EXPECT_EQ(v.aborted_report, "the machine's reason: vacuum-cleaner-referee died (SIGKILL)");
  EXPECT_TRUE(v.run_over);
  const auto report = abortedReport("vacuum", "reference", v.aborted_report);
  EXPECT_EQ(report["finished"], false);
  EXPECT_EQ(report["aborted"], "the machine's reason: vacuum-cleaner-referee died (SIGKILL)");
  EXPECT_FALSE(report.contains("mark"));
}

TEST(SupervisionRules, UsageErrorsAreExitTwoAndTheRunIsDiscarded) {
  const ExitVerdict v = onExit(exitOf(Role::Component, aula::process::kExitUsage), "vacuum-cleaner");
  EXPECT_TRUE(v.discard);
  EXPECT_TRUE(v.run_over);
  EXPECT_EQ(v.result.value_or(-1), 2);
}

TEST(SupervisionRules, AClosedWindowEndsTheRunCleanly) {
  ExitEvent closed = exitOf(Role::Component, 0);
  closed.headless = false;
  const ExitVerdict v = onExit(closed, "teletaxi");
  EXPECT_TRUE(v.run_over);
  EXPECT_FALSE(v.result.has_value());
}

TEST(SupervisionRules, TheRefereesEndIsTheRunsEnd) {
  ExitEvent done = exitOf(Role::Referee, 0);
  done.last_child = true;
  EXPECT_TRUE(onExit(done, "r").run_over);
  EXPECT_EQ(onExit(exitOf(Role::Referee, aula::process::kExitFailed), "r").result.value_or(-1), 1);
  ExitEvent ended = exitOf(Role::Simulator, 1);
  ended.simulator_ended_run = true;
  EXPECT_FALSE(onExit(ended, "aula-sim").run_over);  // the referee grades and ends the run
}

}  // namespace
