#pragma once
// SIGINT/SIGTERM as a file descriptor (signalfd), so a single-threaded loop can poll for a
// clean stop without a global flag.

#include <csignal>
#include <sys/signalfd.h>
#include <unistd.h>

namespace aula::process {

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
