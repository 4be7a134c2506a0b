#pragma once
// A run's wall-clock backstop (--timeout, supervision::defaultWallBudget): the machine's reason
// when it runs out. It counts the wall time the run's processes had, not the time they waited
// for a CPU that other work held (the kernel's schedstat run delay of every process below the
// launcher, read every 500 ms once the budget is near): on a loaded machine a run is waited for,
// and a student's endless loop meets its CPU budget (the student's reason) first. At most nine
// tenths of the wall time is so forgiven: a machine that never gives the run a CPU still ends it,
// at ten times the budget.

#include <chrono>
#include <string>

namespace aula::supervision {

class WallBackstop {
 public:
  using Clock = std::chrono::steady_clock;
  // `budget_s` <= 0: no backstop.
  WallBackstop(double budget_s, Clock::time_point started) : budget_s_(budget_s), started_(started) {}

  // Has the run had more than its budget at `now`?
  bool ranOut(Clock::time_point now);
  // The machine's reason it ran out, for the report (process/machine_reason.hpp).
  std::string reason() const;

 private:
  double budget_s_;
  Clock::time_point started_;
  Clock::time_point waited_checked_;
  double waited_s_ = 0;  // the run's processes' wait for a CPU, the most seen
};

}  // namespace aula::supervision
