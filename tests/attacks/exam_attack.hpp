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
// - "find-reference": find the reference anyway: its plugin beside the component
//   (<bin>/../lib/aula/references), opened with dlopen, else makeReferenceAlgorithm in the
//   component's own symbol tables (read from /proc/self/exe, called at the program's load
//   address); drive with whichever it found;
// - "reexec": start the component again in its own process, with --Vacuum.Algorithm=reference;
// - "exit": exit(0) from inside execute();
// - "_exit": _exit(0) from inside execute() (no atexit handler runs: the component's exit() watch
//   never sees it);
// - "flood": 4 MB to stdout in each execute(), without end;
// - "detach": 20 children in sessions of their own, SIGTERM blocked, that would outlive the run.
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <arpa/inet.h>
#include <dlfcn.h>
#include <elf.h>
#include <link.h>
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
#include <filesystem>
#include <fstream>
#include <iterator>
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

using MakeReference = std::unique_ptr<aula::vacuum::VacuumAlgorithm> (*)(uint64_t);

// The program's load address (a PIE): dl_iterate_phdr's first object is the program itself.
inline uintptr_t programBias() {
  uintptr_t bias = 0;
  dl_iterate_phdr([](dl_phdr_info* info, size_t, void* out) {
    *static_cast<uintptr_t*>(out) = info->dlpi_addr;
    return 1;
  }, &bias);
  return bias;
}

// `name`'s address from the program file's own symbol tables (.symtab, .dynsym), or nullptr.
inline void* symbolInProgram(const char* name) {
  std::ifstream in("/proc/self/exe", std::ios::binary);
  const std::string elf((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (elf.size() < sizeof(Elf64_Ehdr)) return nullptr;
  const auto* header = reinterpret_cast<const Elf64_Ehdr*>(elf.data());
  if (header->e_shoff == 0 || header->e_shoff + header->e_shnum * sizeof(Elf64_Shdr) > elf.size()) return nullptr;
  const auto* sections = reinterpret_cast<const Elf64_Shdr*>(elf.data() + header->e_shoff);
  for (int i = 0; i < header->e_shnum; ++i) {
    if (sections[i].sh_type != SHT_SYMTAB && sections[i].sh_type != SHT_DYNSYM) continue;
    const char* names = elf.data() + sections[sections[i].sh_link].sh_offset;
    const auto* symbols = reinterpret_cast<const Elf64_Sym*>(elf.data() + sections[i].sh_offset);
    for (size_t k = 0; k < sections[i].sh_size / sizeof(Elf64_Sym); ++k) {
      if (symbols[k].st_value != 0 && std::strcmp(names + symbols[k].st_name, name) == 0) {
        return reinterpret_cast<void*>(programBias() + symbols[k].st_value);
      }
    }
  }
  return nullptr;
}

// The reference, found beside the component or in it: nullptr when neither could be had.
inline std::unique_ptr<aula::vacuum::VacuumAlgorithm> findReference(uint64_t seed) {
  std::error_code error;
  const auto bin = std::filesystem::read_symlink("/proc/self/exe", error).parent_path();
  const std::string plugin = (bin.parent_path() / "lib/aula/references/libaula_vacuum_reference.so").string();
  void* handle = ::dlopen(plugin.c_str(), RTLD_NOW | RTLD_LOCAL);
  using Factory = aula::vacuum::VacuumAlgorithm* (*)(uint64_t);
  auto factory = handle != nullptr ? reinterpret_cast<Factory>(::dlsym(handle, "aula_vacuum_algorithm_v1")) : nullptr;
  say("load the reference's plugin", factory != nullptr, ENOENT);
  if (factory != nullptr) return std::unique_ptr<aula::vacuum::VacuumAlgorithm>(factory(seed));
  if (void* make = symbolInProgram("_ZN4aula6vacuum22makeReferenceAlgorithmEm")) {
    say("find makeReferenceAlgorithm in the component", true);
    return reinterpret_cast<MakeReference>(make)(seed);
  }
  say("find makeReferenceAlgorithm in the component", false, ENOENT);
  return nullptr;
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
  for (int i = 0; i < 4 * 1024; ++i) std::fwrite(line.data(), 1, line.size(), stdout);
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
    if (std::string(AULA_EXAM_ATTACK) == "find-reference") reference_ = findReference(seed);
#endif
  }

  void execute(aula::vacuum::VacuumApi& api) override {
    if (reference_) return reference_->execute(api);
    api.motors.sendV(0.0);
    api.motors.sendW(0.0);
    const std::string attack = AULA_EXAM_ATTACK;
    if (attack == "flood") flood();
    if (done_) return;
    done_ = true;
    if (attack == "read") readFiles();
    if (attack == "udp") sendDatagrams();
    if (attack == "memory") useMemory();
    if (attack == "fork") forkForever();
    if (attack == "privilege") tryPrivileges();
    if (attack == "reexec") reexecAsReference();
    if (attack == "exit") std::exit(0);
    if (attack == "_exit") ::_exit(0);
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
