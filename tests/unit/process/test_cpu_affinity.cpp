// aula_process's CPU placement: the CPUs a process may use, a child started on one of them, and
// batch scheduling inherited by the processes a batch task starts.
#include <aula/process/child_process.hpp>
#include <aula/process/cpu_affinity.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <cerrno>
#include <cstdint>
#include <string>

#include <sched.h>
#include <sys/utsname.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using aula::process::allowedCpus;

TEST(CpuAffinity, ThisProcessRunsOnOneOfTheCpusItMayUse) {
  const std::vector<int> cpus = allowedCpus();
  ASSERT_FALSE(cpus.empty());
  EXPECT_TRUE(std::is_sorted(cpus.begin(), cpus.end()));
  const int now = aula::process::currentCpu(cpus);
  EXPECT_NE(std::find(cpus.begin(), cpus.end(), now), cpus.end());
  EXPECT_EQ(aula::process::currentCpu({12345}), 12345) << "not running there: the first of the list";
  EXPECT_EQ(aula::process::cpuList({0, 2, 3}), "0,2,3");
}

TEST(CpuAffinity, AChildStartedOnACpuRunsThereOnly) {
  const int cpu = allowedCpus().back();
  char path[] = "/tmp/aula_cpu_affinity_XXXXXX";
  const int fd = mkstemp(path);
  ASSERT_GE(fd, 0);
  close(fd);
  aula::process::ChildProcess child({"/bin/sh", "-c", "grep Cpus_allowed_list /proc/self/status"}, path, path, {},
                                    aula::process::Placement{cpu, false});
  ASSERT_EQ(child.wait(std::chrono::seconds(10)).value_or(-1), 0);
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  std::remove(path);
  EXPECT_EQ(text.str(), "Cpus_allowed_list:\t" + std::to_string(cpu) + "\n");
}

// True when this task's time slice is kLockstepSliceNs, or the kernel keeps no slice per task
// (before Linux 6.12).
bool sliceIsTheLockstepOne() {
  utsname system{};
  int major = 0, minor = 0;
  if (uname(&system) != 0 || std::sscanf(system.release, "%d.%d", &major, &minor) != 2) return false;
  if (major < 6 || (major == 6 && minor < 12)) return true;
  return aula::process::timeSliceNs() == aula::process::kLockstepSliceNs;
}

TEST(CpuAffinity, ABatchTaskStartsBatchTasks) {
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (!aula::process::runAsBatch()) _exit(2);
    const pid_t grandchild = fork();
    if (grandchild == 0) _exit(sched_getscheduler(0) == SCHED_BATCH && sliceIsTheLockstepOne() ? 0 : 1);
    int status = 0;
    waitpid(grandchild, &status, 0);
    _exit(WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : 1);
  }
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the child's child is not a batch task with the lockstep's time slice";
}

TEST(CpuAffinity, ACpuThatDoesNotExistIsRefused) {
  errno = 0;
  EXPECT_FALSE(aula::process::runOnlyOn(-1));
  EXPECT_EQ(errno, EINVAL);
  EXPECT_FALSE(aula::process::runOnlyOn(CPU_SETSIZE));
}

}  // namespace
