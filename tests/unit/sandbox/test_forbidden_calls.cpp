// The graded component's watch on forbidden system calls (sandbox/forbidden_calls.hpp), in a
// child process of its own (a seccomp filter is for a process's life): a forbidden call returns
// EPERM and is said on the line; the watch's handler and line cannot be taken away; a call it
// does not watch goes through.
#include <aula/sandbox/forbidden_calls.hpp>

#include <gtest/gtest.h>

#include <cerrno>
#include <csignal>
#include <string>

#include <sys/mount.h>
#include <sys/wait.h>
#include <sched.h>
#include <unistd.h>

namespace {

// Runs `tries(line_fd)` in a watched child: returns what the child wrote on its line, a '|', then
// "ok" or the number of the try that failed.
std::string inWatchedChild(int (*tries)(int line_fd)) {
  int line[2], verdict[2];
  if (::pipe(line) != 0 || ::pipe(verdict) != 0) return "pipe failed";
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(line[0]);
    ::close(verdict[0]);
    const std::string why = aula::sandbox::watchForbiddenCalls(line[1]);
    const int failed = why.empty() ? tries(line[1]) : -1;
    const std::string text = failed == 0 ? "ok" : "failed at try " + std::to_string(failed) + " " + why;
    (void)!::write(verdict[1], text.data(), text.size());
    ::_exit(0);
  }
  ::close(line[1]);
  ::close(verdict[1]);
  int status = 0;
  ::waitpid(child, &status, 0);
  std::string out;
  char buffer[512];
  for (ssize_t n; (n = ::read(line[0], buffer, sizeof buffer)) > 0;) out.append(buffer, n);
  out += "|";
  for (ssize_t n; (n = ::read(verdict[0], buffer, sizeof buffer)) > 0;) out.append(buffer, n);
  if (!WIFEXITED(status)) out += " (the child died of signal " + std::to_string(WTERMSIG(status)) + ")";
  ::close(line[0]);
  ::close(verdict[0]);
  return out;
}

}  // namespace

TEST(ForbiddenCalls, AreRefusedWithEpermAndSaidOnTheLine) {
  const std::string out = inWatchedChild([](int) {
    if (::umount2("/proc", MNT_DETACH) != -1 || errno != EPERM) return 1;
    if (::mount(nullptr, "/", nullptr, MS_REMOUNT | MS_BIND, nullptr) != -1 || errno != EPERM) return 2;
    if (::unshare(CLONE_NEWUSER) != -1 || errno != EPERM) return 3;
    if (::getpid() <= 0) return 4;  // an ordinary call goes through
    return 0;
  });
  EXPECT_EQ(out, "refused umount2\nrefused mount\nrefused unshare\n|ok");
}

TEST(ForbiddenCalls, TheWatchCannotBeSilenced) {
  const std::string out = inWatchedChild([](int line_fd) {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    if (::sigaction(SIGSYS, &ignore, nullptr) != -1 || errno != EPERM) return 1;
    if (::close(line_fd) != -1) return 2;
    if (::dup2(0, line_fd) != -1) return 3;
    if (::close_range(line_fd, line_fd, 0) != -1) return 4;
    if (::umount2("/proc", MNT_DETACH) != -1 || errno != EPERM) return 5;
    const int other = ::dup(0);  // another descriptor closes as ever
    if (other < 0 || ::close(other) != 0) return 6;
    return 0;
  });
  EXPECT_EQ(out, "refused umount2\n|ok");
}
