// aula-sim as a real process on a private LCM port, driven by this test as its client.
#include "test_support.hpp"

#include <aula/bumper_t.hpp>
#include <aula/laser_t.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/lcm/lockstep_client.hpp>
#include <aula/lockstep_ack_t.hpp>
#include <aula/lockstep_register_t.hpp>
#include <aula/motors_t.hpp>
#include <aula/pose3d_t.hpp>
#include <aula/process/child_process.hpp>
#include <aula/sim_clock_t.hpp>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include <unistd.h>

using namespace std::chrono_literals;
using aula::testing::readFile;
using aula::process::ChildProcess;

namespace {

const std::string kVacuumWorld = std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world";


struct RoombaClient {
  explicit RoombaClient(aula::lcmbus::Bus& bus) : bus(bus) {
    bus.subscribe("ROOMBA_LASER", &RoombaClient::onLaser, this);
    bus.subscribe("ROOMBA_BUMPER", &RoombaClient::onBumper, this);
    bus.subscribe("ROOMBA_POSE", &RoombaClient::onPose, this);
  }
  void onLaser(const lcm::ReceiveBuffer*, const std::string&, const aula::laser_t* m) {
    if (m->num_ranges == 0) return;
    const float centre = m->ranges[m->num_ranges / 2];
    if (scans == 0) first_centre_m = centre;
    last_centre_m = centre;
    ++scans;
  }
  void onBumper(const lcm::ReceiveBuffer*, const std::string&, const aula::bumper_t* m) {
    if (m->state == aula::bumper_t::PRESSED) pressed = true;
  }
  void onPose(const lcm::ReceiveBuffer*, const std::string&, const aula::pose3d_t* m) { pose = *m; }

  aula::lcmbus::Bus& bus;
  int scans = 0;
  float first_centre_m = 0, last_centre_m = 0;
  bool pressed = false;
  aula::pose3d_t pose{};
};

}  // namespace

TEST(SimProcess, ClientDrivesTheRoombaIntoAWall) {
  const std::string url = aula::testing::privateLcmUrl();
  const std::string log = ::testing::TempDir() + "aula_sim_drive.log";
  ChildProcess sim({AULA_SIM_PATH, kVacuumWorld, "--lockstep", "--rtf=0", "--lcm-url=" + url,
                    "--Simulator.Lockstep.WaitForClients=1"},
                   "", log);
  auto bus = aula::lcmbus::openBus(url);
  RoombaClient client(*bus);
  int64_t last_tick_us = 0;
  aula::lcmbus::LockstepClient lockstep(*bus, "test-client", 80000, [&](int64_t utime) {
    last_tick_us = utime;
    aula::motors_t cmd{};
    cmd.utime = utime;
    cmd.v = client.pressed ? 0.0 : 0.5;  // straight ahead until the bumper says stop
    bus->publish("ROOMBA_MOTORS", &cmd);
  });
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (std::chrono::steady_clock::now() < deadline && last_tick_us < 25'000'000 &&
         !(client.pressed && client.scans > 10)) {
    bus->handleTimeout(50);
    lockstep.poll();
    ASSERT_FALSE(sim.poll().has_value()) << readFile(log);
  }
  EXPECT_TRUE(client.pressed) << "no bump after " << last_tick_us / 1e6 << " s sim\n" << readFile(log);
  EXPECT_GT(client.scans, 10);
  EXPECT_LT(client.last_centre_m, client.first_centre_m - 0.5) << "the laser did not see the wall coming";
  EXPECT_LT(client.last_centre_m, 0.4f);
  lockstep.leave();
  EXPECT_EQ(sim.stop(), 0) << readFile(log);
}

