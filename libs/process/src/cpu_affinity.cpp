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

namespace {

// linux/sched/types.h's struct sched_attr (glibc wraps sched_setattr only from 2.41).
struct SchedAttr {
  uint32_t size = sizeof(SchedAttr);
  uint32_t sched_policy = 0;
  uint64_t sched_flags = 0;
  int32_t sched_nice = 0;
  uint32_t sched_priority = 0;
  uint64_t sched_runtime = 0, sched_deadline = 0, sched_period = 0;
};

}  // namespace

bool runAsBatch() {
  SchedAttr attributes;
  attributes.sched_policy = SCHED_BATCH;
  attributes.sched_runtime = kLockstepSliceNs;
  if (syscall(SYS_sched_setattr, 0, &attributes, 0) == 0) return true;
  const sched_param none{};
  return sched_setscheduler(0, SCHED_BATCH, &none) == 0;
}

uint64_t timeSliceNs() {
  SchedAttr attributes;
  if (syscall(SYS_sched_getattr, 0, &attributes, sizeof attributes, 0) != 0) return 0;
  return attributes.sched_runtime;
}

std::string cpuList(const std::vector<int>& cpus) {
  std::string text;
  for (const int cpu : cpus) text += (text.empty() ? "" : ",") + std::to_string(cpu);
  return text;
}

}  // namespace aula::process
