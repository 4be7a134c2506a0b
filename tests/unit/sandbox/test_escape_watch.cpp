// What a graded run's launcher sees of the student's tries to get out of the run: the graded
// component's watch on forbidden system calls (sandbox/forbidden_calls.hpp), in a child process
// of its own (a seccomp filter is for a process's life): a forbidden call returns EPERM and is
// said on the line; the watch's handler and line cannot be taken away; a call it does not watch
// goes through. And the algorithm's own process's list: a call off it fails, said on stderr,
// the escapes among them on the line.
#include <aula/sandbox/datagram_watch.hpp>
#include <aula/sandbox/forbidden_calls.hpp>
#include <aula/sandbox/sandbox.hpp>

#include <gtest/gtest.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/mount.h>
#include <sys/socket.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <sched.h>
#include <unistd.h>

namespace {

// Runs `tries(line_fd)` in a watched child: returns what the child wrote on its line, a '|', then
// "ok" or the number of the try that failed.
// `install`: the filter (the watch, by default, or the algorithm's list). `said`: when given,
// what the child wrote on stderr.
std::string inWatchedChild(int (*tries)(int line_fd), std::string (*install)(int) = aula::sandbox::watchForbiddenCalls,
                           std::string* said = nullptr) {
  int line[2], verdict[2], err[2];
  if (::pipe(line) != 0 || ::pipe(verdict) != 0 || ::pipe(err) != 0) return "pipe failed";
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(line[0]);
    ::close(verdict[0]);
    ::close(err[0]);
    if (said != nullptr) ::dup2(err[1], STDERR_FILENO);
    ::close(err[1]);
    const std::string why = install(line[1]);
    const int failed = why.empty() ? tries(line[1]) : -1;
    const std::string text = failed == 0 ? "ok" : "failed at try " + std::to_string(failed) + " " + why;
    (void)!::write(verdict[1], text.data(), text.size());
    ::_exit(0);
  }
  ::close(line[1]);
  ::close(verdict[1]);
  ::close(err[1]);
  int status = 0;
  ::waitpid(child, &status, 0);
  std::string out;
  char buffer[512];
  for (ssize_t n; (n = ::read(line[0], buffer, sizeof buffer)) > 0;) out.append(buffer, n);
  for (ssize_t n; said != nullptr && (n = ::read(err[0], buffer, sizeof buffer)) > 0;) said->append(buffer, n);
  ::close(err[0]);
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

// io_uring (whose requests make sockets past socket()'s rule) and the keyring (the caller's
// session keys): refused and said as the other escape calls are.
TEST(ForbiddenCalls, IoUringAndTheKeyringAreRefusedAndSaid) {
  const std::string out = inWatchedChild([](int) {
    char params[120] = {};
    if (::syscall(SYS_io_uring_setup, 8, params) != -1 || errno != EPERM) return 1;
    if (::syscall(SYS_io_uring_enter, 0, 0, 0, 0, nullptr, 0) != -1 || errno != EPERM) return 2;
    if (::syscall(SYS_io_uring_register, 0, 0, nullptr, 0) != -1 || errno != EPERM) return 3;
    if (::syscall(SYS_keyctl, 0 /* KEYCTL_GET_KEYRING_ID */, -3, 0) != -1 || errno != EPERM) return 4;
    if (::syscall(SYS_add_key, "user", "aula", "x", 1, -3) != -1 || errno != EPERM) return 5;
    if (::syscall(SYS_request_key, "user", "aula", nullptr, 0) != -1 || errno != EPERM) return 6;
    return 0;
  });
  EXPECT_EQ(out, "refused io_uring_setup\nrefused io_uring_enter\nrefused io_uring_register\nrefused keyctl\n"
                 "refused add_key\nrefused request_key\n|ok");
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

// A tripwire's end (a reference's factory called): the try said on the line, exit code 5 at once
// (no atexit handler: the student's state is not trusted), whether or not the watch is installed.
TEST(ForbiddenCalls, AForbiddenTryEndsTheProcessAndIsSaidOnTheLine) {
  const std::string out = inWatchedChild([](int line_fd) -> int {
    std::atexit([] { ::_exit(9); });
    aula::sandbox::endForForbiddenTry(line_fd, "vacuum-cleaner", "call makeReferenceAlgorithm");
  });
  EXPECT_EQ(out, "refused call makeReferenceAlgorithm\n|");
  int line[2];
  ASSERT_EQ(::pipe(line), 0);
  const pid_t child = ::fork();
  if (child == 0) aula::sandbox::endForForbiddenTry(line[1], "vacuum-cleaner", "call it");
  ::close(line[1]);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 5);
  char said[64] = {};
  EXPECT_GT(::read(line[0], said, sizeof said - 1), 0);
  EXPECT_STREQ(said, "refused call it\n");
  ::close(line[0]);
}

// The algorithm's own process: what an algorithm needs goes through (memory, threads, a child,
// time); any other call fails, said once on stderr; the escapes among them (a socket, a
// namespace, a mount) on the line; the terminal is read, never typed into.
TEST(AlgorithmCalls, OnlyTheListGoesThroughAndEscapesAreSaidOnTheLine) {
  std::string said;
  const std::string out = inWatchedChild(
      [](int) {
        if (::socket(AF_INET, SOCK_DGRAM, 0) != -1 || errno != EACCES) return 1;
        if (::memfd_create("aula", 0) != -1 || errno != EPERM) return 2;
        if (::memfd_create("aula", 0) != -1 || errno != EPERM) return 3;  // said once
        if (::syscall(SYS_clone, CLONE_NEWUSER | SIGCHLD, 0, 0, 0, 0) != -1 || errno != EPERM) return 4;
        if (::umount2("/proc", MNT_DETACH) != -1 || errno != EPERM) return 5;
        char typed = 'x';
        if (::ioctl(STDIN_FILENO, TIOCSTI, &typed) != -1 || errno != ENOTTY) return 6;
        cpu_set_t cpus;  // its CPUs are read, never changed (a graded run's CPU is its own)
        if (::sched_getaffinity(0, sizeof cpus, &cpus) != 0) return 11;
        if (::sched_setaffinity(0, sizeof cpus, &cpus) != -1 || errno != EPERM) return 12;
        int ran = 0;
        std::thread([&ran] { ran = 1; }).join();  // clone3 refused as unknown: the C library calls clone
        if (ran != 1) return 7;
        const pid_t child = ::fork();
        if (child == 0) ::_exit(3);
        int status = 0;
        if (child < 0 || ::waitpid(child, &status, 0) != child || WEXITSTATUS(status) != 3) return 8;
        std::unique_ptr<char[]> block(new char[64 << 20]);
        block[(64 << 20) - 1] = 1;
        timespec now{};
        if (::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now) != 0) return 9;
        struct sigaction ignore {};
        ignore.sa_handler = SIG_IGN;
        if (::sigaction(SIGSYS, &ignore, nullptr) != -1 || errno != EPERM) return 10;
        return 0;
      },
      aula::sandbox::allowOnlyAlgorithmCalls, &said);
  EXPECT_EQ(out, "refused socket\nrefused clone\nrefused umount2\n|ok");
  EXPECT_EQ(said, "the algorithm's process may not call memfd_create(): refused\n"
                  "the algorithm's process may not call ioctl(): refused\n"
                  "the algorithm's process may not call sched_setaffinity(): refused\n");
}

