#include "aula/process/child_process.hpp"

#include "aula/process/cpu_affinity.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <sys/syscall.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace aula::process {
namespace {

int decode(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

}  // namespace

bool processGone(pid_t pid) {
  if (pid <= 0) return false;
  if (::kill(pid, 0) != 0) return errno == ESRCH;
  // /proc/PID/stat: "PID (COMMAND) STATE ...", the command in parentheses may hold spaces.
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  const auto paren = line.rfind(')');
  if (paren == std::string::npos || paren + 2 >= line.size()) return false;
  const char state = line[paren + 2];
  return state == 'Z' || state == 'X';
}

ChildProcess::ChildProcess(std::vector<std::string> argv, const std::string& stdout_path,
                           const std::string& stderr_path, std::vector<int> pass_fds, Placement placement,
                           std::optional<std::vector<std::string>> environment) {
  if (argv.empty()) throw std::runtime_error("ChildProcess: empty command");
  name_ = argv[0];
  // A pipe closed on exec tells the parent whether exec succeeded.
  int status_pipe[2];
  if (pipe2(status_pipe, O_CLOEXEC) != 0) throw std::runtime_error("pipe2 failed");
  const pid_t parent = getpid();
  std::vector<char*> env;  // made before fork: the child only execs
  if (environment) {
    for (auto& e : *environment) env.push_back(e.data());
    env.push_back(nullptr);
  }
  pid_ = fork();
  if (pid_ < 0) throw std::runtime_error("fork failed: " + std::string(std::strerror(errno)));
  if (pid_ == 0) {
    close(status_pipe[0]);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(127);  // the parent died before prctl
    // The parent may block SIGINT/SIGTERM for a signalfd; the child must not inherit that.
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    signal(SIGPIPE, SIG_DFL);  // a launcher ignores it (a referee that has ended); its children do not
    auto redirect = [](const std::string& path, int fd) {
      if (path.empty()) return;
      const int out = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (out >= 0) {
        dup2(out, fd);
        close(out);
      }
    };
    redirect(stdout_path, STDOUT_FILENO);
    if (!stderr_path.empty() && stderr_path == stdout_path) {
      dup2(STDOUT_FILENO, STDERR_FILENO);  // one file, one offset: the lines stay in order
    } else {
      redirect(stderr_path, STDERR_FILENO);
    }
    // First every passed descriptor out of the way (a source may be one of the targets), then
    // each onto its number; dup2's copy has no FD_CLOEXEC, so it survives exec.
    constexpr int kAboveTargets = 100;
    for (int& fd : pass_fds) fd = fcntl(fd, F_DUPFD_CLOEXEC, kAboveTargets);
    for (size_t i = 0; i < pass_fds.size(); ++i) {
      if (pass_fds[i] >= 0) dup2(pass_fds[i], passedFd(i));
    }
    if (placement.cpu >= 0) runOnlyOn(placement.cpu);  // a CPU it may not use: it runs where it may
    if (placement.batch) runAsBatch();
    std::vector<char*> args;
    for (auto& a : argv) args.push_back(a.data());
    args.push_back(nullptr);
    if (environment) {
      execvpe(args[0], args.data(), env.data());
    } else {
      execvp(args[0], args.data());
    }
    const int err = errno;
    (void)!write(status_pipe[1], &err, sizeof err);
    _exit(127);
  }
  close(status_pipe[1]);
  // Readable once the child exits: waits end at that moment instead of at the next look.
  exit_fd_ = static_cast<int>(syscall(SYS_pidfd_open, pid_, 0));
  int err = 0;
  const ssize_t n = read(status_pipe[0], &err, sizeof err);
  close(status_pipe[0]);
  if (n == static_cast<ssize_t>(sizeof err)) {
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
    if (exit_fd_ >= 0) close(exit_fd_);
    exit_fd_ = -1;
    throw std::runtime_error("cannot start '" + name_ + "': " + std::strerror(err));
  }
}

ChildProcess::~ChildProcess() {
  if (pid_ > 0 && !exit_code_) stop();
  if (exit_fd_ >= 0) close(exit_fd_);
}

std::optional<int> ChildProcess::poll() {
  if (exit_code_ || pid_ <= 0) return exit_code_;
  int status = 0;
  if (waitpid(pid_, &status, WNOHANG) == pid_) exit_code_ = decode(status);
  return exit_code_;
}

std::optional<int> ChildProcess::wait(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!poll()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return std::nullopt;
    if (exit_fd_ >= 0) {
      pollfd exited{exit_fd_, POLLIN, 0};
      ::poll(&exited, 1, static_cast<int>(left.count()) + 1);
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));  // a kernel without pidfds (before 5.3)
    }
  }
  return exit_code_;
}

int ChildProcess::stop(std::chrono::milliseconds grace) {
  if (poll()) return *exit_code_;
  kill(pid_, SIGTERM);
  if (auto code = wait(grace)) return *code;
  kill(pid_, SIGKILL);
  int status = 0;
  waitpid(pid_, &status, 0);
  exit_code_ = decode(status);
  return *exit_code_;
}

}  // namespace aula::process
