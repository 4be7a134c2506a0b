#include "aula/sandbox/forbidden_calls.hpp"

#include <aula/process/exit_codes.hpp>

#include <seccomp.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <iostream>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <memory>

#include <fcntl.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <ucontext.h>
#include <unistd.h>

namespace aula::sandbox {

namespace {

// The calls only an escape needs. Resolved by libseccomp for this architecture.
constexpr std::array<const char*, 28> kForbidden = {
    "mount",         "umount2",          "unshare",     "setns",          "pivot_root",  "chroot",
    "ptrace",        "process_vm_readv", "process_vm_writev", "init_module", "finit_module", "delete_module",
    "kexec_load",    "reboot",           "open_by_handle_at", "bpf",      "move_mount",  "open_tree",
    "fsopen",        "fsmount",          "fspick",      "mount_setattr",
    // io_uring's requests open sockets and files without the calls the filter looks at (a TCP or
    // Unix socket past socket()'s rule); the keyring holds the caller's session keys.
    "io_uring_setup", "io_uring_enter",  "io_uring_register", "keyctl",    "add_key",     "request_key"};

// The calls an algorithm's own process makes (algorithm_box.hpp), found with `strace -f` on every
// shipped algorithm, C++ and Python (numpy, OpenCV), a crash's addr2line and a hot reload, plus
// what a computing program may need beside them: memory, files, threads, children, time, signals.
// No new socket, no namespace, no other process's memory, no keyring, no io_uring; and no move to
// another CPU (sched_setaffinity: a graded run has one of its own, beside other students' runs).
// Signals go only to itself and its own children (kill, tkill, tgkill: narrowed by a second filter,
// signalsStayInside), never a stop signal. restart_syscall: what a process stopped and continued
// (a debugger, an admin's kill -STOP) makes to go on with the call it was in.
constexpr std::array<const char*, 150> kAlgorithmCalls = {
    // memory
    "brk", "mmap", "munmap", "mprotect", "madvise", "mremap", "msync", "mincore", "mlock", "munlock",
    "get_mempolicy", "set_mempolicy", "membarrier",
    // descriptors it has, and files it may see
    "read", "readv", "pread64", "preadv", "preadv2", "write", "writev", "pwrite64", "pwritev", "pwritev2", "lseek",
    "open", "openat", "openat2", "creat", "close", "close_range", "dup", "dup2", "dup3", "fcntl", "flock",
    "stat", "fstat", "lstat", "newfstatat", "statx", "statfs", "fstatfs", "access", "faccessat", "faccessat2",
    "readlink", "readlinkat", "getdents", "getdents64", "getcwd", "chdir", "fchdir", "ftruncate", "truncate",
    "fsync", "fdatasync", "fadvise64", "fallocate", "sendfile", "copy_file_range", "umask", "utimensat",
    "mkdir", "mkdirat", "rmdir", "unlink", "unlinkat", "rename", "renameat", "renameat2", "chmod", "fchmod",
    "fchmodat", "pipe", "pipe2", "poll", "ppoll", "select", "pselect6", "epoll_create1", "epoll_ctl",
    "epoll_wait", "epoll_pwait", "eventfd2",
    // its socket to the component (sockets it has; socket() and socketpair() are not here)
    "sendto", "recvfrom", "sendmsg", "recvmsg", "shutdown",
    // threads and children (clone without a namespace, below)
    "fork", "vfork", "execve", "wait4", "waitid", "exit", "exit_group", "futex", "set_robust_list",
    "get_robust_list", "set_tid_address", "rseq", "sched_yield", "sched_getaffinity",
    "sched_getparam", "sched_getscheduler", "getpriority", "getcpu",
    // signals
    "rt_sigprocmask", "rt_sigreturn", "rt_sigsuspend", "rt_sigtimedwait", "sigaltstack", "kill", "tgkill", "tkill",
    "restart_syscall",
    // time
    "clock_gettime", "clock_getres", "clock_nanosleep", "nanosleep", "gettimeofday", "time", "getitimer",
    "setitimer", "alarm",
    // who and where it is
    "getpid", "getppid", "gettid", "getuid", "geteuid", "getgid", "getegid", "getgroups", "getresuid",
    "getresgid", "getpgrp", "getpgid", "setpgid", "getsid", "setsid", "getrusage", "times", "sysinfo", "uname",
    "getrandom", "prlimit64", "getrlimit", "arch_prctl", "prctl", "seccomp"};

// Past the list, what the algorithm's process tries and a graded run flags as an escape: the
// escape calls above, the sockets and namespaces only an escape needs there, and a signal to a
// process of the run's (its component: a kill would be "killed from outside the run", a stop would
// stall the run) or a stop signal (signalsStayInside).
constexpr std::array<const char*, 6> kAlgorithmEscapes = {"socket", "socketpair", "clone", "kill", "tkill", "tgkill"};

constexpr int kCallNumbers = 1024;  // above every x86_64 and aarch64 system call number

// What the SIGSYS handler reads: a signal handler reaches only process-wide state, and this is
// its one place, filled before the filter is installed; after, the handler alone writes `said`.
struct WatchState {
  std::array<const char*, kCallNumbers> names{};
  std::array<bool, kCallNumbers> escape{};
  std::array<volatile sig_atomic_t, kCallNumbers> said{};
  int line_fd = -1;  // a graded run's: escapes are said there, and flagged; the rest on stderr
};

WatchState& watchState() {
  static WatchState state;
  return state;
}

void writeAll(int fd, const char* text, size_t length) {
  const int saved_errno = errno;
  (void)!::write(fd, text, length);
  errno = saved_errno;
}

void onForbiddenCall(int, siginfo_t* info, void* context) {
  WatchState& state = watchState();
  const int number = info->si_syscall;
  const bool known = number >= 0 && number < kCallNumbers;
  const char* name = known && state.names[number] != nullptr ? state.names[number] : "a system call";
  char line[160];
  size_t length = 0;
  auto append = [&](const char* text) {
    const size_t n = std::min(std::strlen(text), sizeof line - 1 - length);
    std::memcpy(line + length, text, n);
    length += n;
  };
  if (state.line_fd >= 0 && known && state.escape[number]) {
    append(kRefusedPrefix);
    append(name);
    append("\n");
    writeAll(state.line_fd, line, length);
  } else if (!known || state.said[number] == 0) {
    // Once per call, on the student's own output: why their call failed.
    if (known) state.said[number] = 1;
    append("the algorithm's process may not call ");
    append(name);
    append("(): refused\n");
    writeAll(STDERR_FILENO, line, length);
  }
  // The call returns an error, as the sandbox would have answered it: socket()'s is EACCES (as the
  // sandbox's filter says it), ioctl()'s ENOTTY (a descriptor that is no terminal), others EPERM.
  int error = EPERM;
  if (std::strcmp(name, "socket") == 0 || std::strcmp(name, "socketpair") == 0) error = EACCES;
  if (std::strcmp(name, "ioctl") == 0) error = ENOTTY;
  auto* uc = static_cast<ucontext_t*>(context);
#if defined(__x86_64__)
  uc->uc_mcontext.gregs[REG_RAX] = -error;
#elif defined(__aarch64__)
  uc->uc_mcontext.regs[0] = static_cast<unsigned long long>(-error);
#else
  (void)uc;
  (void)error;
#endif
}

// Fills the handler's state and installs it, before any filter that traps.
std::string installHandler(int line_fd, bool listed) {
  WatchState& state = watchState();
  state.line_fd = line_fd;
  for (int number = 0; number < kCallNumbers; ++number) {
    // libseccomp's name is allocated once per number and kept for the process's life.
    state.names[number] = seccomp_syscall_resolve_num_arch(SCMP_ARCH_NATIVE, number);
  }
  auto markEscape = [&](const char* name) {
    const int number = seccomp_syscall_resolve_name(name);
    if (number >= 0 && number < kCallNumbers) state.escape[number] = true;
  };
  for (const char* name : kForbidden) markEscape(name);
  if (listed) {
    for (const char* name : kAlgorithmEscapes) markEscape(name);
  }
  // A loop of tries must never block the handler on a full pipe: past it, lines are dropped.
  if (line_fd >= 0) ::fcntl(line_fd, F_SETFL, ::fcntl(line_fd, F_GETFL) | O_NONBLOCK);
  struct sigaction action {};
  action.sa_sigaction = onForbiddenCall;
  action.sa_flags = SA_SIGINFO;
  sigemptyset(&action.sa_mask);
  if (::sigaction(SIGSYS, &action, nullptr) != 0) return std::string("sigaction(SIGSYS): ") + std::strerror(errno);
  return "";
}

// The rules that keep the watch from being silenced: its handler stays, its line stays open.
// `allow`: also allow those calls otherwise (a filter whose default refuses).
int keepTheWatch(scmp_filter_ctx ctx, int line_fd, bool allow) {
  int rc = seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(rt_sigaction), 1, SCMP_A0(SCMP_CMP_EQ, SIGSYS));
  if (allow) rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(rt_sigaction), 1, SCMP_A0(SCMP_CMP_NE, SIGSYS));
  if (line_fd < 0) {
    if (allow) {
      for (const int call : {SCMP_SYS(close), SCMP_SYS(dup2), SCMP_SYS(dup3), SCMP_SYS(close_range)}) {
        rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, call, 0);
      }
    }
    return rc;
  }
  const auto fd = static_cast<scmp_datum_t>(line_fd);
  rc |= seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EBADF), SCMP_SYS(close), 1, SCMP_A0(SCMP_CMP_EQ, fd));
  rc |= seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EBUSY), SCMP_SYS(dup2), 1, SCMP_A1(SCMP_CMP_EQ, fd));
  rc |= seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EBUSY), SCMP_SYS(dup3), 1, SCMP_A1(SCMP_CMP_EQ, fd));
  rc |= seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(close_range), 2, SCMP_A0(SCMP_CMP_LE, fd),
                         SCMP_A1(SCMP_CMP_GE, fd));
  if (allow) {
    rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(close), 1, SCMP_A0(SCMP_CMP_NE, fd));
    rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(dup2), 1, SCMP_A1(SCMP_CMP_NE, fd));
    rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(dup3), 1, SCMP_A1(SCMP_CMP_NE, fd));
    rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(close_range), 1, SCMP_A0(SCMP_CMP_GT, fd));
    rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(close_range), 1, SCMP_A1(SCMP_CMP_LT, fd));
  }
  return rc;
}

