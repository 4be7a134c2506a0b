#pragma once
// A sandboxed component's output (the student's prints) reaches the run's log through a pipe the
// launcher drains: the first kHeadBytes as they come, then only the last kTailBytes are kept and
// written at the end with how much was dropped. A student's flood ends neither the grade nor the
// disk (issue 28: 562 MB of stdout per run once filled a class's out folder); past
// Component.Sandbox.Output the launcher ends that run with the reason (supervisor.cpp).

#include <cstddef>
#include <string>

namespace aula::supervision {

class CappedOutput {
 public:
  static constexpr size_t kHeadBytes = 256 * 1024;
  static constexpr size_t kTailBytes = 64 * 1024;

  CappedOutput();  // throws std::runtime_error when no pipe can be made
  ~CappedOutput();
  CappedOutput(const CappedOutput&) = delete;
  CappedOutput& operator=(const CappedOutput&) = delete;

  // What the child opens for its stdout and stderr ("/proc/self/fd/N", opened before its exec).
  std::string childPath() const;
  // Once the child runs: the parent's copy of the writing end closed.
  void childStarted();
  int readFd() const { return read_fd_; }
  // Reads what is there (non-blocking) and passes it on, within the cap.
  void drain();
  // The rest, the kept tail and the count of what was dropped.
  void finish();
  // Everything read so far, kept or dropped.
  size_t bytesRead() const { return passed_ + dropped_ + tail_.size(); }

 private:
  void pass(const char* data, size_t size);

  int read_fd_ = -1, write_fd_ = -1;
  size_t passed_ = 0, dropped_ = 0;
  std::string tail_;
};

}  // namespace aula::supervision
