// A student's vacuum algorithm that attacks its exam from inside execute(), once, and says on
// stderr what each try gave ("exam: <try>: done" / "exam: <try>: refused (<why>)"); then it
// stays still. Which attack: AULA_EXAM_ATTACK, defined by the submission's MyAlgorithm.cpp that
// includes this file (tests/attacks/test_exam.cpp writes one folder per attack):
// - "read": read each file named in $AULA_EXAM_READ (colon-separated: a classmate's
//   MyAlgorithm.cpp, the out folder's grades, a teacher's world, /home);
// - "udp": send a datagram to 127.0.0.1 and to LCM's group on $AULA_EXAM_PORT, where a listener
//   outside the run waits;
// - "memory": allocate and touch 3 GB;
// - "fork": start processes until refused, and keep trying;
// - "privilege": what a root sandbox once allowed (issue 28): unmount /proc, remount / read-write,
//   make a user namespace of its own (to get capabilities back), write a file in $AULA_EXAM_WRITE;
// - "reference": drive with the component's own reference (makeReferenceAlgorithm, declared here
//   since the API no longer does);
// - "reexec": start the component again in its own process, with --Vacuum.Algorithm=reference;
// - "exit": exit(0) from inside execute();
// - "_exit": _exit(0) from inside execute() (no atexit handler runs: the component's exit() watch
//   never sees it);
// - "flood": 64 MB to stdout;
// - "detach": 20 children in sessions of their own, SIGTERM blocked, that would outlive the run.
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <arpa/inet.h>
#include <sched.h>
#include <csignal>
#include <sys/mount.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace aula::vacuum {
std::unique_ptr<VacuumAlgorithm> makeReferenceAlgorithm(uint64_t seed);
}  // namespace aula::vacuum

namespace exam {

inline void say(const std::string& what, bool done, int error = 0) {
  if (done) std::fprintf(stderr, "exam: %s: done\n", what.c_str());
  else std::fprintf(stderr, "exam: %s: refused (%s)\n", what.c_str(), std::strerror(error));
}

inline void readFiles() {
  std::stringstream names(std::getenv("AULA_EXAM_READ") != nullptr ? std::getenv("AULA_EXAM_READ") : "");
  std::string path;
  while (std::getline(names, path, ':')) {
    errno = 0;
    std::ifstream in(path);
    std::string first;
    const bool opened = static_cast<bool>(in);
    say("read " + path, opened, errno != 0 ? errno : ENOENT);
  }
}

inline void sendDatagrams() {
  const char* port = std::getenv("AULA_EXAM_PORT");
  for (const char* address : {"127.0.0.1", "239.255.76.67"}) {
    const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(static_cast<uint16_t>(std::atoi(port != nullptr ? port : "9")));
    ::inet_pton(AF_INET, address, &to.sin_addr);
    const char secret[] = "a classmate's MyAlgorithm.cpp";
    const bool sent = fd >= 0 && ::sendto(fd, secret, sizeof secret, 0, reinterpret_cast<sockaddr*>(&to), sizeof to) > 0;
    say(std::string("send to ") + address, sent, errno);
    if (fd >= 0) ::close(fd);
  }
}

inline void useMemory() {
  const size_t size = 3ull << 30;
  std::unique_ptr<char[]> block(new char[size]);
  std::memset(block.get(), 1, size);
  say("use 3 GB", block[size - 1] == 1);
}

inline void forkForever() {
  for (;;) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::pause();
      ::_exit(0);
    }
  }
}

inline void tryPrivileges() {
  say("unmount /proc", ::umount2("/proc", MNT_DETACH) == 0, errno);
  say("remount / read-write", ::mount(nullptr, "/", nullptr, MS_REMOUNT | MS_BIND, nullptr) == 0, errno);
  say("make a user namespace", ::unshare(CLONE_NEWUSER) == 0, errno);
  const char* target = std::getenv("AULA_EXAM_WRITE");
  errno = 0;
  std::ofstream out(target != nullptr ? target : "/nonexistent");
  say("write " + std::string(target != nullptr ? target : ""), static_cast<bool>(out), errno != 0 ? errno : ENOENT);
}

// The component's own command line, its algorithm made the reference, run in this process.
inline void reexecAsReference() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::vector<std::string> args;
  for (std::string arg; std::getline(in, arg, '\0');) {
    args.push_back(arg.rfind("--Vacuum.Algorithm=", 0) == 0 ? "--Vacuum.Algorithm=reference" : arg);
  }
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  ::execv("/proc/self/exe", argv.data());
  say("re-execute the component", false, errno);
}

inline void flood() {
  std::string line(1023, 'x');
  line += '\n';
  for (int i = 0; i < 64 * 1024; ++i) std::fwrite(line.data(), 1, line.size(), stdout);
  std::fflush(stdout);
}

inline void detachChildren() {
  for (int i = 0; i < 20; ++i) {
    if (::fork() == 0) {
      ::setsid();
      sigset_t term;
      sigemptyset(&term);
      sigaddset(&term, SIGTERM);
      sigprocmask(SIG_BLOCK, &term, nullptr);
      // The test tells its own children from another test's by their length of sleep.
      const char* length = std::getenv("AULA_EXAM_SLEEP");
      const char* args[] = {"sleep", length != nullptr ? length : "1000", nullptr};
      ::execvp("sleep", const_cast<char* const*>(args));
      ::_exit(0);
    }
  }
  say("detach 20 children", true);
}

class ExamAttack : public aula::vacuum::VacuumAlgorithm {
 public:
  explicit ExamAttack(uint64_t seed) {
#ifdef AULA_EXAM_REFERENCE  // only the "reference" attack names it: the others must load
    reference_ = aula::vacuum::makeReferenceAlgorithm(seed);
#else
    (void)seed;
#endif
  }

  void execute(aula::vacuum::VacuumApi& api) override {
    if (reference_) return reference_->execute(api);
    api.motors.sendV(0.0);
    api.motors.sendW(0.0);
    if (done_) return;
    done_ = true;
    const std::string attack = AULA_EXAM_ATTACK;
    if (attack == "read") readFiles();
    if (attack == "udp") sendDatagrams();
    if (attack == "memory") useMemory();
    if (attack == "fork") forkForever();
    if (attack == "privilege") tryPrivileges();
    if (attack == "reexec") reexecAsReference();
    if (attack == "exit") std::exit(0);
    if (attack == "_exit") ::_exit(0);
    if (attack == "flood") flood();
    if (attack == "detach") detachChildren();
  }

 private:
  bool done_ = false;
  std::unique_ptr<aula::vacuum::VacuumAlgorithm> reference_;
};

}  // namespace exam

namespace aula::vacuum {
std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t seed) { return std::make_unique<exam::ExamAttack>(seed); }
}  // namespace aula::vacuum
