#pragma once
// Which CPUs a process runs on (sched_setaffinity). A lockstep run is one thread of control passed
// between its processes (the simulator waits for the component, which waits for the simulator):
// on one CPU each hand-over is a context switch, across CPUs a cross-CPU wake-up, which on a
// virtual machine whose idle CPUs halt costs tens of microseconds at every control period
// (docs/performance.md). The launcher pins a headless run to one CPU; `aula grade` gives each of
// its runs at once a CPU of its own.

#include <string>
#include <vector>

namespace aula::process {

// The CPUs this process may run on (its affinity mask), in increasing order.
std::vector<int> allowedCpus();
// The CPU this process runs on now, when it is one of `allowed` (not empty); else the first of them.
int currentCpu(const std::vector<int>& allowed);
// Pins the calling process, and every process it starts from now on, to `cpu`. Throws
// std::runtime_error naming the CPU and why.
void pinToCpu(int cpu);
// The same without throwing (in a child between fork and exec): false with errno set.
bool runOnlyOn(int cpu);
// "0,1,3": for messages.
std::string cpuList(const std::vector<int>& cpus);

}  // namespace aula::process
