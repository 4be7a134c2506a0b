// A student's vacuum algorithm that attacks its exam from inside execute(), once, and says on
// stderr what each try gave ("exam: <try>: done" / "exam: <try>: refused (<why>)"); then it
// stays still. Which attack: AULA_EXAM_ATTACK, defined by the submission's MyAlgorithm.cpp that
// includes this file (tests/attacks/test_exam.cpp writes one folder per attack):
// The test's values come in the submission's own source (a graded run's environment is the
// sandbox's, not the test's): AULA_EXAM_READ_LIST, AULA_EXAM_PORT_NUMBER, AULA_EXAM_WRITE_PATH
// defined before this file is included; a plugin built without them (run without the sandbox,
// the tests' control) reads $AULA_EXAM_READ, $AULA_EXAM_PORT, $AULA_EXAM_WRITE instead.
// - "read": read each file named in AULA_EXAM_READ (colon-separated: a classmate's
//   MyAlgorithm.cpp, the out folder's grades, a teacher's world, /home);
// - "udp": send a datagram to 127.0.0.1 and to LCM's group on AULA_EXAM_PORT, where a listener
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
// - "detach": 20 children in sessions of their own, SIGTERM blocked, that would outlive the run;
// - "keyring": read the key "aula-exam-secret" of the session keyring (keyctl), where the test
//   put it: a teacher's session keys;
// - "io_uring": set up an io_uring (whose requests make sockets without socket());
// - "shared-memory": map 3 GB of shared memory and touch it, and fill a file in /dev/shm with
//   256 MB;
// - "fork-memory": three children, each with 800 MB of its own written (under the limit of one
//   process, 2.4 GB together), that stay; said done once all three have written theirs;
// - "world-in-exception": throw an exception whose message holds 2 KB of the run's world file (its
//   path from the component's --Vacuum.World=), its path and the process's environment.
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <arpa/inet.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/syscall.h>
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
#include <stdexcept>
#include <string>
#include <vector>

namespace aula::vacuum {
std::unique_ptr<VacuumAlgorithm> makeReferenceAlgorithm(uint64_t seed);
}  // namespace aula::vacuum

