#pragma once
// SIGINT/SIGTERM as a file descriptor (signalfd), so a single-threaded loop can poll for a
// clean stop without a global flag.

#include <csignal>
#include <pthread.h>
#include <sys/signalfd.h>
#include <unistd.h>

namespace aula::process {

// Starts a thread (`start()` returns it) with SIGINT and SIGTERM blocked, so the thread inherits
// the block. A thread that does not block them can be handed a stop signal meant for the main
// loop's SignalWatcher, and its default action kills the whole process before it can leave
// lockstep and exit cleanly (seen: the TeleTaxi component ending with 143 at every run's end).
// Blocks SIGINT and SIGTERM in the calling thread, and so in every thread it starts from now on.
// A headless process calls it first thing, before any library starts a thread of its own (TBB's
// workers under OpenCV), so that only its SignalWatcher ever takes a stop signal (a signal that
// arrives before the watcher exists waits, pending, and the watcher reads it).
inline void blockStopSignals() {
  sigset_t stop;
  sigemptyset(&stop);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop, nullptr);
}

template <class Start>
auto startWithStopSignalsBlocked(Start start) {
  sigset_t stop, previous;
  sigemptyset(&stop);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop, &previous);
  auto started = start();
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  return started;
}

class SignalWatcher {
 public:
  SignalWatcher() {
    sigset_t mask;
    sigemptyset(&mask);
    sigaddset(&mask, SIGINT);
    sigaddset(&mask, SIGTERM);
    sigprocmask(SIG_BLOCK, &mask, nullptr);
    fd_ = signalfd(-1, &mask, SFD_NONBLOCK | SFD_CLOEXEC);
  }
  ~SignalWatcher() {
    if (fd_ >= 0) close(fd_);
  }
  SignalWatcher(const SignalWatcher&) = delete;
  SignalWatcher& operator=(const SignalWatcher&) = delete;

  // Non-blocking: true once a stop signal has arrived.
  bool stopRequested() {
    if (stop_ || fd_ < 0) return stop_;
    signalfd_siginfo info;
    if (read(fd_, &info, sizeof info) == static_cast<ssize_t>(sizeof info)) {
      stop_ = true;
      signal_ = static_cast<int>(info.ssi_signo);
    }
    return stop_;
  }
  // Readable when a stop signal waits (for poll() beside other descriptors).
  int fd() const { return fd_; }
  // The signal that asked to stop (SIGINT, SIGTERM), or 0.
  int signal() const { return signal_; }

 private:
  int fd_ = -1;
  bool stop_ = false;
  int signal_ = 0;
};

}  // namespace aula::process
