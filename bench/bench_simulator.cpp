// Whole-simulator costs: ticks of aula-sim's core (physics + drivers + clock) on the real
// worlds, on the in-process memq:// bus, and the lockstep round trip over real UDP LCM.
#include <aula/lcm/bus.hpp>
#include <aula/lockstep_ack_t.hpp>
#include <aula/physics/physics_world.hpp>
#include <aula/sim/simulator.hpp>
#include <aula/sim_clock_t.hpp>
#include <aula/world/world_spec.hpp>

#include <benchmark/benchmark.h>
#include <lcm/lcm-cpp.hpp>

#include <atomic>
#include <thread>

#include <unistd.h>

namespace {

void simulateWorld(benchmark::State& state, const std::string& world_file, bool drive) {
  aula::lcmbus::Bus bus("memq://");
  auto spec = aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/" + world_file);
  aula::sim::SimulatorOptions options;
  options.real_time_factor = 0;
  aula::sim::Simulator sim(std::move(spec), options, bus);
  // Drive the first robot in a slow circle: a moving robot costs more contacts than an idle one.
  if (drive) sim.physics().commandVelocity(0, 0.3, 0.5, 0.0);
  const int64_t start_us = sim.timeUs();
  for (auto _ : state) {
    sim.advanceToNextTick();
    while (bus.handleTimeout(0) > 0) {
    }
  }
  const double sim_s = (sim.timeUs() - start_us) / 1e6;
  state.counters["sim_s_per_tick"] = sim_s / state.iterations();
  state.counters["real_time_factor"] =
      benchmark::Counter(sim_s, benchmark::Counter::kIsRate);  // sim seconds per wall second
}

void BM_CityIdleTaxi(benchmark::State& state) { simulateWorld(state, "cityLarge.world", false); }
void BM_VacuumHouse(benchmark::State& state) { simulateWorld(state, "vacuum.world", false); }
void BM_AutoparkStreet(benchmark::State& state) { simulateWorld(state, "autopark.world", false); }
BENCHMARK(BM_CityIdleTaxi)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(BM_VacuumHouse)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(BM_AutoparkStreet)->Unit(benchmark::kMicrosecond)->UseRealTime();

// One DART physics step alone (no drivers, no bus), the first robot driving a slow circle.
void physicsStep(benchmark::State& state, const std::string& world_file) {
  const auto spec = aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/" + world_file);
  aula::physics::PhysicsWorld physics(spec, 0.005);
  physics.commandVelocity(0, 0.3, 0.5, 0.0);
  for (auto _ : state) physics.step();
  state.counters["near_statics"] = physics.nearStaticCount();
}
void BM_PhysicsStepCity(benchmark::State& state) { physicsStep(state, "cityLarge.world"); }
void BM_PhysicsStepHouse(benchmark::State& state) { physicsStep(state, "vacuum.world"); }
void BM_PhysicsStepStreet(benchmark::State& state) { physicsStep(state, "autopark.world"); }
BENCHMARK(BM_PhysicsStepCity)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PhysicsStepHouse)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PhysicsStepStreet)->Unit(benchmark::kMicrosecond);

// One lockstep handshake over UDP multicast: the simulator side publishes a tick, a client
// thread (its own LCM instance, as a separate process would have) acks it.
void BM_LockstepRoundTrip(benchmark::State& state) {
  const std::string url =
      "udpm://239.255.76.67:" + std::to_string(30000 + getpid() % 20000) + "?ttl=0";
  aula::lcmbus::Bus server(url);
  std::atomic<bool> stop{false};
  std::thread client([&] {
    aula::lcmbus::Bus bus(url);
    struct Acker {
      aula::lcmbus::Bus* bus;
      void on(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t* tick) {
        aula::lockstep_ack_t ack;
        ack.client = "bench";
        ack.seq = tick->seq;
        ack.utime = tick->utime;
        bus->publish(aula::lcmbus::kLockstepAckChannel, &ack);
      }
    } acker{&bus};
    bus.subscribe(aula::lcmbus::kClockChannel, &Acker::on, &acker);
    while (!stop) bus.handleTimeout(10);
  });
  struct AckWait {
    int64_t seq = -1;
    void on(const lcm::ReceiveBuffer*, const std::string&, const aula::lockstep_ack_t* ack) { seq = ack->seq; }
  } wait;
  server.subscribe(aula::lcmbus::kLockstepAckChannel, &AckWait::on, &wait);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  aula::sim_clock_t tick{};
  tick.world = "bench";
  int64_t lost = 0;
  for (auto _ : state) {
    ++tick.seq;
    tick.utime += 20000;
    server.publish(aula::lcmbus::kClockChannel, &tick);
    while (wait.seq != tick.seq) {
      if (server.handleTimeout(20) == 0) {  // lost packet: re-send, as the simulator does
        ++lost;
        server.publish(aula::lcmbus::kClockChannel, &tick);
      }
    }
  }
  stop = true;
  client.join();
  state.counters["resends"] = static_cast<double>(lost);
}
BENCHMARK(BM_LockstepRoundTrip)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
