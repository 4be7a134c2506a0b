#include <aula/config/config.hpp>
#include <aula/sim/lockstep_server.hpp>
#include <aula/settings/tables.hpp>
#include <aula/sim/simulator.hpp>

#include <gtest/gtest.h>

using aula::sim::LockstepServer;
using namespace std::chrono_literals;

TEST(LockstepServer, WaitsOnlyForDueClientsUntilTheyAck) {
  LockstepServer server(1000ms);
  const auto t0 = LockstepServer::WallClock::now();
  EXPECT_TRUE(server.join("component", 80000));
  EXPECT_FALSE(server.join("component", 80000));  // re-registration is not news
  EXPECT_TRUE(server.join("referee", 20000));
  server.tick(0, 0, t0);  // everyone is due at t = 0
  EXPECT_TRUE(server.waiting());
  server.ack("component", 0);
  EXPECT_TRUE(server.waiting());
  server.ack("referee", 5);  // wrong seq: still waiting
  EXPECT_TRUE(server.waiting());
  server.ack("referee", 0);
  EXPECT_FALSE(server.waiting());

  EXPECT_EQ(server.nextDueAfter(0), 20000);
  server.tick(1, 20000, t0);  // only the referee is due
  server.ack("referee", 1);
  EXPECT_FALSE(server.waiting());
  EXPECT_EQ(server.nextDueAfter(20000), 40000);
  server.tick(4, 80000, t0);  // both due
  server.ack("referee", 4);
  EXPECT_TRUE(server.waiting());
  server.ack("component", 4);
  EXPECT_FALSE(server.waiting());
}

TEST(LockstepServer, ListsASilentClientOncePerTimeoutWithItsProcess) {
  LockstepServer server(100ms);
  const auto t0 = LockstepServer::WallClock::now();
  server.join("slow", 10000, 4242);
  server.join("fast", 10000);
  server.tick(0, 0, t0);
  server.ack("fast", 0);
  EXPECT_TRUE(server.silent(t0 + 50ms).empty());
  const auto silent = server.silent(t0 + 150ms);
  ASSERT_EQ(silent.size(), 1u);
  EXPECT_EQ(silent[0].client, "slow");
  EXPECT_EQ(silent[0].pid, 4242);
  EXPECT_EQ(silent[0].silent_for, 150ms);
  EXPECT_TRUE(server.silent(t0 + 200ms).empty()) << "listed again only after another timeout";
  ASSERT_EQ(server.silent(t0 + 260ms).size(), 1u);
  EXPECT_TRUE(server.waiting()) << "nothing is dropped here: the simulator decides";
  server.ack("slow", 0);
  EXPECT_TRUE(server.silent(t0 + 500ms).empty());
}

TEST(LockstepServer, LeaveAndReset) {
  LockstepServer server(100ms);
  const auto t0 = LockstepServer::WallClock::now();
  server.join("a", 10000);
  server.tick(3, 30000, t0);
  EXPECT_TRUE(server.waiting());
  EXPECT_TRUE(server.leave("a"));
  EXPECT_FALSE(server.leave("a"));
  EXPECT_FALSE(server.waiting());
  server.join("b", 10000);
  server.tick(4, 40000, t0);
  server.resetSchedule();
  EXPECT_FALSE(server.waiting());
  server.tick(5, 0, t0);  // time went back to zero: due again at once
  EXPECT_TRUE(server.waiting());
}

TEST(SimulatorOptions, RejectsBadValuesNamingTheKey) {
  const auto& table = aula::settings::simulator();
  const auto cfg = aula::config::Config::fromString("Simulator.PhysicsStep = 0.5\n", "simulator.cfg");
  try {
    table.resolve(cfg);
    FAIL() << "expected an error";
  } catch (const aula::config::ConfigError& e) {
    EXPECT_STREQ(e.what(), "simulator.cfg:1: Simulator.PhysicsStep = '0.5': out of range [0.0001, 0.05] s");
  }
  const auto ok = aula::config::Config::fromString(
      "Simulator.PhysicsStep = 0.002\nSimulator.Lockstep = yes\nSimulator.Seed = 42\n", "s.cfg");
  const auto o = aula::sim::SimulatorOptions::fromConfig(table.resolve(ok));
  EXPECT_DOUBLE_EQ(o.step_s, 0.002);
  EXPECT_TRUE(o.lockstep);
  EXPECT_EQ(o.seed, 42);
  EXPECT_DOUBLE_EQ(o.duration_s, 0.0);  // the declared default
}
