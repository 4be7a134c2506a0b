// What the student's call budgets cost per control period: one arm() and one disarm() of the
// ExecuteWatchdog around each call (the CPU clock of the calling thread read twice, a mutex), beside
// what the wall-clock watchdog before it did (a steady_clock read and two atomic stores, kept here
// as the baseline). A 900 s vacuum run makes 11,250 such calls.
#include <aula/component/execute_watchdog.hpp>

#include <benchmark/benchmark.h>

#include <atomic>
#include <chrono>
#include <cstdint>

namespace {

void BM_CpuTimeBudgets(benchmark::State& state) {
  aula::component::ExecuteWatchdog watchdog("bench", aula::component::RunBudget{600, 60});
  const aula::component::CallBudget budget{2, 10, "Component.ExecuteBudget"};
  for (auto _ : state) {
    watchdog.arm("execute()", budget);
    watchdog.disarm();
  }
}
BENCHMARK(BM_CpuTimeBudgets);

// The wall-clock watchdog's arm()/disarm(), as it was.
void BM_WallClockDeadline(benchmark::State& state) {
  std::atomic<const char*> what{""};
  std::atomic<int64_t> deadline_ns{0};
  for (auto _ : state) {
    what.store("execute()", std::memory_order_relaxed);
    const auto now = std::chrono::steady_clock::now().time_since_epoch();
    deadline_ns.store(std::chrono::duration_cast<std::chrono::nanoseconds>(now).count() + 2000000000,
                      std::memory_order_release);
    deadline_ns.store(0, std::memory_order_release);
  }
  benchmark::DoNotOptimize(deadline_ns.load());
}
BENCHMARK(BM_WallClockDeadline);

}  // namespace

BENCHMARK_MAIN();
