#pragma once
// Inside a graded run's sandbox, the component's own watch on what the student's code tries: the
// system calls that only an escape needs (mount, umount2, unshare, setns, pivot_root, chroot,
// ptrace, process_vm_readv/writev, kernel modules, reboot, bpf, io_uring, the keyring...) are refused with EPERM, as
// the sandbox refuses them anyway, and each try is said on the launcher's private line
// ("refused mount\n"), so that the run is flagged (the referee's "refused_system_calls").
//
// It is a seccomp filter whose action is SIGSYS (SECCOMP_RET_TRAP), installed before the
// student's plugin is loaded; the handler counts nothing itself: it writes the line and makes the
// call return -EPERM. The same filter keeps the student from silencing it: replacing the SIGSYS
// handler (rt_sigaction) and closing or replacing the line's descriptor (close, dup2, dup3,
// close_range) are refused. A student who blocks SIGSYS and tries anyway is killed by it (the
// kernel's rule for a blocked forced signal): "the algorithm made a system call the sandbox
// forbids (SIGSYS)".

#include <string>
#include <vector>

namespace aula::sandbox {

// The names of those calls ("mount", ..., "io_uring_setup", "keyctl"): the watch traps them, and
// the sandbox's own filter (seccompProgram) refuses them too, for a process that has no watch (a
// build, a component whose watch could not be set).
std::vector<std::string> forbiddenCalls();

// Installs the handler and the filter in this process (every thread); `line_fd` is the
// launcher's private line. Returns "" when done, else why not (no seccomp here, an architecture
// the handler does not know): the caller says so and goes on, the sandbox's own refusals stand.
std::string watchForbiddenCalls(int line_fd);

// The student's algorithm in a process of its own (the component's algorithm box) makes only
// the system calls on a list (memory, the files it may see, threads, children, time, signals,
// its socket to the component): any other is refused (EPERM; socket() EACCES, ioctl() ENOTTY),
// said once on stderr ("the algorithm's process may not call memfd_create(): refused"), and the
// escapes among them (forbiddenCalls(), socket, socketpair, clone into a namespace) said on
// `line_fd` as the watch says them, when it is a graded run's line (else -1): the run is flagged.
// No new socket (the run's bus address is in the component's command line, which any process
// reads), no namespace, no io_uring, no keyring. Returns "" when done, else why not.
std::string allowOnlyAlgorithmCalls(int line_fd);
// The line the handler writes for a forbidden call: "refused " + the call's name.
constexpr const char* kRefusedPrefix = "refused ";

// Ends this process because the student's code tried what no student's algorithm may, `what`
// ("call makeReferenceAlgorithm", "run the algorithm 'reference'"): "refused WHAT" on the
// launcher's private line `line_fd` when there is one (the run is flagged), the reason on stderr
// after `program`, and exit code kExitAlgorithmForbidden, with no destructor or atexit handler
// run (the student's state is not to be trusted).
[[noreturn]] void endForForbiddenTry(int line_fd, const std::string& program, const std::string& what);

}  // namespace aula::sandbox