// Loads `ctx` into this process (every thread) when all its rules (`rc`) were added.
std::string load(scmp_filter_ctx ctx, int rc) {
  if (rc != 0) return "a seccomp rule could not be added";
  if (seccomp_load(ctx) != 0) return std::string("seccomp_load: ") + std::strerror(errno);
  return "";
}

// A second filter, stacked on the list (the kernel takes the stricter answer of the two): a signal
// goes to this process, its threads or its children only, which are numbered after it in its
// process namespace (its component, bubblewrap's init and every process outside are numbered
// before it, or not seen); never a process group (0, negative) and never a stop signal (a stopped
// process uses no time a budget counts: it would stall the run). Its own filter because libseccomp
// compares an argument once a rule, and the range `own <= pid <= INT_MAX` takes two; 32-bit
// comparisons, as the kernel reads a pid and a signal.
std::string signalsStayInside() {
  std::unique_ptr<void, void (*)(scmp_filter_ctx)> ctx(seccomp_init(SCMP_ACT_ALLOW), seccomp_release);
  if (!ctx) return "seccomp_init failed";
  int rc = seccomp_attr_set(ctx.get(), SCMP_FLTATR_CTL_TSYNC, 1);
  const auto own = static_cast<scmp_datum_t>(::getpid());
  struct Signalling {
    int call;
    unsigned target, signal;  // argument numbers
  };
  for (const Signalling s : {Signalling{SCMP_SYS(kill), 0, 1}, Signalling{SCMP_SYS(tkill), 0, 1},
                             Signalling{SCMP_SYS(tgkill), 0, 2}}) {
    rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_TRAP, s.call, 1, SCMP_CMP32(s.target, SCMP_CMP_LT, own));
    rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_TRAP, s.call, 1, SCMP_CMP32(s.target, SCMP_CMP_GT, 0x7fffffffu));
    for (const int stop : {SIGSTOP, SIGTSTP, SIGTTIN, SIGTTOU}) {
      rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_TRAP, s.call, 1,
                             SCMP_CMP32(s.signal, SCMP_CMP_EQ, static_cast<scmp_datum_t>(stop)));
    }
  }
  return load(ctx.get(), rc);
}

}  // namespace

