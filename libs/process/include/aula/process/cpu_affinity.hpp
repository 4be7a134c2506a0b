#pragma once
// Which CPUs a process runs on (sched_setaffinity), and how it is scheduled there. A lockstep run is one thread of control passed
// between its processes (the simulator waits for the component, which waits for the simulator):
// on one CPU each hand-over is a context switch, across CPUs a cross-CPU wake-up, which on a
// virtual machine whose idle CPUs halt costs tens of microseconds at every control period
// (docs/performance.md). The launcher starts a headless run's processes on one CPU, as batch
// tasks (aula::process::Placement); `aula grade` gives each of its runs at once a CPU of its own.

#include <string>
#include <vector>

namespace aula::process {

// The CPUs this process may run on (its affinity mask), in increasing order.
std::vector<int> allowedCpus();
// The CPU this process runs on now, when it is one of `allowed` (not empty); else the first of them.
int currentCpu(const std::vector<int>& allowed);
// The calling process, and every process it starts from now on, runs on `cpu` only. False, with
// errno, when it may not (a CPU that does not exist or is not in its mask); safe between fork
// and exec.
bool runOnlyOn(int cpu);
// The calling process, and every process it starts from now on, as a batch task (SCHED_BATCH,
// which any user may choose): a process woken by one of them no longer preempts it. On one CPU a
// lockstep run then hands the CPU over when a process blocks, once per control period, instead
// of at every datagram of the simulator's burst (each woke the component, which preempted the
// simulator to read it: 52 k context switches per vacuum run instead of 12 k). False, with
// errno, when the kernel refuses; safe between fork and exec.
bool runAsBatch();
// "0,1,3": for messages.
std::string cpuList(const std::vector<int>& cpus);

}  // namespace aula::process
