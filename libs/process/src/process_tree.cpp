#include "aula/process/process_tree.hpp"

#include <filesystem>
#include <fstream>
#include <string>

namespace aula::process {

namespace {

// The children of every thread of `pid` (a child belongs to the thread that forked it).
std::vector<pid_t> childrenOf(pid_t pid) {
  std::vector<pid_t> children;
  std::error_code error;
  const std::filesystem::path tasks = "/proc/" + std::to_string(pid) + "/task";
  for (const auto& task : std::filesystem::directory_iterator(tasks, error)) {
    std::ifstream in(task.path() / "children");
    pid_t child = 0;
    while (in >> child) children.push_back(child);
  }
  return children;
}

}  // namespace

std::vector<pid_t> descendantsOf(pid_t pid) {
  std::vector<pid_t> found = childrenOf(pid);
  for (size_t i = 0; i < found.size(); ++i) {
    const std::vector<pid_t> more = childrenOf(found[i]);
    found.insert(found.end(), more.begin(), more.end());
  }
  return found;
}

double waitedForCpuS(const std::vector<pid_t>& pids) {
  double waited_ns = 0;
  for (const pid_t pid : pids) {
    std::error_code error;
    for (const auto& task : std::filesystem::directory_iterator("/proc/" + std::to_string(pid) + "/task", error)) {
      std::ifstream in(task.path() / "schedstat");
      double on_cpu_ns = 0, run_delay_ns = 0;
      if (in >> on_cpu_ns >> run_delay_ns) waited_ns += run_delay_ns;
    }
  }
  return waited_ns * 1e-9;
}

}  // namespace aula::process
