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

bool AlgorithmThread::run(std::function<void()> call, double budget_s) {
  std::unique_lock<std::mutex> lock(mutex_);
  job_ = std::move(call);
  has_job_ = true;
  done_ = false;
  wake_.notify_all();
  return wake_.wait_for(lock, std::chrono::duration<double>(budget_s), [this] { return done_; });
}

bool AlgorithmThread::waitMore(double s) {
  std::unique_lock<std::mutex> lock(mutex_);
  return wake_.wait_for(lock, std::chrono::duration<double>(s), [this] { return done_; });
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
