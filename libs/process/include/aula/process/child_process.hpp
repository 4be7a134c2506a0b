#pragma once
// A child process that never outlives its parent: started with PR_SET_PDEATHSIG, stopped with
// SIGTERM then SIGKILL. Used by the `aula` launcher and by integration tests.

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace aula::process {

// Where and how a child is scheduled (cpu_affinity.hpp), set before it starts.
struct Placement {
  int cpu = -1;        // >= 0: on that CPU only (one it may not use: wherever it may)
  bool batch = false;  // SCHED_BATCH: woken, it does not preempt the one that woke it
};

// True when no process `pid` runs on this machine: none has that id, or it has exited and waits
// to be reaped (a zombie: its parent, a shell or a test, has not looked yet). One this process
// may not signal (EPERM) runs. `pid` <= 0 (unknown) is never gone.
bool processGone(pid_t pid);

class ChildProcess {
 public:
  // argv[0] is the program (a path or a name on PATH). stdout/stderr go to the given files
  // (empty: inherited; the same path twice: one file with both, in order). `pass_fds[i]` is
  // handed to the child as its descriptor kPassedFd + i (the launcher's private control pipe,
  // the run's key: passedFd(i) is the number to tell the child); nothing else of the parent's is
  // inherited past exec beyond what lacks FD_CLOEXEC. `placement`: where and how the child is
  // scheduled. `environment` ("NAME=value" each): the child's whole environment instead of
  // ours. Throws std::runtime_error when the program cannot be started.
  ChildProcess(std::vector<std::string> argv, const std::string& stdout_path = "",
               const std::string& stderr_path = "", std::vector<int> pass_fds = {}, Placement placement = Placement(),
               std::optional<std::vector<std::string>> environment = std::nullopt);
  static constexpr int kPassedFd = 3;
  static constexpr int passedFd(size_t index) { return kPassedFd + static_cast<int>(index); }
  ~ChildProcess();  // stops the child if still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  const std::string& name() const { return name_; }

  // Readable (poll) once the child has exited (a pidfd; -1 on a kernel without them): a
  // supervisor sleeps until something happens instead of looking every few milliseconds.
  int exitFd() const { return exit_fd_; }
  // Non-blocking: the exit code once finished (128 + signal when killed by a signal).
  std::optional<int> poll();
  // Waits up to `timeout`; nullopt if still running.
  std::optional<int> wait(std::chrono::milliseconds timeout);
  // SIGTERM, wait up to `grace`, then SIGKILL. Returns the exit code.
  int stop(std::chrono::milliseconds grace = std::chrono::milliseconds(2000));

 private:
  pid_t pid_ = -1;
  int exit_fd_ = -1;
  std::string name_;
  std::optional<int> exit_code_;
};

}  // namespace aula::process
