// What lets the processes of a run started by hand (three terminals) notice a peer gone: the
// simulator ticks at least every 100 ms of wall time whatever its pace (a client that hears
// nothing for 2 s knows it is gone), and alone (no launcher) it ends the run when a client's
// process is gone without leaving; its last ticks say why.
#include <aula/auth/run_key.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/lockstep_ack_t.hpp>
#include <aula/lockstep_register_t.hpp>
#include <aula/sim/simulator.hpp>
#include <aula/sim_clock_t.hpp>
#include <aula/world/world_spec.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace {

using namespace std::chrono_literals;

struct Ticks {
  std::vector<aula::sim_clock_t> seen;
  void on(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t* tick) { seen.push_back(*tick); }
};

aula::world::WorldSpec vacuumWorld() { return aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world"); }

void runFor(aula::sim::Simulator& sim, std::chrono::milliseconds wall) {
  const auto until = std::chrono::steady_clock::now() + wall;
  sim.run([&] { return std::chrono::steady_clock::now() >= until; });
}

void registerClient(aula::lcmbus::Bus& bus, const std::string& name, int pid) {
  aula::lockstep_register_t msg{};
  msg.client = name;
  msg.period_us = 100000;
  msg.pid = pid;
  bus.publish(aula::lcmbus::kLockstepRegisterChannel, &msg);
}

// A process that has exited and been reaped: its pid is gone.
pid_t deadPid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

}  // namespace

TEST(SimulatorPeers, ASlowPaceStillTicksEveryHundredMillisecondsOfWallTime) {
  aula::lcmbus::Bus bus("memq://");
  aula::sim::SimulatorOptions options;
  options.real_time_factor = 0.001;  // one 20 ms tick every 20 s of wall time
  aula::sim::Simulator sim(vacuumWorld(), options, bus);
  Ticks ticks;
  bus.subscribe(aula::lcmbus::kClockChannel, &Ticks::on, &ticks);
  runFor(sim, 1000ms);
  while (bus.handleTimeout(0) > 0) {
  }
  // About 10 (a loaded machine: fewer); without the heartbeat, 1 (tick 0).
  EXPECT_GE(ticks.seen.size(), 5u);
  EXPECT_LT(sim.timeUs(), 40000);
}

TEST(SimulatorPeers, AloneItEndsTheRunWhenAClientsProcessIsGoneAndItsLastTicksSayWhy) {
  aula::lcmbus::Bus bus("memq://");
  aula::sim::SimulatorOptions options;
  options.real_time_factor = 1.0;
  options.watch_client_processes = true;
  aula::sim::Simulator sim(vacuumWorld(), options, bus);
  Ticks ticks;
  bus.subscribe(aula::lcmbus::kClockChannel, &Ticks::on, &ticks);
  registerClient(bus, "alive", static_cast<int>(::getpid()));
  registerClient(bus, "unknown", 0);  // a client that did not say: never taken for gone
  const pid_t dead = deadPid();
  registerClient(bus, "vacuum-cleaner", static_cast<int>(dead));
  runFor(sim, 5000ms);
  const std::string why = "lockstep client 'vacuum-cleaner' (pid " + std::to_string(dead) + ") is gone without leaving the run";
  EXPECT_EQ(sim.endedBecause(), why);
  EXPECT_LT(sim.timeUs(), 2000000) << "it ended at once, not at the end of the 5 s";
  ticks.seen.clear();
  sim.announceEnd();
  while (bus.handleTimeout(0) > 0) {
  }
  ASSERT_EQ(ticks.seen.size(), 3u);
  EXPECT_EQ(ticks.seen.back().ended, why);
  EXPECT_EQ(ticks.seen.back().clients, (std::vector<std::string>{"alive", "unknown"}));
}

TEST(SimulatorPeers, UnderALauncherItLeavesAGoneClientToTheLauncher) {
  aula::lcmbus::Bus bus("memq://");
  aula::sim::SimulatorOptions options;
  options.real_time_factor = 1.0;  // watch_client_processes off: aula-sim --status-fd
  aula::sim::Simulator sim(vacuumWorld(), options, bus);
  registerClient(bus, "vacuum-cleaner", static_cast<int>(deadPid()));
  runFor(sim, 400ms);
  EXPECT_EQ(sim.endedBecause(), "");
  EXPECT_GT(sim.timeUs(), 0);
}

