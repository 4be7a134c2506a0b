#include "aula/component/execute_watchdog.hpp"

#include <aula/component/crash_report.hpp>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>

#include <pthread.h>
#include <unistd.h>

namespace aula::component {
namespace {

int64_t steadyNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

int64_t ns(double s) { return static_cast<int64_t>(std::llround(s * 1e9)); }

std::string over(double s) {
  std::ostringstream text;
  text << s;
  return text.str();
}

}  // namespace

bool threadBlocked(pid_t tid) {
  std::ifstream stat("/proc/self/task/" + std::to_string(tid) + "/stat");
  std::string line;
  std::getline(stat, line);
  const auto paren = line.rfind(')');  // the name may hold spaces and parentheses
  if (paren == std::string::npos || paren + 2 >= line.size()) return false;
  const char state = line[paren + 2];
  return state == 'S' || state == 'D';
}

int64_t threadCpuNs(pthread_t thread) {
  clockid_t clock{};
  timespec t{};
  if (pthread_getcpuclockid(thread, &clock) != 0 || clock_gettime(clock, &t) != 0) return 0;
  return static_cast<int64_t>(t.tv_sec) * 1000000000 + t.tv_nsec;
}

namespace {
thread_local pid_t cached_tid = 0;
// The calling thread's id, asked of the kernel once per thread, not at every arm() (every control
// period); a child forked from this thread asks again.
pid_t threadId() {
  static const int reset_in_children = ::pthread_atfork(nullptr, nullptr, [] { cached_tid = 0; });
  (void)reset_in_children;
  if (cached_tid == 0) cached_tid = ::gettid();
  return cached_tid;
}
}  // namespace

ExecuteWatchdog::ExecuteWatchdog(std::string program, RunBudget run_budget, Response response)
    : program_(std::move(program)), run_budget_(run_budget), response_(response), thread_([this] { watch(); }) {}

ExecuteWatchdog::~ExecuteWatchdog() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void ExecuteWatchdog::arm(const char* what, const CallBudget& budget) {
  const pthread_t self = pthread_self();
  const int64_t cpu_ns = threadCpuNs(self);
  std::lock_guard<std::mutex> lock(mutex_);
  armed_ = true;
  ++call_seq_;
  what_ = what;
  budget_ = budget;
  thread_id_ = self;
  tid_ = threadId();
  cpu_at_arm_ns_ = cpu_ns;
  call_blocked_ns_ = 0;
  last_sample_ns_ = steadyNowNs();
  abandoned_.clear();
}

void ExecuteWatchdog::disarm() {
  const int64_t cpu_ns = threadCpuNs(pthread_self());
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!armed_) return;
    armed_ = false;
    run_cpu_ns_ += cpu_ns - cpu_at_arm_ns_;
    run_blocked_ns_ += call_blocked_ns_;
  }
  changed_.notify_all();
}

void ExecuteWatchdog::setInterrupter(std::function<void(const std::string&)> interrupter) {
  std::lock_guard<std::mutex> lock(mutex_);
  interrupter_ = std::move(interrupter);
}

void ExecuteWatchdog::setResponse(Response response) {
  std::lock_guard<std::mutex> lock(mutex_);
  response_ = response;
}

std::string ExecuteWatchdog::abandoned() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return abandoned_;
}

bool ExecuteWatchdog::waitAbandoned(double s) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait_for(lock, std::chrono::duration<double>(s), [this] { return !armed_ || !abandoned_.empty(); });
  return !abandoned_.empty();
}

double ExecuteWatchdog::runCpuS() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return run_cpu_ns_ / 1e9;
}

double ExecuteWatchdog::runBlockedS() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return run_blocked_ns_ / 1e9;
}

std::string ExecuteWatchdog::sampleLocked(int64_t now_ns) {
  // The whole interval since the last sample is counted as the state seen now: at 50 ms a sample,
  // a budget of seconds is judged to within a few percent.
  if (threadBlocked(tid_)) call_blocked_ns_ += now_ns - last_sample_ns_;
  last_sample_ns_ = now_ns;
  const int64_t cpu_ns = threadCpuNs(thread_id_) - cpu_at_arm_ns_;
  if (interrupted_seq_ == call_seq_) {
    // Interrupted: it has its grace of its own time (CPU or blocked) to return.
    if (cpu_ns + call_blocked_ns_ - used_at_interrupt_ns_ < ns(kInterruptGraceS)) return "";
    return interrupt_text_;
  }
  std::string why;
  if (budget_.cpu_s > 0 && cpu_ns > ns(budget_.cpu_s)) {
    why = std::string(what_) + " used more than " + over(budget_.cpu_s) + " s of CPU time (an endless loop?) (" +
          budget_.setting + ")";
  } else if (budget_.blocked_s > 0 && call_blocked_ns_ > ns(budget_.blocked_s)) {
    why = std::string(what_) + " was blocked (sleeping or waiting) for more than " + over(budget_.blocked_s) +
          " s (Component.BlockedLimit)";
  } else if (run_budget_.cpu_s > 0 && run_cpu_ns_ + cpu_ns > ns(run_budget_.cpu_s)) {
    why = "the algorithm's calls used more than " + over(run_budget_.cpu_s) + " s of CPU time in all (Component.RunBudget)";
  } else if (run_budget_.blocked_s > 0 && run_blocked_ns_ + call_blocked_ns_ > ns(run_budget_.blocked_s)) {
    why = "the algorithm's calls were blocked (sleeping or waiting) for more than " + over(run_budget_.blocked_s) +
          " s in all (Component.RunBlockedLimit)";
  }
  if (why.empty()) return "";
  if (interrupter_) {
    interrupted_seq_ = call_seq_;
    used_at_interrupt_ns_ = cpu_ns + call_blocked_ns_;
    interrupt_text_ = why;
    // Raise inside the call, from a thread of its own: the interrupter may wait for the
    // student's code to yield, and this thread must still give up if it never does.
    std::thread(interrupter_, why).detach();
    return "";
  }
  return why;
}

void ExecuteWatchdog::giveUp(const std::string& why) {
  if (response_ == Response::Flag) {
    abandoned_ = why;
    changed_.notify_all();
    return;
  }
  // The stuck thread holds whatever it holds: no destructor, no flush, no exit handler.
  endForOverrun(program_, why);
}

void ExecuteWatchdog::watch() {
  // Stop signals belong to the main thread's signalfd (SignalWatcher): never to this one, or
  // Ctrl-C would kill the process instead of ending the run cleanly.
  sigset_t all;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, nullptr);
  std::unique_lock<std::mutex> lock(mutex_);
  uint64_t given_up_seq = 0;
  while (!stopping_) {
    wake_.wait_for(lock, std::chrono::milliseconds(50));
    if (!armed_ || given_up_seq == call_seq_) continue;
    std::string why = sampleLocked(steadyNowNs());
    if (why.empty()) continue;
    given_up_seq = call_seq_;
    giveUp(why);
  }
}

}  // namespace aula::component
