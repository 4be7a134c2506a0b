#pragma once
// Ends the process when the student's execute() does not return within its budget of wall
// time: an endless loop must not hang a lockstep run (or a class's grading) forever. A thread
// of its own sleeps until the budget of the current call runs out; it shares only two atomics
// with the caller, and touches nothing else of the process before _exit.
// An algorithm that can be interrupted (a Python file) is interrupted first: the call raises
// inside the student's loop, naming its line, and returns as a fault; only a call still running
// kInterruptGraceS later ends the process.

#include <atomic>
#include <functional>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

namespace aula::component {

class ExecuteWatchdog {
 public:
  // `budget_s` <= 0: no watchdog.
  ExecuteWatchdog(std::string program, double budget_s);
  ~ExecuteWatchdog();
  ExecuteWatchdog(const ExecuteWatchdog&) = delete;
  ExecuteWatchdog& operator=(const ExecuteWatchdog&) = delete;

  // How long an interrupted call has to return before the process ends.
  static constexpr double kInterruptGraceS = 1.0;
  // What overran its budget, for the student: "execute() did not return within 2 s (an endless loop?)".
  static std::string overrunText(const char* what, double budget_s);

  // A call begins; `what` is a string literal naming it ("execute()").
  void arm(const char* what);
  void disarm();                      // it returned
  // The algorithm's interrupter (PluginLibrary::interrupter), or empty: set between calls.
  void setInterrupter(std::function<void(const std::string&)> interrupter);

  double budgetS() const { return budget_s_; }

 private:
  void watch();

  std::string program_;
  double budget_s_;
  std::atomic<const char*> what_{""};
  std::atomic<int64_t> deadline_ns_{0};  // steady clock; 0: not armed
  std::mutex mutex_;                 // for the sleep, the stop flag and the interrupter
  std::function<void(const std::string&)> interrupter_;
  int64_t interrupted_deadline_ns_ = 0;  // the overrun already interrupted (watchdog thread only)
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace aula::component
