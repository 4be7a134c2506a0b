#pragma once
// A process's descendants, read from /proc (each task's `children` file): how many processes a
// sandboxed component has started (the supervisor ends the run past its limit).

#include <sys/types.h>

#include <vector>

namespace aula::process {

// Every process below `pid` (its children, theirs, ...), not `pid` itself; empty when it is gone.
std::vector<pid_t> descendantsOf(pid_t pid);

// How long every thread of the processes `pids` has waited, runnable, for a CPU (the kernel's
// schedstat run delay), in seconds: the time a busy machine, not a process, took.
double waitedForCpuS(const std::vector<pid_t>& pids);

}  // namespace aula::process
