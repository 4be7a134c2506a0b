#pragma once
// The sandbox a graded student's code runs in (`aula grade`, `aula run --sandbox`). The component
// that hosts the student's plugin (or MyAlgorithm.py) is started under bubblewrap (Debian's
// `bwrap`) and sees nothing but its own inputs (docs/grading.md, "What a student's code can do"):
// - a filesystem of exactly what the component opens: the system's programs and libraries
//   (/usr), Aula's runtime (its program, lib/aula), the run's settings file, the run's world and
//   the model files it was read from, the student's plugin, a private temporary folder (a fresh
//   /var/tmp of bounded size: TMPDIR, HOME and the cache); no home folder, no class folder, no out
//   folder, no other world, no calibration file (Confinement, filled by the launcher);
// - an unprivileged user of its own (uid 65534 in a user namespace of its own), with no
//   capability and no way to make another user namespace: no mount, no remount, no unmount;
// - its own process namespace: it sees no other process (no /proc of the simulator or the
//   referee, nothing to ptrace or signal) and dies with its parent; its own IPC and host name;
// - a seccomp filter (libseccomp): sockets only of the kind LCM's multicast uses (IPv4 datagram),
//   so no TCP, no Unix, IPv6, raw or netlink sockets; no ptrace, no process_vm_readv/writev;
// - resource limits with a reason each (Limits): memory, processes, file size.
// The network is the run's own (enterPrivateNetwork: the launcher and its three processes in a
// network namespace with only a loopback), so nothing the student sends leaves the run.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace aula::sandbox {

// What a sandboxed process may use; past a limit the run ends with that limit's reason.
struct Limits {
  uint64_t memory_bytes = 2ull << 30;  // RLIMIT_DATA: its heap and private mappings
  int processes = 64;                  // processes it may start (its own threads aside)
  uint64_t file_bytes = 64ull << 20;   // RLIMIT_FSIZE, and the size of its private /var/tmp
  uint64_t output_bytes = 256ull << 20;  // its stdout and stderr together (counted by the launcher)
};

// The threads a component runs by itself (the algorithm's thread, the watchdog, the bus, TBB's
// workers), counted in RLIMIT_NPROC beside the processes a student may start.
constexpr int kOwnThreads = 32;

// What the sandboxed process sees of the filesystem and its environment.
struct Confinement {
  std::vector<std::string> read_only;  // files or folders, at their own paths
  std::vector<std::pair<std::string, std::string>> read_only_at;  // host path, path inside
  std::vector<std::string> folders;    // empty folders made inside (a data folder's worlds/)
  std::vector<std::pair<std::string, std::string>> environment;  // set inside
  Limits limits;
};

// The seccomp program above, as a file descriptor that bubblewrap reads (`--seccomp FD`): a
// memory file, rewound. The caller passes it to the child and closes its own copy. Throws
// std::runtime_error when libseccomp cannot build it.
int seccompProgram();

// `argv` wrapped in bubblewrap (and prlimit for the limits): the sandbox above, with the seccomp
// program read from the child's descriptor `seccomp_child_fd`, seeing only `confinement`.
std::vector<std::string> wrap(const std::vector<std::string>& argv, int seccomp_child_fd, const Confinement& confinement);

// The private temporary folder inside the sandbox: TMPDIR, HOME, and XDG_CACHE_HOME below it.
constexpr const char* kPrivateTmp = "/var/tmp";
constexpr const char* kPrivateCache = "/var/tmp/cache";

// In a graded run's sandbox, a read-only file holding the one algorithm the component may run
// (the grade's plugin or .py): a component started there with any other (a student's plugin that
// re-executes the component with --Vacuum.Algorithm=reference) refuses to start.
constexpr const char* kGradedAlgorithmFile = "/run/aula/graded-algorithm";

// Where bubblewrap is ("" when it is not installed: `aula run --sandbox` then refuses to run).
std::string bubblewrapPath();

// Moves the calling process, which must have no thread yet, into a network namespace of its own
// (and, when it is not root, a user namespace of its own that maps it to root there): only a
// loopback, up, with the multicast route LCM needs. Every process it starts afterwards shares it
// and nothing else: no datagram leaves the run, none reaches it. Returns "" when done, else why
// not (user namespaces not allowed here): the caller says so and goes on with the host's network.
// Throws std::runtime_error when the namespace was made but its loopback could not be set up.
std::string enterPrivateNetwork();

}  // namespace aula::sandbox
