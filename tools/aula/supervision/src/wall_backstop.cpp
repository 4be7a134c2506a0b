#include "aula/supervision/wall_backstop.hpp"

#include <aula/process/machine_reason.hpp>
#include <aula/process/process_tree.hpp>

#include <algorithm>
#include <sstream>

#include <unistd.h>

namespace aula::supervision {

bool WallBackstop::ranOut(Clock::time_point now) {
  const double wall_s = std::chrono::duration<double>(now - started_).count();
  if (budget_s_ <= 0 || wall_s <= budget_s_) return false;
  if (now - waited_checked_ >= std::chrono::milliseconds(500)) {
    waited_checked_ = now;
    // A process that ended takes its count with it: keep the most seen.
    waited_s_ = std::max(waited_s_, process::waitedForCpuS(process::descendantsOf(::getpid())));
  }
  return wall_s - std::min(waited_s_, 0.9 * wall_s) > budget_s_;
}

std::string WallBackstop::reason() const {
  std::ostringstream what;
  what << "the run's wall-clock backstop of " << budget_s_
       << " s ran out (--timeout): the machine was too slow or too busy for this run";
  return process::machineReason(what.str());
}

}  // namespace aula::supervision