// A graded run's simulator (it has the run's key) takes only its own run's lockstep clients
// (issue 38): a registration or an ack not signed with that client's key of this run (another
// run's client on the same bus, or a forgery) is refused; the run's own client, signed with
// auth::clientKey(run key, name), joins and its acks count.
TEST(SimulatorPeers, AGradedSimulatorRefusesAnotherRunsClient) {
  aula::lcmbus::Bus bus("memq://");
  aula::sim::SimulatorOptions options;
  options.real_time_factor = 0;
  options.lockstep = true;
  const aula::auth::Key run_key = aula::auth::randomKey(), other_run_key = aula::auth::randomKey();
  aula::sim::Simulator sim(vacuumWorld(), options, bus, run_key);
  Ticks ticks;
  bus.subscribe(aula::lcmbus::kClockChannel, &Ticks::on, &ticks);
  auto registration = [](const std::string& name) {
    aula::lockstep_register_t msg{};
    msg.client = name;
    msg.period_us = 100000;
    return msg;
  };
  aula::lockstep_register_t unsigned_msg = registration("vacuum-cleaner");
  bus.publish(aula::lcmbus::kLockstepRegisterChannel, &unsigned_msg);
  aula::lockstep_register_t other_run = registration("vacuum-cleaner");
  aula::auth::sign(aula::auth::Signer(aula::auth::clientKey(other_run_key, "vacuum-cleaner")),
                   aula::lcmbus::kLockstepRegisterChannel, other_run);
  bus.publish(aula::lcmbus::kLockstepRegisterChannel, &other_run);
  aula::lockstep_register_t other_name = registration("vacuum-referee");  // this run's key for another client
  aula::auth::sign(aula::auth::Signer(aula::auth::clientKey(run_key, "vacuum-cleaner")), aula::lcmbus::kLockstepRegisterChannel,
                   other_name);
  bus.publish(aula::lcmbus::kLockstepRegisterChannel, &other_name);
  runFor(sim, 300ms);
  while (bus.handleTimeout(0) > 0) {
  }
  ASSERT_FALSE(ticks.seen.empty());
  EXPECT_TRUE(ticks.seen.back().clients.empty()) << "a client of another run joined";
  EXPECT_GT(sim.timeUs(), 0) << "with no client of its own, lockstep waits for nobody";

  aula::lockstep_register_t own = registration("vacuum-cleaner");
  aula::auth::Signer own_key(aula::auth::clientKey(run_key, "vacuum-cleaner"));
  aula::auth::sign(own_key, aula::lcmbus::kLockstepRegisterChannel, own);
  bus.publish(aula::lcmbus::kLockstepRegisterChannel, &own);
  runFor(sim, 200ms);
  while (bus.handleTimeout(0) > 0) {
  }
  EXPECT_EQ(ticks.seen.back().clients, (std::vector<std::string>{"vacuum-cleaner"}));
  // Now the world waits for it: another run's ack does not move it on, its own does.
  const int64_t waiting_at = sim.timeUs();
  auto ack = [&](aula::auth::Signer signer) {
    aula::lockstep_ack_t msg{};
    msg.client = "vacuum-cleaner";
    msg.seq = ticks.seen.back().seq;
    msg.utime = ticks.seen.back().utime;
    aula::auth::sign(signer, aula::lcmbus::kLockstepAckChannel, msg);
    bus.publish(aula::lcmbus::kLockstepAckChannel, &msg);
  };
  ack(aula::auth::Signer(aula::auth::clientKey(other_run_key, "vacuum-cleaner")));
  runFor(sim, 200ms);
  while (bus.handleTimeout(0) > 0) {
  }
  EXPECT_EQ(sim.timeUs(), waiting_at) << "another run's ack moved the world";
  ack(own_key);
  runFor(sim, 200ms);
  EXPECT_GT(sim.timeUs(), waiting_at) << "its own run's ack did not";
}
