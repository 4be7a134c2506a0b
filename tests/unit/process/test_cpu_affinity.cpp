// aula_process's CPU placement: the CPUs a process may use, and a child started on one of them.
#include <aula/process/child_process.hpp>
#include <aula/process/cpu_affinity.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

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
  aula::process::ChildProcess child({"/bin/sh", "-c", "grep Cpus_allowed_list /proc/self/status"}, path, path, {}, cpu);
  ASSERT_EQ(child.wait(std::chrono::seconds(10)).value_or(-1), 0);
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  std::remove(path);
  EXPECT_EQ(text.str(), "Cpus_allowed_list:\t" + std::to_string(cpu) + "\n");
}

TEST(CpuAffinity, ACpuThatDoesNotExistIsRefusedWithItsNumber) {
  try {
    aula::process::pinToCpu(-1);
    FAIL() << "pinned to CPU -1";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("CPU -1"), std::string::npos) << e.what();
  }
}

}  // namespace
