#include "aula/sandbox/sandbox.hpp"

#include "aula/sandbox/forbidden_calls.hpp"

#include <seccomp.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include <sys/mman.h>
#include <sys/socket.h>
#include <unistd.h>

namespace aula::sandbox {

int seccompProgram() {
  std::unique_ptr<void, void (*)(scmp_filter_ctx)> ctx(seccomp_init(SCMP_ACT_ALLOW), seccomp_release);
  if (!ctx) throw std::runtime_error("sandbox: seccomp_init failed");
  const uint32_t refuse = SCMP_ACT_ERRNO(EACCES);
  int rc = 0;
  // Sockets: IPv4 datagrams only (LCM's UDP multicast).
  rc |= seccomp_rule_add(ctx.get(), refuse, SCMP_SYS(socket), 1, SCMP_A0(SCMP_CMP_NE, AF_INET));
  for (const scmp_datum_t type : {SOCK_STREAM, SOCK_RAW, SOCK_RDM, SOCK_SEQPACKET, SOCK_PACKET}) {
    rc |= seccomp_rule_add(ctx.get(), refuse, SCMP_SYS(socket), 1, SCMP_A1(SCMP_CMP_MASKED_EQ, 0xf, type));
  }
  // The calls only an escape needs (another process's memory, mounts, io_uring, the keyring...):
  // refused here too, for a process without the component's watch (forbidden_calls.hpp), which
  // traps them first and says so.
  for (const std::string& name : forbiddenCalls()) {
    const int call = seccomp_syscall_resolve_name(name.c_str());
    if (call != __NR_SCMP_ERROR) rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_ERRNO(EPERM), call, 0);
  }
  if (rc != 0) throw std::runtime_error("sandbox: a seccomp rule could not be added");
  const int fd = memfd_create("aula-seccomp", MFD_CLOEXEC);
  if (fd < 0) throw std::runtime_error("sandbox: memfd_create failed");
  if (seccomp_export_bpf(ctx.get(), fd) != 0 || lseek(fd, 0, SEEK_SET) != 0) {
    close(fd);
    throw std::runtime_error("sandbox: the seccomp program could not be written");
  }
  return fd;
}

namespace {

// The system's programs and libraries: /usr, and the top-level folders Debian links into it
// (/lib -> usr/lib) as the same links; the few files of /etc a program's start reads.
void systemBinds(std::vector<std::string>& out) {
  out.insert(out.end(), {"--ro-bind", "/usr", "/usr"});
  for (const char* top : {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"}) {
    std::error_code error;
    const auto status = std::filesystem::symlink_status(top, error);
    if (error || !std::filesystem::exists(status)) continue;
    if (std::filesystem::is_symlink(status)) {
      out.insert(out.end(), {"--symlink", std::filesystem::read_symlink(top).string(), top});
    } else {
      out.insert(out.end(), {"--ro-bind", top, top});
    }
  }
  for (const char* file : {"/etc/ld.so.cache", "/etc/localtime", "/etc/alternatives", "/etc/passwd", "/etc/group"}) {
    if (std::filesystem::exists(file)) out.insert(out.end(), {"--ro-bind", file, file});
  }
}

std::vector<std::string> limitsPrefix(const Limits& limits) {
  std::vector<std::string> out = {"prlimit", "--as=" + std::to_string(limits.memory_bytes),
                                  "--nproc=" + std::to_string(limits.processes + kOwnThreads),
                                  "--fsize=" + std::to_string(limits.file_bytes)};
  if (limits.cpu_s > 0) out.push_back("--cpu=" + std::to_string(limits.cpu_s));
  out.push_back("--");
  return out;
}

// A cleared environment, then kKeptEnvironment from ours, the sandbox's own and `environment`.
void environmentOf(const Confinement& confinement, std::vector<std::string>& out) {
  out.insert(out.end(), {"--clearenv", "--setenv", "PATH", "/usr/local/bin:/usr/bin:/bin", "--setenv", "TMPDIR",
                         kPrivateTmp, "--setenv", "HOME", kPrivateTmp, "--setenv", "XDG_CACHE_HOME", kPrivateCache,
                         // One thread of numpy's BLAS: a run has one CPU, and each thread reserves
                         // address space that the memory limit counts.
                         "--setenv", "OPENBLAS_NUM_THREADS", "1", "--setenv", "OMP_NUM_THREADS", "1"});
  for (const char* name : kKeptEnvironment) {
    const char* value = std::getenv(name);
    if (value != nullptr) out.insert(out.end(), {"--setenv", name, value});
  }
  for (const auto& [name, value] : confinement.environment) out.insert(out.end(), {"--setenv", name, value});
}

}  // namespace

std::vector<std::string> wrap(const std::vector<std::string>& argv, int seccomp_child_fd, const Confinement& confinement) {
  std::vector<std::string> out = limitsPrefix(confinement.limits);
  out.insert(out.end(), {bubblewrapPath(), "--unshare-user", "--uid", "65534", "--gid", "65534", "--disable-userns",
                         "--cap-drop", "ALL", "--unshare-pid", "--unshare-ipc", "--unshare-uts", "--unshare-cgroup-try",
                         "--die-with-parent", "--new-session"});
  if (confinement.own_network) out.push_back("--unshare-net");
  systemBinds(out);
  // /dev/shm: a small tmpfs of its own (the host's is shared and as large as the RAM).
  out.insert(out.end(), {"--dev", "/dev", "--size", std::to_string(confinement.limits.shm_bytes), "--tmpfs", "/dev/shm",
                         "--proc", "/proc", "--size", std::to_string(confinement.limits.file_bytes), "--tmpfs",
                         kPrivateTmp, "--dir", kPrivateCache});
  environmentOf(confinement, out);
  for (const std::string& path : confinement.hidden) out.insert(out.end(), {"--perms", "0555", "--tmpfs", path});
  for (const std::string& path : confinement.read_only) out.insert(out.end(), {"--ro-bind", path, path});
  for (const auto& [host, inside] : confinement.read_only_at) out.insert(out.end(), {"--ro-bind", host, inside});
  for (const std::string& folder : confinement.folders) out.insert(out.end(), {"--dir", folder});
  for (const auto& [host, inside] : confinement.writable_at) out.insert(out.end(), {"--bind", host, inside});
  // The folders made for the binds above are bwrap's own: read-only too (only /var/tmp, /dev/shm
  // and the writable binds, mounts of their own, stay writable).
  out.insert(out.end(), {"--remount-ro", "/"});
  if (!confinement.working_dir.empty()) out.insert(out.end(), {"--chdir", confinement.working_dir});
  out.insert(out.end(), {"--seccomp", std::to_string(seccomp_child_fd), "--"});
  out.insert(out.end(), argv.begin(), argv.end());
  return out;
}

uint64_t memoryOf(const std::vector<int>& processes) {
  uint64_t total_kb = 0;
  for (const int pid : processes) {
    std::ifstream rollup("/proc/" + std::to_string(pid) + "/smaps_rollup");
    for (std::string line; std::getline(rollup, line);) {
      if (line.rfind("Pss:", 0) != 0) continue;
      total_kb += std::strtoull(line.c_str() + 4, nullptr, 10);
      break;
    }
  }
  return total_kb << 10;
}

std::string bubblewrapPath() {
  for (const char* candidate : {"/usr/bin/bwrap", "/bin/bwrap"}) {
    if (::access(candidate, X_OK) == 0) return candidate;
  }
  return "";
}

}  // namespace aula::sandbox
