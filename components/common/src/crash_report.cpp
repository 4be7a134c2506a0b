#include "aula/component/crash_report.hpp"

#include <csignal>
#include <cstring>

#include <execinfo.h>
#include <unistd.h>

namespace aula::component {

namespace {

// A signal handler can only reach process-wide state; this is the one place that holds it, in
// fixed buffers (nothing to allocate while crashing).
struct CrashReportState {
  char program[128] = "";
  char plugin[1024] = "";
  bool installed = false;
};

CrashReportState& crashState() {
  static CrashReportState state;
  return state;
}

void say(const char* text) { (void)!::write(STDERR_FILENO, text, std::strlen(text)); }

void onCrash(int signal) {
  const CrashReportState& s = crashState();
  say(s.program);
  say(": crashed (");
  const char* name = sigabbrev_np(signal);
  say("SIG");
  say(name != nullptr ? name : "?");
  say("); the stack, innermost first:\n");
  void* frames[48];
  const int count = ::backtrace(frames, 48);
  ::backtrace_symbols_fd(frames, count, STDERR_FILENO);
  if (s.plugin[0] != '\0') {
    say("  frames in a lib*.so(+0xOFFSET) loaded from ~/.cache/aula/plugins are in your plugin, ");
    say(s.plugin);
    say(":\n  addr2line -f -C -e ");
    say(s.plugin);
    say(" 0xOFFSET   names the function and line\n");
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

void copyInto(char* buffer, size_t size, const std::string& text) {
  const size_t n = std::min(size - 1, text.size());
  std::memcpy(buffer, text.data(), n);
  buffer[n] = '\0';
}

}  // namespace

void installCrashReport(const std::string& program, const std::string& plugin_path) {
  CrashReportState& s = crashState();
  copyInto(s.program, sizeof s.program, program);
  copyInto(s.plugin, sizeof s.plugin, plugin_path);
  if (s.installed) return;
  s.installed = true;
  void* warm_up[1];
  ::backtrace(warm_up, 1);  // loads libgcc now: backtrace() may allocate the first time
  for (int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(signal, onCrash);
}

}  // namespace aula::component
