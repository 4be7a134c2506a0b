#include "aula/process/line_pipe.hpp"

#include <cerrno>

#include <fcntl.h>
#include <unistd.h>

namespace aula::process {

LinePipe::LinePipe(int fd) : fd_(fd) {
  if (fd_ >= 0) ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) | O_NONBLOCK);
}

LinePipe::~LinePipe() {
  if (fd_ >= 0) ::close(fd_);
}

std::vector<std::string> LinePipe::lines() {
  std::vector<std::string> out;
  if (fd_ < 0) return out;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n > 0) {
      pending_.append(buffer, static_cast<size_t>(n));
      continue;
    }
    if (n == 0) {  // the launcher closed it: nothing more will come
      ::close(fd_);
      fd_ = -1;
    }
    break;  // EAGAIN: nothing now
  }
  for (size_t end; (end = pending_.find('\n')) != std::string::npos;) {
    out.push_back(pending_.substr(0, end));
    pending_.erase(0, end + 1);
  }
  return out;
}

}  // namespace aula::process
