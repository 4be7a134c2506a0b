#include "aula/process/cpu_affinity.hpp"

#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>

namespace aula::process {

std::vector<int> allowedCpus() {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  std::vector<int> cpus;
  if (sched_getaffinity(0, sizeof mask, &mask) != 0) return cpus;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
    if (CPU_ISSET(cpu, &mask)) cpus.push_back(cpu);
  }
  return cpus;
}

int currentCpu(const std::vector<int>& allowed) {
  const int now = sched_getcpu();
  if (std::find(allowed.begin(), allowed.end(), now) != allowed.end()) return now;
  return allowed.empty() ? 0 : allowed.front();
}

bool runOnlyOn(int cpu) {
  if (cpu < 0 || cpu >= CPU_SETSIZE) {
    errno = EINVAL;
    return false;
  }
  cpu_set_t mask;
  CPU_ZERO(&mask);
  CPU_SET(cpu, &mask);
  return sched_setaffinity(0, sizeof mask, &mask) == 0;
}

bool runAsBatch() {
  // linux/sched/types.h's struct sched_attr (glibc wraps sched_setattr only from 2.41).
  struct {
    uint32_t size;
    uint32_t sched_policy;
    uint64_t sched_flags;
    int32_t sched_nice;
    uint32_t sched_priority;
    uint64_t sched_runtime, sched_deadline, sched_period;
  } attributes{};
  attributes.size = sizeof attributes;
  attributes.sched_policy = SCHED_BATCH;
  attributes.sched_runtime = kLockstepSliceNs;
  if (syscall(SYS_sched_setattr, 0, &attributes, 0) == 0) return true;
  const sched_param none{};
  return sched_setscheduler(0, SCHED_BATCH, &none) == 0;
}

std::string cpuList(const std::vector<int>& cpus) {
  std::string text;
  for (const int cpu : cpus) text += (text.empty() ? "" : ",") + std::to_string(cpu);
  return text;
}

}  // namespace aula::process
