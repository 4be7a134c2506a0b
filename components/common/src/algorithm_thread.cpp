#include "aula/component/algorithm_thread.hpp"

#include <aula/component/crash_report.hpp>

#include <chrono>
#include <csignal>

#include <pthread.h>

namespace aula::component {

AlgorithmThread::AlgorithmThread() : thread_([this] { loop(); }) {}

AlgorithmThread::~AlgorithmThread() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

bool AlgorithmThread::run(std::function<void()> call, ExecuteWatchdog& watchdog) {
  std::unique_lock<std::mutex> lock(mutex_);
  job_ = std::move(call);
  has_job_ = true;
  done_ = false;
  wake_.notify_all();
  // However long it takes: only the watchdog's judgement of the call ends the wait.
  while (!wake_.wait_for(lock, std::chrono::milliseconds(50), [this] { return done_; })) {
    lock.unlock();
    const bool given_up = !watchdog.abandoned().empty();
    lock.lock();
    if (given_up && !done_) return false;
  }
  return true;
}

void AlgorithmThread::loop() {
  // Stop signals belong to the main thread (SignalWatcher), never to the student's code.
  sigset_t all;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, nullptr);
  prepareThreadForCrashes();  // a crash inside a call comes back to it (callSurvivingCrashes)
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return has_job_ || stopping_; });
    if (stopping_) return;
    std::function<void()> job = std::move(job_);
    has_job_ = false;
    lock.unlock();
    job();
    lock.lock();
    done_ = true;
    wake_.notify_all();
  }
}

}  // namespace aula::component
