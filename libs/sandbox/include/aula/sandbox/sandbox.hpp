#pragma once
// The sandbox a graded student's code runs in (`aula grade`, `aula run --sandbox`): the component
// that hosts the student's plugin is started under bubblewrap (Debian's `bwrap`) with
// - the whole filesystem read-only, a private temporary folder (a fresh /var/tmp, TMPDIR), and
//   writable only the folders given;
// - its own process namespace: it sees no other process (no /proc of the simulator or the
//   referee, nothing to ptrace or signal) and dies with its parent;
// - its own IPC and host-name namespaces;
// - a seccomp filter (libseccomp): sockets only of the kind LCM's multicast uses (IPv4 datagram),
//   so no TCP, no Unix, IPv6, raw or netlink sockets; no ptrace, no process_vm_readv/writev.
// The network namespace stays the host's: LCM's multicast must cross between the sandbox and the
// simulator. What this does and does not stop is in docs/grading.md ("What a student's code can
// do").

#include <string>
#include <vector>

namespace aula::sandbox {

// The seccomp program above, as a file descriptor that bubblewrap reads (`--seccomp FD`): a
// memory file, rewound. The caller passes it to the child and closes its own copy. Throws
// std::runtime_error when libseccomp cannot build it.
int seccompProgram();

// `argv` wrapped in bubblewrap: the sandbox above, with the seccomp program read from the
// child's descriptor `seccomp_child_fd`, and `writable` folders bound read-write.
std::vector<std::string> wrap(const std::vector<std::string>& argv, int seccomp_child_fd,
                              const std::vector<std::string>& writable = {});

// Where bubblewrap is ("" when it is not installed: `aula run --sandbox` then refuses to run).
std::string bubblewrapPath();

}  // namespace aula::sandbox