// The algorithm's process signals itself and its own children only, never with a stop signal: its
// component (its parent, numbered before it), a process group and a forged 64-bit pid are refused
// and flagged, so no kill of the component passes for the machine's and no stop stalls the run.
TEST(AlgorithmCalls, SignalsStayWithItselfAndItsChildren) {
  std::string said;
  const std::string out = inWatchedChild(
      [](int) {
        const pid_t parent = ::getppid();
        if (::kill(parent, SIGKILL) != -1 || errno != EPERM) return 1;
        if (::kill(parent, 0) != -1 || errno != EPERM) return 2;
        if (::kill(0, SIGTERM) != -1 || errno != EPERM) return 3;   // its process group: its parent's too
        if (::kill(-1, SIGKILL) != -1 || errno != EPERM) return 4;  // every process it may signal
        if (::syscall(SYS_kill, (1L << 32) | parent, SIGKILL) != -1 || errno != EPERM) return 5;  // the kernel reads 32 bits
        if (::kill(::getpid(), SIGSTOP) != -1 || errno != EPERM) return 6;
        if (::raise(SIGTSTP) == 0) return 7;  // tgkill, to itself: a stop signal all the same
        if (::kill(::getpid(), 0) != 0) return 8;
        signal(SIGUSR1, SIG_IGN);
        if (::raise(SIGUSR1) != 0) return 9;
        int never[2];
        if (::pipe(never) != 0) return 11;
        const pid_t child = ::fork();
        if (child == 0) {
          char c = 0;
          (void)!::read(never[0], &c, 1);  // until it is killed
          ::_exit(0);
        }
        int status = 0;
        if (::kill(child, SIGKILL) != 0 || ::waitpid(child, &status, 0) != child || !WIFSIGNALED(status)) return 10;
        return 0;
      },
      aula::sandbox::allowOnlyAlgorithmCalls, &said);
  EXPECT_EQ(out, "refused kill\nrefused kill\nrefused kill\nrefused kill\nrefused kill\nrefused kill\nrefused tgkill\n|ok");
  EXPECT_EQ(said, "");
}