namespace exam {

// The test's value: the macro the submission defined, else the environment's variable.
#define AULA_EXAM_SETTING(macro, variable) exam::setting(macro##_GIVEN, macro##_VALUE, variable)
inline const char* setting(bool given, const char* value, const char* variable) {
  return given ? value : std::getenv(variable);
}
#ifdef AULA_EXAM_READ_LIST
#define AULA_EXAM_READ_GIVEN true
#define AULA_EXAM_READ_VALUE AULA_EXAM_READ_LIST
#else
#define AULA_EXAM_READ_GIVEN false
#define AULA_EXAM_READ_VALUE nullptr
#endif
#ifdef AULA_EXAM_PORT_NUMBER
#define AULA_EXAM_PORT_GIVEN true
#define AULA_EXAM_PORT_VALUE AULA_EXAM_PORT_NUMBER
#else
#define AULA_EXAM_PORT_GIVEN false
#define AULA_EXAM_PORT_VALUE nullptr
#endif
#ifdef AULA_EXAM_WRITE_PATH
#define AULA_EXAM_WRITE_GIVEN true
#define AULA_EXAM_WRITE_VALUE AULA_EXAM_WRITE_PATH
#else
#define AULA_EXAM_WRITE_GIVEN false
#define AULA_EXAM_WRITE_VALUE nullptr
#endif

inline void say(const std::string& what, bool done, int error = 0) {
  if (done) std::fprintf(stderr, "exam: %s: done\n", what.c_str());
  else std::fprintf(stderr, "exam: %s: refused (%s)\n", what.c_str(), std::strerror(error));
}

inline void readFiles() {
  const char* list = AULA_EXAM_SETTING(AULA_EXAM_READ, "AULA_EXAM_READ");
  std::stringstream names(list != nullptr ? list : "");
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
  const char* port = AULA_EXAM_SETTING(AULA_EXAM_PORT, "AULA_EXAM_PORT");
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
  const char* target = AULA_EXAM_SETTING(AULA_EXAM_WRITE, "AULA_EXAM_WRITE");
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

// Each ends in "done" only when the key's payload was read.
inline void readKeyring() {
  const long key = ::syscall(SYS_keyctl, 10 /* KEYCTL_SEARCH */, -3 /* KEY_SPEC_SESSION_KEYRING */, "user",
                             "aula-exam-secret", 0);
  if (key < 0) return say("read the session keyring", false, errno);
  char payload[256] = {};
  const long read = ::syscall(SYS_keyctl, 11 /* KEYCTL_READ */, key, payload, sizeof payload - 1);
  say("read the session keyring", read > 0, errno);
  if (read > 0) std::fprintf(stderr, "exam: the key holds %s\n", payload);
}

inline void setUpIoUring() {
  char params[120] = {};  // struct io_uring_params, zeroed
  const long fd = ::syscall(SYS_io_uring_setup, 8, params);
  say("set up an io_uring", fd >= 0, errno);
  if (fd >= 0) ::close(static_cast<int>(fd));
}

inline void useSharedMemory() {
  const size_t size = 3ull << 30;
  void* block = ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (block == MAP_FAILED) {
    say("map 3 GB of shared memory", false, errno);
  } else {
    std::memset(block, 1, size);
    say("map 3 GB of shared memory", true);
    ::munmap(block, size);
  }
  const int fd = ::open("/dev/shm/aula-exam", O_WRONLY | O_CREAT | O_TRUNC, 0600);
  std::string chunk(1 << 20, 'x');
  int written = 0, error = fd < 0 ? errno : 0;
  while (fd >= 0 && written < 256 && ::write(fd, chunk.data(), chunk.size()) == static_cast<ssize_t>(chunk.size())) ++written;
  if (fd >= 0 && written < 256) error = errno;
  say("write 256 MB in /dev/shm", written == 256, error);
  if (fd >= 0) ::close(fd);
}

// Starts the children; each writes a byte on `ready` once its memory is written.
inline void forkMemory(int ready) {
  for (int i = 0; i < 3; ++i) {
    if (::fork() != 0) continue;
    const size_t size = 800ull << 20;
    void* block = ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (block != MAP_FAILED) std::memset(block, 1, size);
    (void)!::write(ready, block != MAP_FAILED ? "y" : "n", 1);
    for (;;) ::pause();
  }
}

// Waits up to 0.1 s (within an execute(): the run goes on meanwhile) for the children's bytes:
// true when all three came.
inline bool forkedMemoryReady(int ready, int& count) {
  pollfd watched{ready, POLLIN, 0};
  while (count < 3 && ::poll(&watched, 1, 100) > 0) {
    char said = 0;
    if (::read(ready, &said, 1) != 1) break;
    if (said == 'y') ++count;
  }
  return count == 3;
}

[[noreturn]] inline void throwTheWorld() {
  // The world's path is in the component's command line: its own, or its parent's when the
  // algorithm runs in a process of its own.
  std::string world;
  for (const std::string& process : {std::string("self"), std::to_string(::getppid())}) {
    std::ifstream cmdline("/proc/" + process + "/cmdline", std::ios::binary);
    for (std::string arg; world.empty() && std::getline(cmdline, arg, '\0');) {
      if (arg.rfind("--Vacuum.World=", 0) == 0) world = arg.substr(15);
    }
  }
  std::ifstream in(world);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string environment;
  for (char** variable = environ; *variable != nullptr; ++variable) environment += std::string(*variable) + " ";
  throw std::runtime_error("the world " + world + " reads: " + text.substr(0, 2048) + " and the environment: " + environment);
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
    if (attack == "fork-memory" && done_ && ready_[0] >= 0 && forkedMemoryReady(ready_[0], ready_count_)) {
      say("three children of 800 MB each", true);
      ::close(ready_[0]);
      ready_[0] = -1;
    }
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
    if (attack == "keyring") readKeyring();
    if (attack == "io_uring") setUpIoUring();
    if (attack == "shared-memory") useSharedMemory();
    if (attack == "world-in-exception") throwTheWorld();
    if (attack == "fork-memory" && ::pipe(ready_) == 0) forkMemory(ready_[1]);
  }

 private:
  bool done_ = false;
  int ready_[2] = {-1, -1};  // fork-memory: the children's "written" line
  int ready_count_ = 0;
  std::unique_ptr<aula::vacuum::VacuumAlgorithm> reference_;
};

}  // namespace exam

namespace aula::vacuum {
std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t seed) { return std::make_unique<exam::ExamAttack>(seed); }
}  // namespace aula::vacuum
