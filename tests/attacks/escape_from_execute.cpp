// A student's vacuum algorithm that tries to leave its process from inside execute(), once, and
// says on stderr what each try gave ("escape: <try>: done" or "escape: <try>: refused (...)"):
// - write a file into escape-target-cpp beside the component's program (a folder the test owns;
//   found from /proc/self/exe, since a sandboxed run has none of the test's environment);
// - find the simulator and the referee among the processes it can see (/proc);
// - open a TCP socket, and a Unix socket (the way out of a UDP-only sandbox);
// - read another process's memory (ptrace the simulator or the referee if it sees one, else its
//   parent process).
// It then stays still. Sandboxed (`aula run --sandbox`, `aula grade`) every try must be refused;
// without the sandbox they succeed, which is what shows that the test can fail.
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <sys/ptrace.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

namespace aula::vacuum {
namespace {

void say(const char* what, bool done, int error = 0) {
  if (done) {
    std::fprintf(stderr, "escape: %s: done\n", what);
  } else {
    std::fprintf(stderr, "escape: %s: refused (%s)\n", what, std::strerror(error));
  }
}

void tryEverything() {
  {
    std::error_code error;
    const auto bin = std::filesystem::read_symlink("/proc/self/exe", error).parent_path();
    const std::string path = (bin / "escape-target-cpp" / "escaped.txt").string();
    FILE* file = std::fopen(path.c_str(), "w");
    say("write a file outside", file != nullptr, errno);
    if (file != nullptr) std::fclose(file);
  }
  int others = 0;
  pid_t other_pid = -1;
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(entry.path() / "cmdline", std::ios::binary);
    const std::string cmdline((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (cmdline.find("aula-sim") != std::string::npos || cmdline.find("referee") != std::string::npos) {
      ++others;
      if (other_pid < 0) other_pid = std::stoi(name);
    }
  }
  if (others > 0) {
    say("see the simulator or the referee in /proc", true);
  } else {
    say("see the simulator or the referee in /proc", false, ESRCH);
  }
  for (const auto& [what, domain, type] : {std::make_tuple("open a TCP socket", AF_INET, SOCK_STREAM),
                                            std::make_tuple("open a Unix socket", AF_UNIX, SOCK_STREAM)}) {
    const int fd = ::socket(domain, type, 0);
    say(what, fd >= 0, errno);
    if (fd >= 0) ::close(fd);
  }
  const pid_t target = other_pid > 0 ? other_pid : ::getppid();
  if (::ptrace(PTRACE_ATTACH, target, nullptr, nullptr) == 0) {
    ::waitpid(target, nullptr, 0);
    ::ptrace(PTRACE_DETACH, target, nullptr, nullptr);
    say("ptrace another process", true);
  } else {
    say("ptrace another process", false, errno);
  }
}

class EscapeFromExecute : public VacuumAlgorithm {
 public:
  void execute(VacuumApi& api) override {
    api.motors.sendV(0.0);
    api.motors.sendW(0.0);
    if (tried_) return;
    tried_ = true;
    tryEverything();
  }

 private:
  bool tried_ = false;
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<EscapeFromExecute>(); }

}  // namespace aula::vacuum