// Stopped and continued from outside (a debugger, an admin's kill -STOP) in the middle of a sleep,
// the algorithm's process goes on: the kernel resumes the call with restart_syscall, on its list.
TEST(AlgorithmCalls, AStopAndContinueFromOutsideIsNoFault) {
  int slept[2];
  ASSERT_EQ(::pipe(slept), 0);
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(slept[0]);
    if (!aula::sandbox::allowOnlyAlgorithmCalls(-1).empty()) ::_exit(2);
    (void)!::write(slept[1], "s", 1);
    timespec nap{1, 0};
    ::_exit(::nanosleep(&nap, nullptr) == 0 ? 0 : 1);
  }
  ::close(slept[1]);
  char c = 0;
  ASSERT_EQ(::read(slept[0], &c, 1), 1);
  ::usleep(200000);  // in its sleep (were it not, the call would not need restarting, and pass)
  ::kill(child, SIGSTOP);
  ::usleep(200000);
  ::kill(child, SIGCONT);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ::close(slept[0]);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << (WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status)) : "exit " + std::to_string(WEXITSTATUS(status)));
}

// Outside a graded run (no line) the escapes too are refused, and said on stderr.
TEST(AlgorithmCalls, WithoutALineEveryRefusalIsSaidOnStderr) {
  std::string said;
  const std::string out = inWatchedChild(
      [](int) {
        if (::socket(AF_UNIX, SOCK_STREAM, 0) != -1 || errno != EACCES) return 1;
        if (::syscall(SYS_keyctl, 0, -3, 0) != -1 || errno != EPERM) return 2;
        return 0;
      },
      [](int) { return aula::sandbox::allowOnlyAlgorithmCalls(-1); }, &said);
  EXPECT_EQ(out, "|ok");
  EXPECT_EQ(said, "the algorithm's process may not call socket(): refused\n"
                  "the algorithm's process may not call keyctl(): refused\n");
}

// In a private network, a datagram to any port but the run's is seen (unicast and multicast),
// once each; the run's own traffic is not.
TEST(DatagramWatch, SeesDatagramsToOtherPortsOnly) {
  int seen[2];
  ASSERT_EQ(::pipe(seen), 0);
  const pid_t child = ::fork();
  if (child == 0) {  // a namespace is for a process's life: the child's, which has no thread
    ::close(seen[0]);
    const std::string why = aula::sandbox::enterPrivateNetwork();
    if (!why.empty()) {
      const std::string text = "no private network: " + why;
      (void)!::write(seen[1], text.data(), text.size());
      ::_exit(0);
    }
    aula::sandbox::DatagramWatch watch(7667);
    const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
    for (const char* address : {"127.0.0.1", "239.255.76.67"}) {
      for (const uint16_t port : {uint16_t{7667}, uint16_t{9}}) {
        sockaddr_in to{};
        to.sin_family = AF_INET;
        to.sin_port = htons(port);
        ::inet_pton(AF_INET, address, &to.sin_addr);
        (void)!::sendto(fd, "x", 1, 0, reinterpret_cast<sockaddr*>(&to), sizeof to);
      }
    }
    pollfd ready{watch.fd(), POLLIN, 0};
    ::poll(&ready, 1, 500);
    ::usleep(50000);  // both arrived
    std::string text;
    for (const std::string& what : watch.seen()) text += what + "\n";
    (void)!::write(seen[1], text.data(), text.size());
    ::_exit(0);
  }
  ::close(seen[1]);
  int status = 0;
  ::waitpid(child, &status, 0);
  std::string out;
  char buffer[512];
  for (ssize_t n; (n = ::read(seen[0], buffer, sizeof buffer)) > 0;) out.append(buffer, n);
  ::close(seen[0]);
  if (out.rfind("no private network", 0) == 0) GTEST_SKIP() << out;
  EXPECT_EQ(out, "datagram to 127.0.0.1:9\ndatagram to 239.255.76.67:9\n");
}
