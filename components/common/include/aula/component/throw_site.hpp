#pragma once
// Where a C++ exception was thrown: every throw in a component passes through __cxa_throw, which
// the component defines (and exports, so a plugin's throws come here too) to keep the thrower's
// stack before it hands over to the C++ runtime. The algorithm host then names the student's
// line (PluginLibrary::throwSite) instead of only the exception's text.

namespace aula::component {

// The stack of the last exception thrown on this thread.
struct ThrowStack {
  const void* object = nullptr;  // the exception object (dynamic_cast<const void*> of what is caught)
  int count = 0;
  void* frames[48] = {};  // return addresses, innermost first (frame 0 is __cxa_throw's own)
};

const ThrowStack& lastThrowOnThisThread();

// Throw sites are kept on this thread only while one of these lives: around a call into a C++
// plugin, the only place whose throw site is ever named. Never in a Python algorithm's calls:
// they run on greenlets, which throw C++ exceptions of their own (a paused program ended with
// GreenletExit), and the unwinder cannot walk a greenlet's stack past its start: backtrace() read
// what lay beyond it and crashed the component (SIGSEGV at the first call after a Reload,
// gui.RoboticsAcademyProgramWithWindowsReloadsAndParks on Debian 13).
class KeepThrowSites {
 public:
  KeepThrowSites();
  ~KeepThrowSites();
  KeepThrowSites(const KeepThrowSites&) = delete;
  KeepThrowSites& operator=(const KeepThrowSites&) = delete;

 private:
  bool was_;
};

}  // namespace aula::component
