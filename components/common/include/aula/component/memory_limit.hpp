#pragma once
// Why a sandboxed (graded) run's algorithm ran out of memory, in the same words whatever its
// language: the sandbox's limit (RLIMIT_AS, Component.Sandbox.Memory) is what refused it, so a
// C++ std::bad_alloc and a Python MemoryError both say "the algorithm used more than 2048 MB of
// memory". Not part of the student's API (not installed): the component and the Python host.

#include <sys/resource.h>

#include <string>

namespace aula::component {

// "the algorithm used more than N MB of memory" when this process has a memory limit, else "".
inline std::string memoryLimitReason() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return "";
  return "the algorithm used more than " + std::to_string(limit.rlim_cur >> 20) + " MB of memory";
}

}  // namespace aula::component
