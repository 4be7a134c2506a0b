#pragma once
// SIGINT/SIGTERM as a file descriptor (signalfd), so a single-threaded loop can poll for a
// clean stop without a global flag.

#include <csignal>
#include <pthread.h>
#include <sys/signalfd.h>
#include <unistd.h>

namespace aula::process {

// SIGINT and SIGTERM: what the launcher, a terminal's Ctrl-C or a Slurm job's end send.
inline sigset_t stopSignals() {
  sigset_t stop;
  sigemptyset(&stop);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGTERM);
  return stop;
}

// Blocks the stop signals in the calling thread, and so in every thread it starts from now on.
// A headless process calls it first thing, before any library starts a thread of its own (TBB's
// workers under OpenCV), so that only its SignalWatcher ever takes a stop signal: a thread that
// does not block them can be handed one, and its default action kills the whole process before
// it can leave lockstep (seen: the TeleTaxi component ending with 143 at every run's end). A
// signal that arrives before the watcher exists waits, pending, and the watcher reads it.
inline void blockStopSignals() {
  const sigset_t stop = stopSignals();
  pthread_sigmask(SIG_BLOCK, &stop, nullptr);
}

class SignalWatcher {
 public:
  SignalWatcher() {
    blockStopSignals();
    const sigset_t stop = stopSignals();
    fd_ = signalfd(-1, &stop, SFD_NONBLOCK | SFD_CLOEXEC);
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
