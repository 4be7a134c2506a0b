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

std::vector<std::string> wrap(const std::vector<std::string>& argv, int seccomp_child_fd,
                              const std::vector<std::string>& writable) {
  // /tmp stays visible (read-only): the world, the settings or the plugin may be there. The
  // private temporary folder is a fresh /var/tmp (a directory bwrap cannot create under the
  // read-only root must already exist).
  std::vector<std::string> out = {bubblewrapPath(), "--ro-bind", "/", "/", "--dev", "/dev", "--proc", "/proc",
                                  "--tmpfs", "/var/tmp", "--setenv", "TMPDIR", "/var/tmp", "--unshare-pid",
                                  "--unshare-ipc", "--unshare-uts", "--die-with-parent", "--new-session"};
  for (const std::string& dir : writable) {
    out.insert(out.end(), {"--bind", dir, dir});
  }
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