std::vector<std::string> forbiddenCalls() { return {kForbidden.begin(), kForbidden.end()}; }

std::string watchForbiddenCalls(int line_fd) {
#if !defined(__x86_64__) && !defined(__aarch64__)
  (void)line_fd;
  return "the forbidden-call watch knows no registers of this architecture";
#else
  if (std::string why = installHandler(line_fd, false); !why.empty()) return why;
  std::unique_ptr<void, void (*)(scmp_filter_ctx)> ctx(seccomp_init(SCMP_ACT_ALLOW), seccomp_release);
  if (!ctx) return "seccomp_init failed";
  int rc = seccomp_attr_set(ctx.get(), SCMP_FLTATR_CTL_TSYNC, 1);
  for (const char* name : kForbidden) {
    const int number = seccomp_syscall_resolve_name(name);
    if (number >= 0) rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_TRAP, number, 0);
  }
  rc |= keepTheWatch(ctx.get(), line_fd, false);
  return load(ctx.get(), rc);
#endif
}

std::string allowOnlyAlgorithmCalls(int line_fd) {
#if !defined(__x86_64__) && !defined(__aarch64__)
  (void)line_fd;
  return "the algorithm's list of system calls knows no registers of this architecture";
#else
  if (std::string why = installHandler(line_fd, true); !why.empty()) return why;
  std::unique_ptr<void, void (*)(scmp_filter_ctx)> ctx(seccomp_init(SCMP_ACT_TRAP), seccomp_release);
  if (!ctx) return "seccomp_init failed";
  int rc = seccomp_attr_set(ctx.get(), SCMP_FLTATR_CTL_TSYNC, 1);
  // A binary tree of the call numbers: each call is checked in a few comparisons, not 150.
  rc |= seccomp_attr_set(ctx.get(), SCMP_FLTATR_CTL_OPTIMIZE, 2);
  for (const char* name : kAlgorithmCalls) {
    const int number = seccomp_syscall_resolve_name(name);  // some are x86_64's alone (open, stat, fork...)
    if (number >= 0) rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_ALLOW, number, 0);
  }
  // Threads and children, in no namespace of their own. clone3 passes its flags in memory, where
  // no filter looks: refused as unknown (ENOSYS), the C library then calls clone.
  const scmp_datum_t namespaces = CLONE_NEWNS | CLONE_NEWUSER | CLONE_NEWPID | CLONE_NEWNET | CLONE_NEWIPC |
                                  CLONE_NEWUTS | CLONE_NEWCGROUP;
  rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_ALLOW, SCMP_SYS(clone), 1, SCMP_A0(SCMP_CMP_MASKED_EQ, namespaces, 0));
  rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0);
  // A terminal's state may be read, never written (TIOCSTI types into the teacher's terminal).
  for (const unsigned long request : {TCGETS, TIOCGWINSZ, TIOCGPGRP, FIONREAD, FIONBIO, FIOCLEX, FIONCLEX}) {
    rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_ALLOW, SCMP_SYS(ioctl), 1, SCMP_A1(SCMP_CMP_EQ, request));
  }
  rc |= keepTheWatch(ctx.get(), line_fd, true);
  if (std::string why = load(ctx.get(), rc); !why.empty()) return why;
  return signalsStayInside();
#endif
}

void endForForbiddenTry(int line_fd, const std::string& program, const std::string& what) {
  if (line_fd >= 0) {
    const std::string line = kRefusedPrefix + what + "\n";
    (void)!::write(line_fd, line.data(), line.size());
  }
  std::cerr << program << ": the algorithm tried to " << what << ", which no student's algorithm may: the run ends"
            << std::endl;
  std::_Exit(process::kExitAlgorithmForbidden);
}

}  // namespace aula::sandbox
