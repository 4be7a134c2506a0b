#pragma once
// Which CPUs a process runs on (sched_setaffinity), and how it is scheduled there. A lockstep run is one thread of control passed
// between its processes (the simulator waits for the component, which waits for the simulator):
// on one CPU each hand-over is a context switch, across CPUs a cross-CPU wake-up, which on a
// virtual machine whose idle CPUs halt costs tens of microseconds at every control period
// (docs/performance.md). The launcher starts a headless run's processes on one CPU, as batch
// tasks (aula::process::Placement); `aula grade` gives each of its runs at once a CPU of its own.

#include <cstdint>
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
// errno, when the kernel refuses; safe between fork and exec. It also asks for the longest time
// slice (kLockstepSliceNs).
bool runAsBatch();
// The time slice a batch task of a lockstep run asks for (sched_attr.sched_runtime, Linux 6.12 and
// later; older kernels ignore it): the most a task may ask for. Under EEVDF a task that has used
// up its slice (0.75 ms by default) is switched out at the next wake-up on its CPU, batch or not:
// the simulator, past its slice in the middle of a period's burst, was switched out at most
// control periods, the component at its commands, twice the context switches of a run. A run's
// processes block at every hand-over, so a long slice costs no other process of the run its turn.
inline constexpr uint64_t kLockstepSliceNs = 100000000;
// The calling thread's time slice as the kernel reports it (sched_getattr's sched_runtime), in
// nanoseconds; 0 when it reports none.
uint64_t timeSliceNs();
// "0,1,3": for messages.
std::string cpuList(const std::vector<int>& cpus);

}  // namespace aula::process
