#pragma once
// Ends the process when the student's execute() does not return within its budget of wall
// time: an endless loop must not hang a lockstep run (or a class's grading) forever. A thread
// of its own sleeps until the budget of the current call runs out; it shares only two atomics
// with the caller, and touches nothing else of the process before _exit.

#include <atomic>
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

  // A call begins; `what` is a string literal naming it ("execute()").
  void arm(const char* what);
  void disarm();                      // it returned

  double budgetS() const { return budget_s_; }

 private:
  void watch();

  std::string program_;
  double budget_s_;
  std::atomic<const char*> what_{""};
  std::atomic<int64_t> deadline_ns_{0};  // steady clock; 0: not armed
  std::mutex mutex_;                 // only for the sleep and the stop flag
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace aula::component