TEST(SimProcess, LockstepAdvancesOnlyWhenTheClientAcks) {
  const std::string url = aula::testing::privateLcmUrl();
  const std::string log = ::testing::TempDir() + "aula_sim_lockstep.log";
  ChildProcess sim({AULA_SIM_PATH, kVacuumWorld, "--lockstep", "--rtf=0", "--lcm-url=" + url,
                    "--Simulator.Lockstep.DropAfterMs=60000"},
                   "", log);
  auto bus = aula::lcmbus::openBus(url);
  aula::sim_clock_t last{};
  bool listed = false;
  struct Handler {
    aula::sim_clock_t* last;
    bool* listed;
    void on(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t* m) {
      *last = *m;
      for (const auto& c : m->clients) *listed = *listed || c == "manual";
    }
  } handler{&last, &listed};
  bus->subscribe(aula::lcmbus::kClockChannel, &Handler::on, &handler);

  aula::lockstep_register_t reg;
  reg.client = "manual";
  reg.period_us = 100000;
  reg.leave = false;
  reg.pid = ::getpid();  // this process: alive as long as the test (an unset pid named a process that may not exist)
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (!listed && std::chrono::steady_clock::now() < deadline) {
    bus->publish(aula::lcmbus::kLockstepRegisterChannel, &reg);
    bus->handleTimeout(100);
  }
  ASSERT_TRUE(listed) << readFile(log);

  // Without acks the world must hold still at the tick we owe.
  const auto hold_until = std::chrono::steady_clock::now() + 500ms;
  while (std::chrono::steady_clock::now() < hold_until) bus->handleTimeout(20);
  const int64_t held_us = last.utime;
  const auto recheck = std::chrono::steady_clock::now() + 300ms;
  while (std::chrono::steady_clock::now() < recheck) bus->handleTimeout(20);
  EXPECT_EQ(last.utime, held_us) << "the world advanced without our ack";

  // Each ack releases the world up to our next due time (multiples of our 100 ms period):
  // the first one to the next multiple, then exactly one period per ack.
  for (int i = 0; i < 6; ++i) {
    const int64_t before = last.utime;
    const int64_t expected = (before / 100000 + 1) * 100000;
    aula::lockstep_ack_t ack;
    ack.client = "manual";
    ack.seq = last.seq;
    ack.utime = last.utime;
    bus->publish(aula::lcmbus::kLockstepAckChannel, &ack);
    const auto wait_until = std::chrono::steady_clock::now() + 2s;
    while (last.utime < expected && std::chrono::steady_clock::now() < wait_until) {
      bus->handleTimeout(20);
    }
    // Let any further (wrong) progress show up.
    const auto settle = std::chrono::steady_clock::now() + 100ms;
    while (std::chrono::steady_clock::now() < settle) bus->handleTimeout(10);
    EXPECT_EQ(last.utime, expected) << "ack " << i;
    if (i > 0) {
      EXPECT_EQ(last.utime - before, 100000) << "ack " << i;
    }
  }
  EXPECT_EQ(sim.stop(), 0) << readFile(log);
}

TEST(SimProcess, BadWorldIsAUsageErrorNamingTheFile) {
  const std::string log = ::testing::TempDir() + "aula_sim_bad.log";
  ChildProcess sim({AULA_SIM_PATH, "/nonexistent/nowhere.world", "--lcm-url=memq://"}, "", log);
  const auto code = sim.wait(20s);
  ASSERT_TRUE(code.has_value());
  EXPECT_EQ(*code, 2);
  EXPECT_NE(readFile(log).find("/nonexistent/nowhere.world"), std::string::npos) << readFile(log);
}

TEST(SimProcess, BadConfigIsAUsageErrorNamingFileAndKey) {
  const std::string cfg = ::testing::TempDir() + "aula_bad_sim.cfg";
  std::ofstream(cfg) << "# test\nSimulator.PhysicsStep = fast\n";
  const std::string log = ::testing::TempDir() + "aula_sim_badcfg.log";
  ChildProcess sim({AULA_SIM_PATH, kVacuumWorld, "--config", cfg, "--lcm-url=memq://"}, "", log);
  const auto code = sim.wait(20s);
  ASSERT_TRUE(code.has_value());
  EXPECT_EQ(*code, 2);
  EXPECT_NE(readFile(log).find(cfg + ":2: Simulator.PhysicsStep"), std::string::npos) << readFile(log);
}
