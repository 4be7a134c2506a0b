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

}  // namespace aula::component
