#pragma once
// The student's calls on a thread of their own, for a component with windows: the GUI thread
// hands over one call and waits for it until it returns or the watchdog gives it up (its own
// budgets of CPU and blocked time: never the wall time the machine takes). While it waits it runs
// no event and touches nothing, so the call is the one owner of the component's state until it
// returns. A call given up is abandoned with its thread: the caller then
// leaks this object (the call may still be running in it) and must never again touch what the
// call can reach (AlgorithmHostBase freezes the devices; the process ends with _Exit).

#include <aula/component/execute_watchdog.hpp>

#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace aula::component {

class AlgorithmThread {
 public:
  AlgorithmThread();
  ~AlgorithmThread();  // only for a thread that is idle (never after a call was abandoned)
  AlgorithmThread(const AlgorithmThread&) = delete;
  AlgorithmThread& operator=(const AlgorithmThread&) = delete;

  // Runs `call` on the thread; true when it returned, false when `watchdog` gave it up (the call
  // arms `watchdog` on this thread; the watchdog answers with ExecuteWatchdog::Response::Flag).
  // `call` must own what it uses (an abandoned call outlives the caller's stack).
  bool run(std::function<void()> call, ExecuteWatchdog& watchdog);

 private:
  void loop();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::function<void()> job_;
  bool has_job_ = false, done_ = false, stopping_ = false;
  std::thread thread_;
};

}  // namespace aula::component
