// The algorithm's end of its own process (algorithm_box_main.hpp): what the exercise's
// runAlgorithmBox calls around the hosted algorithm. The component's end is algorithm_box.cpp.
#include "aula/component/algorithm_box_main.hpp"

#include <aula/component/plugin_library.hpp>
#include <aula/config/paths.hpp>
#include <aula/sandbox/file_view.hpp>
#include <aula/sandbox/forbidden_calls.hpp>
#include <aula/sandbox/sandbox.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include <dlfcn.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

namespace aula::component {

namespace {

// Whether this process runs under AddressSanitizer (scripts/sanitize-check.sh): its runtime is
// loaded. (That build undefines __SANITIZE_ADDRESS__, for Eigen's sake: CMakeLists.txt.)
bool underAddressSanitizer() { return ::dlsym(RTLD_DEFAULT, "__asan_init") != nullptr; }

// A graded run's algorithm process sees only what running an algorithm needs: the system's files,
// Aula's programs and runtime, the student's plugin (or the folder of their MyAlgorithm.py), and
// a folder of its own to write in (its TMPDIR, HOME and cache: a plugin's copy goes there). Not
// the run's world, its parsed cache or its settings, which the sandbox binds for the component.
std::string narrowGradedView(const BoxStart& start) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path own = fs::temp_directory_path(error) / "algorithm";
  fs::create_directories(own, error);
  if (error) return own.string() + ": " + error.message();
  for (const char* name : {"TMPDIR", "HOME", "XDG_CACHE_HOME"}) ::setenv(name, own.c_str(), 1);
  sandbox::FileView view;
  view.readable = {"/usr", "/lib", "/lib64", "/lib32", "/bin", "/sbin", "/etc", "/proc", "/sys", config::libDir(),
                   fs::read_symlink("/proc/self/exe", error).parent_path().string()};
  if (AlgorithmHostBase::namesPlugin(start.choice)) {  // else a built-in, under libDir()
    const fs::path algorithm = fs::absolute(start.choice, error).lexically_normal();
    view.readable.push_back(PluginLibrary::isPythonFile(start.choice) ? algorithm.parent_path().string()
                                                                      : algorithm.string());
  }
  view.writable = {own.string(), "/dev/null", "/dev/zero", "/dev/full", "/dev/random", "/dev/urandom"};
  return sandbox::narrowFileView(view);
}

// The algorithm's end of the socket (one per process).
FrameReader& boxFrames() {
  static FrameReader frames(kBoxSocketFd, /*wait_in_poll=*/true);
  return frames;
}

}  // namespace

