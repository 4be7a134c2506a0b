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
#include <ucontext.h>
#include <unistd.h>

namespace aula::sandbox {

namespace {

struct ForbiddenCall {
  int number;
  const char* name;
};

// The calls only an escape needs. Resolved by libseccomp for this architecture.
constexpr std::array<const char*, 28> kForbidden = {
    "mount",         "umount2",          "unshare",     "setns",          "pivot_root",  "chroot",
    "ptrace",        "process_vm_readv", "process_vm_writev", "init_module", "finit_module", "delete_module",
    "kexec_load",    "reboot",           "open_by_handle_at", "bpf",      "move_mount",  "open_tree",
    "fsopen",        "fsmount",          "fspick",      "mount_setattr",
    // io_uring's requests open sockets and files without the calls the filter looks at (a TCP or
    // Unix socket past socket()'s rule); the keyring holds the caller's session keys.
    "io_uring_setup", "io_uring_enter",  "io_uring_register", "keyctl",    "add_key",     "request_key"};

// What the SIGSYS handler reads: a signal handler reaches only process-wide state, and this is
// its one place, filled before the filter is installed and never written after.
struct WatchState {
  std::array<ForbiddenCall, kForbidden.size()> calls{};
  int line_fd = -1;
};

WatchState& watchState() {
  static WatchState state;
  return state;
}

void onForbiddenCall(int, siginfo_t* info, void* context) {
  const WatchState& state = watchState();
  const char* name = "a forbidden system call";
  for (const ForbiddenCall& call : state.calls) {
    if (call.name != nullptr && call.number == info->si_syscall) name = call.name;
  }
  char line[96];
  const size_t prefix = std::strlen(kRefusedPrefix), length = std::min(std::strlen(name), sizeof line - prefix - 2);
  std::memcpy(line, kRefusedPrefix, prefix);
  std::memcpy(line + prefix, name, length);
  line[prefix + length] = '\n';
  const int saved_errno = errno;
  (void)!::write(state.line_fd, line, prefix + length + 1);
  errno = saved_errno;
  // The call returns -EPERM, as the sandbox would have answered it.
  auto* uc = static_cast<ucontext_t*>(context);
#if defined(__x86_64__)
  uc->uc_mcontext.gregs[REG_RAX] = -EPERM;
#elif defined(__aarch64__)
  uc->uc_mcontext.regs[0] = static_cast<unsigned long long>(-EPERM);
#else
  (void)uc;
#endif
}

}  // namespace

std::vector<std::string> forbiddenCalls() { return {kForbidden.begin(), kForbidden.end()}; }

std::string watchForbiddenCalls(int line_fd) {
#if !defined(__x86_64__) && !defined(__aarch64__)
  (void)line_fd;
  return "the forbidden-call watch knows no registers of this architecture";
#else
  WatchState& state = watchState();
  state.line_fd = line_fd;
  // A loop of tries must never block the handler on a full pipe: past it, lines are dropped.
  ::fcntl(line_fd, F_SETFL, ::fcntl(line_fd, F_GETFL) | O_NONBLOCK);
  for (size_t i = 0; i < kForbidden.size(); ++i) {
    state.calls[i] = {seccomp_syscall_resolve_name(kForbidden[i]), kForbidden[i]};
  }
  struct sigaction action {};
  action.sa_sigaction = onForbiddenCall;
  action.sa_flags = SA_SIGINFO;
  sigemptyset(&action.sa_mask);
  if (::sigaction(SIGSYS, &action, nullptr) != 0) return std::string("sigaction(SIGSYS): ") + std::strerror(errno);

  std::unique_ptr<void, void (*)(scmp_filter_ctx)> ctx(seccomp_init(SCMP_ACT_ALLOW), seccomp_release);
  if (!ctx) return "seccomp_init failed";
  int rc = seccomp_attr_set(ctx.get(), SCMP_FLTATR_CTL_TSYNC, 1);
  for (const ForbiddenCall& call : state.calls) {
    if (call.number >= 0) rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_TRAP, call.number, 0);
  }
  // The watch cannot be silenced: its handler stays, its line stays open.
  const auto fd = static_cast<scmp_datum_t>(line_fd);
  rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_ERRNO(EPERM), SCMP_SYS(rt_sigaction), 1, SCMP_A0(SCMP_CMP_EQ, SIGSYS));
  rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_ERRNO(EBADF), SCMP_SYS(close), 1, SCMP_A0(SCMP_CMP_EQ, fd));
  rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_ERRNO(EBUSY), SCMP_SYS(dup2), 1, SCMP_A1(SCMP_CMP_EQ, fd));
  rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_ERRNO(EBUSY), SCMP_SYS(dup3), 1, SCMP_A1(SCMP_CMP_EQ, fd));
  rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_ERRNO(EPERM), SCMP_SYS(close_range), 2, SCMP_A0(SCMP_CMP_LE, fd),
                         SCMP_A1(SCMP_CMP_GE, fd));
  if (rc != 0) return "a seccomp rule could not be added";
  if (seccomp_load(ctx.get()) != 0) return std::string("seccomp_load: ") + std::strerror(errno);
  return "";
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

std::string refuseNewSockets() {
  std::unique_ptr<void, void (*)(scmp_filter_ctx)> ctx(seccomp_init(SCMP_ACT_ALLOW), seccomp_release);
  if (!ctx) return "seccomp_init failed";
  int rc = seccomp_attr_set(ctx.get(), SCMP_FLTATR_CTL_TSYNC, 1);
  rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_ERRNO(EACCES), SCMP_SYS(socket), 0);
  rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_ERRNO(EACCES), SCMP_SYS(socketpair), 0);
  if (rc != 0) return "a seccomp rule could not be added";
  if (seccomp_load(ctx.get()) != 0) return std::string("seccomp_load: ") + std::strerror(errno);
  return "";
}

}  // namespace aula::sandbox
