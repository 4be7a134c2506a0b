#include "aula/sandbox/file_view.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>

#include <fcntl.h>
#include <linux/landlock.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace aula::sandbox {

namespace {

// Debian 12's kernel headers stop at Landlock's ABI 2; later rights by their numbers.
constexpr uint64_t kTruncate = 1ULL << 14;  // LANDLOCK_ACCESS_FS_TRUNCATE, ABI 3

constexpr uint64_t kRead = LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR;
constexpr uint64_t kWrite = LANDLOCK_ACCESS_FS_WRITE_FILE | LANDLOCK_ACCESS_FS_REMOVE_DIR |
                            LANDLOCK_ACCESS_FS_REMOVE_FILE | LANDLOCK_ACCESS_FS_MAKE_CHAR | LANDLOCK_ACCESS_FS_MAKE_DIR |
                            LANDLOCK_ACCESS_FS_MAKE_REG | LANDLOCK_ACCESS_FS_MAKE_SOCK | LANDLOCK_ACCESS_FS_MAKE_FIFO |
                            LANDLOCK_ACCESS_FS_MAKE_BLOCK | LANDLOCK_ACCESS_FS_MAKE_SYM;
// What a rule on a file (not a folder) may grant.
constexpr uint64_t kFileRights = LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_READ_FILE |
                                 LANDLOCK_ACCESS_FS_WRITE_FILE | kTruncate;

// Every right this kernel's Landlock knows of the files: all of them handled, so none is left open.
uint64_t handledRights(int abi) {
  uint64_t rights = kRead | kWrite;
  if (abi >= 2) rights |= LANDLOCK_ACCESS_FS_REFER;
  if (abi >= 3) rights |= kTruncate;
  return rights;
}

class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

// Adds `path` with `rights` (those the ruleset handles); a missing path is left out.
std::string allow(int ruleset, const std::string& path, uint64_t rights) {
  const Descriptor beneath(::open(path.c_str(), O_PATH | O_CLOEXEC));
  if (beneath.get() < 0) return errno == ENOENT ? "" : path + ": " + std::strerror(errno);
  struct stat info {};
  if (::fstat(beneath.get(), &info) != 0) return path + ": " + std::strerror(errno);
  landlock_path_beneath_attr rule{};
  rule.allowed_access = S_ISDIR(info.st_mode) ? rights : rights & kFileRights;
  rule.parent_fd = beneath.get();
  if (::syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0) != 0) {
    return path + ": landlock_add_rule: " + std::strerror(errno);
  }
  return "";
}

}  // namespace

std::string narrowFileView(const FileView& view) {
  const long abi = ::syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
  if (abi < 1) return std::string("no Landlock in this kernel (") + std::strerror(errno) + ")";
  landlock_ruleset_attr attributes{};
  attributes.handled_access_fs = handledRights(static_cast<int>(abi));
  const Descriptor ruleset(static_cast<int>(::syscall(SYS_landlock_create_ruleset, &attributes, sizeof attributes, 0)));
  if (ruleset.get() < 0) return std::string("landlock_create_ruleset: ") + std::strerror(errno);
  const uint64_t handled = attributes.handled_access_fs;
  for (const std::string& path : view.readable) {
    if (std::string why = allow(ruleset.get(), path, kRead & handled); !why.empty()) return why;
  }
  for (const std::string& path : view.writable) {
    if (std::string why = allow(ruleset.get(), path, handled); !why.empty()) return why;
  }
  if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return std::string("PR_SET_NO_NEW_PRIVS: ") + std::strerror(errno);
  if (::syscall(SYS_landlock_restrict_self, ruleset.get(), 0) != 0) {
    return std::string("landlock_restrict_self: ") + std::strerror(errno);
  }
  return "";
}

}  // namespace aula::sandbox
