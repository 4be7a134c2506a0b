#include "aula/supervision/capped_output.hpp"

#include <cerrno>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

namespace aula::supervision {

CappedOutput::CappedOutput() {
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC | O_NONBLOCK) != 0) throw std::runtime_error("pipe2 failed");
  read_fd_ = ends[0];
  write_fd_ = ends[1];
  // The writing end blocks: a child that prints faster than the launcher drains waits for it.
  ::fcntl(write_fd_, F_SETFL, ::fcntl(write_fd_, F_GETFL) & ~O_NONBLOCK);
}

CappedOutput::~CappedOutput() {
  if (write_fd_ >= 0) ::close(write_fd_);
  if (read_fd_ >= 0) ::close(read_fd_);
}

std::string CappedOutput::childPath() const { return "/proc/self/fd/" + std::to_string(write_fd_); }

void CappedOutput::childStarted() {
  ::close(write_fd_);
  write_fd_ = -1;
}

void CappedOutput::pass(const char* data, size_t size) {
  if (passed_ < kHeadBytes) {
    const size_t now = std::min(size, kHeadBytes - passed_);
    (void)!::write(STDERR_FILENO, data, now);
    passed_ += now;
    data += now;
    size -= now;
  }
  if (size == 0) return;
  tail_.append(data, size);
  if (tail_.size() > kTailBytes) {
    dropped_ += tail_.size() - kTailBytes;
    tail_.erase(0, tail_.size() - kTailBytes);
  }
}

void CappedOutput::drain() {
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(read_fd_, buffer, sizeof buffer);
    if (n > 0) {
      pass(buffer, static_cast<size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    return;  // EAGAIN (nothing now) or 0 (every writer gone)
  }
}

void CappedOutput::finish() {
  drain();
  if (dropped_ > 0) {
    const std::string note = "\n[aula: " + std::to_string(dropped_) + " bytes of the component's output dropped here: " +
                             "only the first " + std::to_string(kHeadBytes / 1024) + " KiB and the last " +
                             std::to_string(kTailBytes / 1024) + " KiB are kept]\n";
    (void)!::write(STDERR_FILENO, note.data(), note.size());
  }
  (void)!::write(STDERR_FILENO, tail_.data(), tail_.size());
  tail_.clear();
}

}  // namespace aula::supervision