bool enterAlgorithmBox(BoxStart& start, AlgorithmBudgets& budgets) {
  ::close_range(kBoxLineFd + 1, ~0U, 0);
  // A component hands its box an open socket; a box without one was started by the algorithm of
  // an earlier one (it re-executed its own program, whose socket closes on exec): that is its end.
  if (::fcntl(kBoxSocketFd, F_GETFD) < 0) {
    sandbox::endForForbiddenTry(kBoxLineFd, "the algorithm's process", "run the algorithm's process again");
  }
  ::fcntl(kBoxSocketFd, F_SETFD, FD_CLOEXEC);  // no program it runs (addr2line, its own) holds it
  std::string frame;
  try {
    if (!boxFrames().read(frame, 1 << 20)) return false;
    BoxWire wire = BoxWire::reading(std::move(frame));
    uint8_t type = 0;
    wire.io(type, "start");
    if (type != static_cast<uint8_t>(BoxMessage::Start)) return false;
    ioStart(wire, start, budgets);
    wire.expectEnd("start");
  } catch (const BoxWireError& e) {
    std::cerr << "--algorithm-box: " << e.what() << std::endl;
    return false;
  }
  // Its memory, in every run (a sandbox's limit is on the component already, and may be lower).
  // Not in an AddressSanitizer build (scripts/sanitize-check.sh): its shadow memory is terabytes
  // of address space, and under any such limit its first mapping fails.
  rlimit memory{};
  if (underAddressSanitizer() && budgets.memory_bytes > 0) {
    std::cerr << start.program << ": under AddressSanitizer the algorithm's process has no address-space limit "
              << "(Component.Sandbox.Memory): the sanitizer's shadow memory would not fit in it" << std::endl;
  } else if (budgets.memory_bytes > 0 && ::getrlimit(RLIMIT_AS, &memory) == 0 &&
      (memory.rlim_cur == RLIM_INFINITY || memory.rlim_cur > budgets.memory_bytes)) {
    memory.rlim_cur = budgets.memory_bytes;
    if (memory.rlim_max != RLIM_INFINITY && memory.rlim_max < memory.rlim_cur) memory.rlim_cur = memory.rlim_max;
    ::setrlimit(RLIMIT_AS, &memory);
  }
  reportCrashesTo(kBoxLineFd);  // a crash's, an overrun's and a forbidden try's line: the component's
  // Only the calls an algorithm needs (forbidden_calls.hpp): no socket of its own, not the run's
  // bus (its address is in the component's command line, which any process may read), not any
  // other. A graded run's (in its sandbox) flags the escapes among the rest, as the component's
  // watch flagged them when the algorithm ran inside it.
  const bool graded = static_cast<bool>(std::ifstream(sandbox::kGradedAlgorithmFile));
  if (graded) {
    if (const std::string why = narrowGradedView(start); !why.empty()) {
      std::cerr << start.program << ": " << why << ": the algorithm's process sees the sandbox's files" << std::endl;
    }
  }
  if (const std::string why = sandbox::allowOnlyAlgorithmCalls(graded ? kBoxLineFd : -1); !why.empty()) {
    std::cerr << start.program << ": " << why << ": the algorithm's process may make any system call" << std::endl;
  }
  return true;
}

void endAlgorithmBox() {
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  if (underAddressSanitizer()) std::exit(0);
  ::_exit(0);
}

void sayRefused(const std::string& why) {
  BoxWire wire = BoxWire::writing();
  auto type = static_cast<uint8_t>(BoxMessage::Refused);
  std::string text = why;
  wire.io(type, "refused");
  wire.io(text, 1 << 16, "refused");
  writeFrame(kBoxSocketFd, wire.bytes());
}

void sayLoaded(const AlgorithmHostBase& host) {
  BoxWire wire = BoxWire::writing();
  auto type = static_cast<uint8_t>(BoxMessage::Loaded);
  std::string path = host.pluginPath(), name = host.name(), label = host.label();
  bool builtin = host.isBuiltin();
  wire.io(type, "loaded");
  wire.io(path, 4096, "loaded");
  wire.io(name, 4096, "loaded");
  wire.io(label, 4096, "loaded");
  wire.io(builtin, "loaded");
  writeFrame(kBoxSocketFd, wire.bytes());
}

bool readCall(std::string& frame, BoxWire& wire, uint64_t& seed, CallKind& kind, const char*& what,
              std::set<std::string>& names) {
  if (!boxFrames().read(frame, kMaxReplyBytes)) return false;
  wire = BoxWire::reading(std::move(frame));
  uint8_t type = 0;
  int32_t kind_code = 0;
  std::string name;
  wire.io(type, "call");
  if (type != static_cast<uint8_t>(BoxMessage::Call)) throw BoxWireError("call: message " + std::to_string(type));
  wire.io(seed, "call");
  wire.io(kind_code, "call");
  wire.io(name, 256, "call");
  kind = static_cast<CallKind>(kind_code);
  what = names.insert(name).first->c_str();
  return true;
}

void sendReply(const std::string& fault, const std::string& printed, const Motors& motors,
               const std::function<void(BoxWire&)>& outputs) {
  BoxWire wire = BoxWire::writing();
  auto type = static_cast<uint8_t>(BoxMessage::Reply);
  std::string f = fault, p = printed;
  int64_t v = motors.nonFiniteV(), w = motors.nonFiniteW(), l = motors.nonFiniteL();
  wire.io(type, "reply");
  wire.io(f, 1 << 20, "reply");
  wire.io(p, kMaxReplyBytes, "reply");
  wire.io(v, "reply");
  wire.io(w, "reply");
  wire.io(l, "reply");
  outputs(wire);
  writeFrame(kBoxSocketFd, wire.bytes());
}

}  // namespace aula::component
