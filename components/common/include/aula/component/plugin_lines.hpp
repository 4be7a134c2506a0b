#pragma once
// The student's lines: addresses in a plugin turned into "MyAlgorithm.cpp:14" and the function
// ("MyAlgorithm::execute"), by addr2line on the plugin's debug info (aula_add_algorithm builds
// it with -g). The one resolver for a throw's site (PluginLibrary::throwSite) and a crash's stack
// (crash_report.hpp): it allocates nothing and runs /usr/bin/addr2line with vfork, execv, a pipe,
// read and waitpid, all async-signal-safe, so a signal handler may call it.

#include <cstdint>

namespace aula::component {

// Where a plugin is mapped, and the file its debug info is read from: filled when it is loaded.
struct PluginImage {
  char path[1024] = "";
  uintptr_t load_address = 0;    // the link map's l_addr: addr2line's offsets are from it
  uintptr_t begin = 0, end = 0;  // its loaded segments
  int64_t mtime_ns = -1;         // the file's time when loaded: a rebuild since has other lines
  bool holds(const void* address) const;
};

// One frame's line in the student's file.
struct StudentLine {
  char where[256] = "";     // "MyAlgorithm.cpp:14"
  char function[256] = "";  // "MyAlgorithm::execute" ("" when addr2line cannot tell)
};

// The student's line of each of `frames` that is in the plugin, innermost first: inlined library
// code (headers under /usr) gives way to the student's line that called it; a frame with no such
// line is left out, and so is every frame when the file changed since it was loaded. `exact` is
// the frame that is an instruction's own address (a crash's faulting one), not a return address
// (the others name the call before them). Returns how many of `out` were filled.
int studentLines(const PluginImage& image, void* const* frames, int count, const void* exact, StudentLine* out,
                 int capacity);

}  // namespace aula::component
