// What a process wrapped by sandbox::wrap (bubblewrap, prlimit, the seccomp program) is given,
// read from inside by a shell: an environment of the sandbox's own (none of the caller's but the
// kept few), an address-space limit (RLIMIT_AS: shared mappings count), a /dev/shm of its own as
// small as its temporary folder, no /etc/machine-id or /etc/hostname; and the seccomp program
// refuses io_uring and the keyring. Each compared with the same shell outside the sandbox, where
// it sees otherwise (the test can fail).
#include <aula/process/child_process.hpp>
#include <aula/sandbox/sandbox.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

namespace {
namespace fs = std::filesystem;

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// What the shell says of its world; `boxed`: under sandbox::wrap with `confinement`.
std::string shellSays(bool boxed, const aula::sandbox::Confinement& confinement) {
  const std::string script =
      "env; grep 'Max address space' /proc/self/limits; df -B1 --output=size /dev/shm | tail -1; "
      "cat /etc/machine-id /etc/hostname 2>&1; python3 -c 'import ctypes,os; l=ctypes.CDLL(None,use_errno=True); "
      "r=l.syscall(425,8,ctypes.create_string_buffer(120)); print(\"io_uring\",r,os.strerror(ctypes.get_errno())); "
      "r=l.syscall(250,0,-3,0); print(\"keyctl\",r,os.strerror(ctypes.get_errno()))'";
  std::vector<std::string> argv = {"/bin/sh", "-c", script};
  std::vector<int> passed;
  if (boxed) {
    passed.push_back(aula::sandbox::seccompProgram());
    argv = aula::sandbox::wrap(argv, aula::process::ChildProcess::passedFd(0), confinement);
  }
  const std::string log = (fs::temp_directory_path() / ("aula_wrap_" + std::to_string(::getpid()) + ".log")).string();
  aula::process::ChildProcess shell(argv, log, log, passed);
  for (const int fd : passed) ::close(fd);
  EXPECT_EQ(shell.wait(std::chrono::seconds(30)).value_or(-1), 0) << readAll(log);
  const std::string said = readAll(log);
  fs::remove(log);
  return said;
}

}  // namespace

TEST(SandboxWrap, TheProcessSeesItsOwnEnvironmentLimitsAndSharedMemory) {
  if (aula::sandbox::bubblewrapPath().empty()) GTEST_SKIP() << "no bubblewrap";
  ::setenv("AULA_TEACHER_TOKEN", "teacher-token-4711", 1);
  ::setenv("LANG", "C.UTF-8", 1);
  aula::sandbox::Confinement confinement;
  confinement.limits.memory_bytes = 1ull << 30;
  confinement.limits.shm_bytes = 8ull << 20;
  confinement.environment = {{"AULA_GIVEN", "given"}};
  const std::string inside = shellSays(true, confinement);
  const std::string outside = shellSays(false, confinement);
  ::unsetenv("AULA_TEACHER_TOKEN");

  EXPECT_EQ(inside.find("teacher-token-4711"), std::string::npos) << inside;
  EXPECT_NE(outside.find("teacher-token-4711"), std::string::npos) << outside;
  EXPECT_NE(inside.find("AULA_GIVEN=given"), std::string::npos) << inside;
  EXPECT_NE(inside.find("LANG=C.UTF-8"), std::string::npos) << inside;  // kept
  EXPECT_NE(inside.find("HOME=/var/tmp"), std::string::npos) << inside;
  EXPECT_NE(inside.find("Max address space         1073741824"), std::string::npos) << inside;
  EXPECT_NE(inside.find(" " + std::to_string(8ull << 20) + "\n"), std::string::npos) << inside;  // /dev/shm's size
  EXPECT_EQ(outside.find(" " + std::to_string(8ull << 20) + "\n"), std::string::npos) << outside;
  EXPECT_NE(inside.find("/etc/machine-id: No such file or directory"), std::string::npos) << inside;
  EXPECT_NE(inside.find("/etc/hostname: No such file or directory"), std::string::npos) << inside;
  EXPECT_NE(inside.find("io_uring -1 Operation not permitted"), std::string::npos) << inside;
  EXPECT_NE(inside.find("keyctl -1 Operation not permitted"), std::string::npos) << inside;
  EXPECT_EQ(outside.find("io_uring -1"), std::string::npos) << outside;
}
