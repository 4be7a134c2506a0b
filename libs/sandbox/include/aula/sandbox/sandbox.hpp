#pragma once
// The sandbox a graded student's code runs in (`aula grade`, `aula run --sandbox`). The component
// that hosts the student's plugin (or MyAlgorithm.py) is started under bubblewrap (Debian's
// `bwrap`) and sees nothing but its own inputs (docs/grading.md, "What a student's code can do"):
// - a filesystem of exactly what the component opens: the system's programs and libraries
//   (/usr), Aula's runtime (its program, lib/aula), the run's settings file, the run's world and
//   the model files it was read from, the student's plugin, a private temporary folder (a fresh
//   /var/tmp of bounded size: TMPDIR, HOME and the cache; a small /dev/shm of its own); no home
//   folder, no class folder, no out folder, no other world, no calibration file (Confinement,
//   filled by the launcher); an environment of a few variables (kKeptEnvironment);
// - an unprivileged user of its own (uid 65534 in a user namespace of its own), with no
//   capability and no way to make another user namespace: no mount, no remount, no unmount;
// - its own process namespace: it sees no other process (no /proc of the simulator or the
//   referee, nothing to ptrace or signal) and dies with its parent; its own IPC and host name;
// - a seccomp filter (libseccomp): sockets only of the kind LCM's multicast uses (IPv4 datagram),
//   so no TCP, no Unix, IPv6, raw or netlink sockets; no ptrace, no process_vm_readv/writev; no
//   io_uring (whose requests make sockets without socket()); no keyring (keyctl, add_key,
//   request_key: the caller's session keyring);
// - resource limits with a reason each (Limits): memory, processes, file size.
// A submission's build runs in the same sandbox (grade/submission_build.hpp), with a folder of
// its own to write and no network at all (Confinement::own_network).
// The network is the run's own (enterPrivateNetwork: the launcher and its three processes in a
// network namespace with only a loopback), so nothing the student sends leaves the run.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace aula::sandbox {

// What a sandboxed process may use; past a limit the run ends with that limit's reason.
struct Limits {
  // RLIMIT_AS: everything each of its processes maps (heap, stacks, shared and file mappings), so
  // a 3 GB shared mmap is refused as a 3 GB heap is (RLIMIT_DATA let shared mappings through).
  uint64_t memory_bytes = 2ull << 30;
  int processes = 64;                  // processes it may start (its own threads aside)
  uint64_t file_bytes = 64ull << 20;   // RLIMIT_FSIZE, and the size of its private /var/tmp
  // Its own /dev/shm (the host's is shared by everyone and as large as the RAM): a tmpfs this
  // size, under file_bytes, so that filling it says "No space left on device" (ENOSPC).
  uint64_t shm_bytes = 16ull << 20;
  uint64_t output_bytes = 256ull << 20;  // its stdout and stderr together (counted by the launcher)
  uint64_t cpu_s = 0;                  // RLIMIT_CPU of each process (0: none; a run has its own clocks)
  // The sandbox's processes that are Aula's, not started by the student: bubblewrap's, the
  // component, and the algorithm's own process when it has one (Component.OwnProcess).
  int aula_processes = 2;
};

// The threads a component runs by itself (the algorithm's thread, the watchdog, the bus, TBB's
// workers), counted in RLIMIT_NPROC beside the processes a student may start.
constexpr int kOwnThreads = 32;

// What the sandboxed process sees of the filesystem and its environment.
struct Confinement {
  std::vector<std::string> read_only;  // files or folders, at their own paths
  std::vector<std::pair<std::string, std::string>> read_only_at;  // host path, path inside
  std::vector<std::pair<std::string, std::string>> writable_at;   // host folder, path inside (a build's folder)
  std::vector<std::string> folders;    // empty folders made inside (a data folder's worlds/)
  // Folders inside that a bind above would show and that must stay out of reach (the built-in
  // algorithms' plugins, <prefix>/lib/aula/references, when Aula is installed under /usr): an
  // empty read-only folder there. A bind above (the one built-in a run runs) still shows in it.
  std::vector<std::string> hidden;
  // Set inside, after the environment is cleared: the process sees only these, kKeptEnvironment
  // taken from the launcher's, and PATH, TMPDIR, HOME, XDG_CACHE_HOME of its own.
  std::vector<std::pair<std::string, std::string>> environment;
  bool own_network = false;  // a network namespace with a loopback alone (a build); a run has the launcher's
  std::string working_dir;   // where it starts, inside ("" : bubblewrap's default)
  Limits limits;
};

// The launcher's variables a sandboxed process keeps (when set): the locale and Aula's own
// (where its data and models are, the run's bus). Nothing else of the caller's environment (a
// teacher's tokens, paths, SSH agent) reaches the student's code.
constexpr const char* kKeptEnvironment[] = {"LANG", "LC_ALL", "AULA_DATA_DIR", "AULA_MODEL_PATH", "LCM_DEFAULT_URL",
                                            "AULA_BUS_STATS"};

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

// The memory `processes` use together: the sum of each one's proportional share of every page it
// maps (Pss of /proc/PID/smaps_rollup: a page shared by two counts half in each, so a parent and
// its forked children are counted once), in bytes. A process gone meanwhile counts 0. The
// launcher's check of a sandboxed component with processes of its own, each of which has its own
// address-space limit: together they may use no more than Limits::memory_bytes.
uint64_t memoryOf(const std::vector<int>& processes);

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
