#include "aula/component/crash_report.hpp"

#include <aula/process/exit_codes.hpp>
#include <aula/sandbox/forbidden_calls.hpp>

#include <csetjmp>
#include <cstdlib>
#include <csignal>
#include <cstring>
#include <memory>

#include <execinfo.h>
#include <ucontext.h>
#include <unistd.h>

namespace aula::component {

namespace {

constexpr size_t kAltStackBytes = 128 * 1024;  // the handler's buffers and addr2line's output
constexpr int kMaxFrames = 48;
constexpr int kMaxLines = 8;

// A signal handler can only reach process-wide state; this is the one place that holds it, in
// fixed buffers (nothing to allocate while crashing).
struct CrashReportState {
  char program[128] = "";
  PluginImage plugin;
  int fault_fd = -1;
  bool installed = false;
};

CrashReportState& crashState() {
  static CrashReportState state;
  return state;
}

// The call under callSurvivingCrashes on this thread, and what ended it.
thread_local sigjmp_buf* recover_to = nullptr;
thread_local char crash_text[600];
// This thread's alternate signal stack while it runs algorithms; the one it had before is given
// back when the thread ends (before AddressSanitizer's own thread teardown, which unmaps the
// stack it finds installed and cannot unmap ours).
struct AltStack {
  std::unique_ptr<char[]> bytes;
  stack_t previous{};
  ~AltStack() {
    if (bytes) ::sigaltstack(&previous, nullptr);
  }
};
thread_local AltStack alt_stack;

// Text built in a fixed buffer, truncated at its end.
struct Text {
  char* out;
  size_t size, used = 0;
  Text& operator<<(const char* more) {
    const size_t n = std::min(std::strlen(more), size - 1 - used);
    std::memcpy(out + used, more, n);
    used += n;
    out[used] = '\0';
    return *this;
  }
};

void say(const char* text) { (void)!::write(STDERR_FILENO, text, std::strlen(text)); }

const void* faultingInstruction(void* context) {
#if defined(__x86_64__)
  return reinterpret_cast<const void*>(static_cast<ucontext_t*>(context)->uc_mcontext.gregs[REG_RIP]);
#elif defined(__aarch64__)
  return reinterpret_cast<const void*>(static_cast<ucontext_t*>(context)->uc_mcontext.pc);
#else
  (void)context;
  return nullptr;  // every frame is then taken for a return address: the line before, at worst
#endif
}

bool survivable(int signal) { return signal == SIGSEGV || signal == SIGBUS || signal == SIGFPE || signal == SIGILL; }

// Tells the student, on stderr: their lines, innermost first, or the raw stack when none is theirs.
void sayWhere(const CrashReportState& s, const char* signal_name, const StudentLine* lines, int found, void** frames,
              int count) {
  char head[1024];
  Text text{head, sizeof head};
  text << s.program << ": crashed (" << signal_name << ")";
  if (found == 0) {
    say((text << "; the stack, innermost first:\n").out);
    ::backtrace_symbols_fd(frames, count, STDERR_FILENO);
    bool in_plugin = false;
    for (int i = 0; i < count; ++i) in_plugin = in_plugin || s.plugin.holds(frames[i]);
    if (in_plugin) {  // addr2line missing, or the plugin rebuilt since it was loaded
      say("  frames in a lib*.so(+0xOFFSET) loaded from ~/.cache/aula/plugins are in your plugin, ");
      say(s.plugin.path);
      say(":\n  addr2line -f -C -e ");
      say(s.plugin.path);
      say(" 0xOFFSET   names the function and line\n");
    }
    return;
  }
  for (int i = 0; i < found; ++i) {
    const bool again = i > 0 && std::strcmp(lines[i].where, lines[i - 1].where) == 0;
    if (again && i + 1 < found) continue;  // a recursion: its line once, and the last frame found
    if (i > 0) text = Text{head, sizeof head} << (again ? "  ... called from " : "  called from ");
    if (i == 0) text << " in your algorithm at ";
    text << lines[i].where;
    if (lines[i].function[0] != '\0') text << " (" << lines[i].function << ")";
    say((text << "\n").out);
  }
}

// The handler of every crash signal: the student's lines, then back into the call that crashed
// (callSurvivingCrashes) or death by the same signal, the launcher told the one line first.
void onCrash(int signal, siginfo_t*, void* context) {
  const CrashReportState& s = crashState();
  void* frames[kMaxFrames];
  const int count = ::backtrace(frames, kMaxFrames);
  StudentLine lines[kMaxLines];
  const int found = studentLines(s.plugin, frames, count, faultingInstruction(context), lines, kMaxLines);
  char signal_name[16];
  const char* abbrev = sigabbrev_np(signal);
  Text{signal_name, sizeof signal_name} << "SIG" << (abbrev != nullptr ? abbrev : "?");
  sayWhere(s, signal_name, lines, found, frames, count);
  // "crashed (SIGSEGV) at MyAlgorithm.cpp:14 (MyAlgorithm::execute)": the fault's one line.
  char crash[sizeof crash_text];
  Text text{crash, sizeof crash};
  text << "crashed (" << signal_name << ")";
  if (found > 0) text << " at " << lines[0].where;
  if (found > 0 && lines[0].function[0] != '\0') text << " (" << lines[0].function << ")";
  if (recover_to != nullptr && survivable(signal)) {
    std::memcpy(crash_text, crash, sizeof crash_text);
    siglongjmp(*recover_to, 1);
  }
  if (s.fault_fd >= 0) {
    text << "\n";
    (void)!::write(s.fault_fd, crash, text.used);
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

void copyInto(char* buffer, size_t size, const std::string& text) {
  const size_t n = std::min(size - 1, text.size());
  std::memcpy(buffer, text.data(), n);
  buffer[n] = '\0';
}

void giveThisThreadAnAltStack() {
  if (alt_stack.bytes) return;
  auto bytes = std::make_unique<char[]>(kAltStackBytes);
  stack_t stack{};
  stack.ss_sp = bytes.get();
  stack.ss_size = kAltStackBytes;
  if (::sigaltstack(&stack, &alt_stack.previous) == 0) alt_stack.bytes = std::move(bytes);
}

// Runs the call armed; disarmed when it returns or throws (a crash disarms in the caller).
void armedCall(const std::function<void()>& call, sigjmp_buf* here) {
  struct Disarm {
    ~Disarm() { recover_to = nullptr; }
  } disarm;
  recover_to = here;
  call();
}

}  // namespace

// LeakSanitizer's interface, present only in a sanitizer build (weak: null otherwise).
extern "C" void __lsan_ignore_object(const void* object) __attribute__((weak));

void abandonAfterCrash(const void* object) {
  if (__lsan_ignore_object != nullptr && object != nullptr) __lsan_ignore_object(object);
}

void installCrashReport(const std::string& program, const PluginImage& plugin) {
  CrashReportState& s = crashState();
  copyInto(s.program, sizeof s.program, program);
  s.plugin = plugin;
  giveThisThreadAnAltStack();
  if (s.installed) return;
  s.installed = true;
  void* warm_up[1];
  ::backtrace(warm_up, 1);  // loads libgcc now: backtrace() may allocate the first time
  struct sigaction action {};
  action.sa_sigaction = onCrash;
  action.sa_flags = SA_SIGINFO | SA_ONSTACK;
  sigemptyset(&action.sa_mask);
  for (int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::sigaction(signal, &action, nullptr);
}

void reportCrashesTo(int fd) { crashState().fault_fd = fd; }

int crashLineFd() { return crashState().fault_fd; }

void endForForbiddenCall(const std::string& what) {
  const CrashReportState& s = crashState();
  sandbox::endForForbiddenTry(s.fault_fd, s.program, what);
}

const char* const kOverranPrefix = "overran ";

void endForOverrun(const std::string& program, const std::string& why) {
  const CrashReportState& s = crashState();
  if (s.fault_fd >= 0) {
    const std::string line = kOverranPrefix + why + "\n";
    (void)!::write(s.fault_fd, line.data(), line.size());
  }
  const std::string said = program + ": the student's algorithm: " + why + "; ending the run\n";
  (void)!::write(STDERR_FILENO, said.data(), said.size());
  std::_Exit(process::kExitAlgorithmHung);
}

void prepareThreadForCrashes() {
  giveThisThreadAnAltStack();
  sigset_t faults;
  sigemptyset(&faults);
  for (int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) sigaddset(&faults, signal);
  pthread_sigmask(SIG_UNBLOCK, &faults, nullptr);
}

std::string callSurvivingCrashes(const std::function<void()>& call) {
  sigjmp_buf here;
  if (sigsetjmp(here, 1) != 0) {
    recover_to = nullptr;
    return crash_text;
  }
  armedCall(call, &here);
  return "";
}

}  // namespace aula::component
