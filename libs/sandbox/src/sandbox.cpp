#include "aula/sandbox/sandbox.hpp"

#include <seccomp.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
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
  // Another process's memory.
  for (const int call : {SCMP_SYS(ptrace), SCMP_SYS(process_vm_readv), SCMP_SYS(process_vm_writev)}) {
    rc |= seccomp_rule_add(ctx.get(), SCMP_ACT_ERRNO(EPERM), call, 0);
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
  return {"prlimit", "--data=" + std::to_string(limits.memory_bytes),
          "--nproc=" + std::to_string(limits.processes + kOwnThreads), "--fsize=" + std::to_string(limits.file_bytes),
          "--"};
}

}  // namespace

std::vector<std::string> wrap(const std::vector<std::string>& argv, int seccomp_child_fd, const Confinement& confinement) {
  std::vector<std::string> out = limitsPrefix(confinement.limits);
  out.insert(out.end(), {bubblewrapPath(), "--unshare-user", "--uid", "65534", "--gid", "65534", "--disable-userns",
                         "--cap-drop", "ALL", "--unshare-pid", "--unshare-ipc", "--unshare-uts", "--unshare-cgroup-try",
                         "--die-with-parent", "--new-session"});
  systemBinds(out);
  out.insert(out.end(), {"--dev", "/dev", "--proc", "/proc", "--size", std::to_string(confinement.limits.file_bytes),
                         "--tmpfs", kPrivateTmp, "--dir", kPrivateCache, "--setenv", "TMPDIR", kPrivateTmp, "--setenv",
                         "HOME", kPrivateTmp, "--setenv", "XDG_CACHE_HOME", kPrivateCache});
  for (const std::string& path : confinement.read_only) out.insert(out.end(), {"--ro-bind", path, path});
  for (const auto& [host, inside] : confinement.read_only_at) out.insert(out.end(), {"--ro-bind", host, inside});
  for (const std::string& folder : confinement.folders) out.insert(out.end(), {"--dir", folder});
  for (const auto& [name, value] : confinement.environment) out.insert(out.end(), {"--setenv", name, value});
  // The folders made for the binds above are bwrap's own: read-only too (only /var/tmp is writable).
  out.insert(out.end(), {"--remount-ro", "/"});
  out.insert(out.end(), {"--seccomp", std::to_string(seccomp_child_fd), "--"});
  out.insert(out.end(), argv.begin(), argv.end());
  return out;
}

std::string bubblewrapPath() {
  for (const char* candidate : {"/usr/bin/bwrap", "/bin/bwrap"}) {
    if (::access(candidate, X_OK) == 0) return candidate;
  }
  return "";
}

}  // namespace aula::sandbox
