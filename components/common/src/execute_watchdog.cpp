#include "aula/component/execute_watchdog.hpp"

#include <aula/process/exit_codes.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <csignal>

#include <pthread.h>
#include <unistd.h>

namespace aula::component {
namespace {

int64_t steadyNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

ExecuteWatchdog::ExecuteWatchdog(std::string program, double budget_s)
    : program_(std::move(program)), budget_s_(budget_s) {
  if (budget_s_ > 0) thread_ = std::thread([this] { watch(); });
}

ExecuteWatchdog::~ExecuteWatchdog() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void ExecuteWatchdog::arm(const char* what) {
  if (budget_s_ <= 0) return;
  what_.store(what, std::memory_order_relaxed);
  deadline_ns_.store(steadyNowNs() + static_cast<int64_t>(std::llround(budget_s_ * 1e9)), std::memory_order_release);
}

void ExecuteWatchdog::disarm() { deadline_ns_.store(0, std::memory_order_release); }

void ExecuteWatchdog::setInterrupter(std::function<void(const std::string&)> interrupter) {
  std::lock_guard<std::mutex> lock(mutex_);
  interrupter_ = std::move(interrupter);
}

std::string ExecuteWatchdog::overrunText(const char* what, double budget_s) {
  std::ostringstream text;
  text << what << " did not return within " << budget_s << " s (an endless loop?)";
  return text.str();
}

void ExecuteWatchdog::watch() {
  // Stop signals belong to the main thread's signalfd (SignalWatcher): never to this one, or
  // Ctrl-C would kill the process instead of ending the run cleanly.
  sigset_t all;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, nullptr);
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    // Short naps: an armed call is checked within 50 ms of its deadline.
    wake_.wait_for(lock, std::chrono::milliseconds(50));
    int64_t deadline = deadline_ns_.load(std::memory_order_acquire);
    if (deadline == 0 || steadyNowNs() < deadline) continue;
    if (interrupter_ && interrupted_deadline_ns_ != deadline) {
      // Raise inside the call, from a thread of its own: the interrupter may wait for the
      // student's code to yield, and this thread must still end the process if it never does.
      const int64_t extended = deadline + static_cast<int64_t>(kInterruptGraceS * 1e9);
      interrupted_deadline_ns_ = extended;
      std::thread(interrupter_, overrunText(what_.load(std::memory_order_relaxed), budget_s_)).detach();
      deadline_ns_.compare_exchange_strong(deadline, extended);  // unless it returned meanwhile
      continue;
    }
    char text[512];
    const int n = std::snprintf(text, sizeof text,
                                "%s: the student's algorithm: %s did not return within %g s (an endless loop?); "
                                "ending the run (Component.ExecuteBudget)\n",
                                program_.c_str(), what_.load(std::memory_order_relaxed), budget_s_);
    if (n > 0) (void)!::write(STDERR_FILENO, text, static_cast<size_t>(n) < sizeof text ? n : sizeof text - 1);
    // The stuck thread holds whatever it holds: no destructor, no flush, no exit handler.
    ::_exit(process::kExitAlgorithmHung);
  }
}

}  // namespace aula::component
