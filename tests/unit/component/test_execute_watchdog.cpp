// The watchdog judges a call by what the call itself uses: the CPU time of the thread that runs
// it, and the time that thread spends blocked. Each test runs the call on a thread of its own and
// lets the watchdog flag it (Response::Flag, as with windows); none asserts how long anything took.

#include <aula/component/execute_watchdog.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>

#include <unistd.h>

using aula::component::CallBudget;
using aula::component::ExecuteWatchdog;
using aula::component::RunBudget;

namespace {

// Runs `body(stop)` as one armed call on a thread of its own, and returns why the watchdog gave it
// up ("" when the call returned first). `stop` tells the body to return (after a give-up).
template <class Body>
std::string judge(ExecuteWatchdog& watchdog, const CallBudget& budget, Body body) {
  std::atomic<bool> stop{false}, returned{false};
  std::thread call([&] {
    watchdog.arm("execute()", budget);
    body(stop);
    watchdog.disarm();
    returned = true;
  });
  std::string why;
  while (why.empty() && !returned) {
    if (watchdog.waitAbandoned(0.05)) why = watchdog.abandoned();
  }
  stop = true;
  call.join();
  return why;
}

void spin(std::atomic<bool>& stop) {
  volatile uint64_t n = 0;
  while (!stop) n = n + 1;
}

}  // namespace

TEST(ExecuteWatchdog, TheKernelTellsASleepingThreadFromAComputingOne) {
  std::atomic<bool> stop{false};
  std::atomic<pid_t> tid{0};
  std::thread sleeper([&] {
    tid = ::gettid();
    while (!stop) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  });
  while (tid == 0) std::this_thread::yield();
  bool seen_blocked = false;
  for (int i = 0; i < 100 && !seen_blocked; ++i) {
    seen_blocked = aula::component::threadBlocked(tid);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_TRUE(seen_blocked);
  stop = true;
  sleeper.join();
  EXPECT_FALSE(aula::component::threadBlocked(::gettid()));  // this thread runs: it is reading its state
}

TEST(ExecuteWatchdog, AnEndlessLoopIsCaughtByItsCPUTime) {
  ExecuteWatchdog watchdog("test", RunBudget{}, ExecuteWatchdog::Response::Flag);
  const std::string why = judge(watchdog, CallBudget{0.3, 0, "Component.ExecuteBudget"}, spin);
  EXPECT_EQ(why, "execute() used more than 0.3 s of CPU time (an endless loop?) (Component.ExecuteBudget)");
}

TEST(ExecuteWatchdog, ACallThatSleepsIsCaughtByItsBlockedTimeNotItsCPUTime) {
  ExecuteWatchdog watchdog("test", RunBudget{}, ExecuteWatchdog::Response::Flag);
  const std::string why = judge(watchdog, CallBudget{0.3, 0.5, "Component.ExecuteBudget"}, [](std::atomic<bool>& stop) {
    while (!stop) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  });
  EXPECT_EQ(why, "execute() was blocked (sleeping or waiting) for more than 0.5 s (Component.BlockedLimit)");
}

// Each call within its budget, all of them together past the run's: the run's budget says so.
TEST(ExecuteWatchdog, TheRunsBudgetCountsEveryCall) {
  ExecuteWatchdog watchdog("test", RunBudget{0.4, 0}, ExecuteWatchdog::Response::Flag);
  std::string why;
  for (int call = 0; call < 200 && why.empty(); ++call) {
    why = judge(watchdog, CallBudget{0.3, 0, "Component.ExecuteBudget"}, [](std::atomic<bool>& stop) {
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(100);
      volatile uint64_t n = 0;
      while (!stop && std::chrono::steady_clock::now() < deadline) n = n + 1;
    });
  }
  EXPECT_EQ(why, "the algorithm's calls used more than 0.4 s of CPU time in all (Component.RunBudget)");
}

TEST(ExecuteWatchdog, ACallThatReturnsIsNeverGivenUp) {
  ExecuteWatchdog watchdog("test", RunBudget{}, ExecuteWatchdog::Response::Flag);
  watchdog.arm("execute()", CallBudget{0.001, 0.001, "Component.ExecuteBudget"});
  watchdog.disarm();
  std::this_thread::sleep_for(std::chrono::milliseconds(120));  // two of the watchdog's samples
  EXPECT_EQ(watchdog.abandoned(), "");
}
