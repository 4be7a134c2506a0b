#pragma once
// Catches a call into the student's code that never ends, by what the call itself uses, never by
// how long the machine takes: the CPU time of the thread that runs it (an endless loop), and the
// wall time that thread spends blocked (sleeping, waiting on a lock or a file). A thread that is
// only waiting for a CPU (a busy machine) accrues neither, so a mark never depends on the load.
// A thread of its own samples the call every 50 ms; the caller's arm()/disarm() only record.
// Budgets are per call (execute(), generatePath(), creating the algorithm) and per run (all the
// calls together): Component.ExecuteBudget, PlanBudget, StartBudget, BlockedLimit, RunBudget.
// An algorithm that can be interrupted (a Python file) is interrupted first: the call raises
// inside the student's loop, naming its line, and returns as a fault; only a call still running
// after kInterruptGraceS more of its own time is given up. Given up, headless: the process ends
// (its reason on the launcher's private line, exit code kExitAlgorithmHung); with windows
// (Response::Flag): abandoned() says why, and the waiting caller abandons the call.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include <pthread.h>
#include <sys/types.h>

namespace aula::component {

// What one call may use; 0 or less: no limit. `setting` names the CPU budget's setting.
struct CallBudget {
  double cpu_s = 0;
  double blocked_s = 0;
  const char* setting = "Component.ExecuteBudget";
};

// What all the calls of a run may use together; 0 or less: no limit.
struct RunBudget {
  double cpu_s = 0;
  double blocked_s = 0;
};

// What the student's calls may use (the Component.*Budget settings): creating the algorithm
// (loading the file, its imports, the constructor or __init__), each execute(), each call that
// plans (TeleTaxi's generatePath()), and all of them over the run.
struct AlgorithmBudgets {
  CallBudget start{60, 10, "Component.StartBudget"};
  CallBudget execute{2, 10, "Component.ExecuteBudget"};
  CallBudget plan{60, 10, "Component.PlanBudget"};
  RunBudget run{600, 60};
  // The address space the algorithm's own process may map (RLIMIT_AS, Component.Sandbox.Memory),
  // in every run, sandboxed or not: a plain `aula run` of a runaway Python program stops there,
  // not at the machine's memory. 0: no limit of its own.
  uint64_t memory_bytes = 0;
};

// Which budget a call has.
enum class CallKind { Execute, Plan };

// Where a thread is, as the kernel says (/proc/self/task/TID/stat): blocked means sleeping or
// waiting (S, D), never runnable (R, waiting for a CPU or on one).
bool threadBlocked(pid_t tid);
// The CPU time a thread of this process has used, in ns (its pthread CPU clock).
int64_t threadCpuNs(pthread_t thread);

class ExecuteWatchdog {
 public:
  enum class Response { EndProcess, Flag };
  ExecuteWatchdog(std::string program, RunBudget run_budget, Response response = Response::EndProcess);
  ~ExecuteWatchdog();
  ExecuteWatchdog(const ExecuteWatchdog&) = delete;
  ExecuteWatchdog& operator=(const ExecuteWatchdog&) = delete;

  // How much more of its own time (CPU or blocked) an interrupted call has to return.
  static constexpr double kInterruptGraceS = 1.0;

  // A call begins on the calling thread; `what` is a string literal naming it ("execute()").
  void arm(const char* what, const CallBudget& budget);
  void disarm();  // it returned (on the same thread)
  // The algorithm's interrupter (PluginLibrary::interrupter), or empty: set between calls.
  void setInterrupter(std::function<void(const std::string&)> interrupter);
  void setResponse(Response response);
  // With Response::Flag: why the current call was given up, or "" (cleared by arm()).
  std::string abandoned() const;
  // Waits (up to `s` wall seconds) for abandoned() or for the call to be disarmed; true when
  // abandoned. For a caller that waits on another thread's call.
  bool waitAbandoned(double s);

  // Totals so far (calls that returned), for logs and tests.
  double runCpuS() const;
  double runBlockedS() const;

 private:
  void watch();
  // With mutex_ held: samples the armed call; its overrun text, or "".
  std::string sampleLocked(int64_t now_ns);
  void giveUp(const std::string& why);

  std::string program_;
  RunBudget run_budget_;
  mutable std::mutex mutex_;  // everything below; held only briefly by the caller
  Response response_;
  bool armed_ = false;
  uint64_t call_seq_ = 0;
  const char* what_ = "";
  CallBudget budget_;
  pthread_t thread_id_{};
  pid_t tid_ = 0;
  int64_t cpu_at_arm_ns_ = 0, call_blocked_ns_ = 0, last_sample_ns_ = 0;
  int64_t run_cpu_ns_ = 0, run_blocked_ns_ = 0;
  uint64_t interrupted_seq_ = 0;  // the call already interrupted
  int64_t used_at_interrupt_ns_ = 0;
  std::string interrupt_text_;    // why it was interrupted
  std::string abandoned_;
  std::function<void(const std::string&)> interrupter_;
  std::condition_variable wake_, changed_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace aula::component
