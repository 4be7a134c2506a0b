// LockstepClient follows only its own simulator: the instance of the first tick that listed it.
// A tick of another instance (a second aula-sim on the same URL, or a forgery) moves nothing,
// is not acked, and is counted.
#include <aula/lcm/bus.hpp>
#include <aula/lcm/lockstep_client.hpp>

#include <aula/lockstep_ack_t.hpp>
#include <aula/lockstep_register_t.hpp>
#include <aula/sim_clock_t.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

namespace {

using aula::lcmbus::Bus;
using aula::lcmbus::LockstepClient;

struct Acks {
  std::vector<int64_t> seqs;
  void on(const lcm::ReceiveBuffer*, const std::string&, const aula::lockstep_ack_t* ack) { seqs.push_back(ack->seq); }
};

aula::sim_clock_t tick(int64_t instance, int64_t seq, int64_t utime, std::vector<std::string> clients) {
  aula::sim_clock_t t{};
  t.instance = instance;
  t.seq = seq;
  t.utime = utime;
  t.lockstep = true;
  t.world = "test";
  t.clients = std::move(clients);
  t.num_clients = static_cast<int32_t>(t.clients.size());
  return t;
}

struct Registrations {
  std::vector<std::string> clients;
  void on(const lcm::ReceiveBuffer*, const std::string&, const aula::lockstep_register_t* msg) {
    if (!msg->leave) clients.push_back(msg->client);
  }
};

void drain(Bus& bus) {
  while (bus.handleTimeout(0) > 0) {
  }
}

constexpr int64_t kOurs = 0x1234567890abcLL, kOther = 0x7edcba987654321LL;

TEST(LockstepClient, FollowsOnlyTheInstanceThatListedIt) {
  Bus bus("memq://");
  Acks acks;
  bus.subscribe(aula::lcmbus::kLockstepAckChannel, &Acks::on, &acks);
  std::vector<int64_t> ran;
  LockstepClient client(bus, "ctl", 20000, [&](int64_t utime) { ran.push_back(utime); });

  // Before it is listed the client locks onto nobody.
  auto before = tick(kOther, -1, 0, {});
  bus.publish(aula::lcmbus::kClockChannel, &before);
  drain(bus);
  EXPECT_FALSE(client.instanceLocked());

  auto first = tick(kOurs, 0, 0, {"ctl"});
  bus.publish(aula::lcmbus::kClockChannel, &first);
  drain(bus);
  ASSERT_TRUE(client.instanceLocked());
  EXPECT_EQ(client.instance(), kOurs);
  EXPECT_TRUE(client.registered());

  // Another simulator's ticks, far ahead, listing us too: ignored, not acked, counted.
  for (int i = 0; i < 3; ++i) {
    auto foreign = tick(kOther, 1000 + i, 500000000 + i * 20000, {"ctl"});
    bus.publish(aula::lcmbus::kClockChannel, &foreign);
  }
  drain(bus);
  EXPECT_EQ(client.foreignTicks(), 3);
  EXPECT_EQ(client.simTimeUs(), 0);
  EXPECT_EQ(client.lastTick().instance, kOurs);

  // Our simulator's next tick is still followed (a foreign seq of 1000 did not make it stale).
  auto second = tick(kOurs, 1, 20000, {"ctl"});
  bus.publish(aula::lcmbus::kClockChannel, &second);
  drain(bus);
  EXPECT_EQ(client.simTimeUs(), 20000);
  EXPECT_EQ(ran, (std::vector<int64_t>{0, 20000}));
  EXPECT_EQ(acks.seqs, (std::vector<int64_t>{0, 1}));
  EXPECT_EQ(client.foreignTicks(), 3);
}

TEST(LockstepClient, AForeignTickOfAnotherWorldDoesNotStopTheClient) {
  Bus bus("memq://");
  LockstepClient client(bus, "referee", 20000, nullptr);
  client.expectWorld("aaaa", "worlds/ours.world");
  auto ours = tick(kOurs, 0, 0, {"referee"});
  ours.world_sha256 = "aaaa";
  bus.publish(aula::lcmbus::kClockChannel, &ours);
  drain(bus);
  auto foreign = tick(kOther, 5, 100000, {"referee"});
  foreign.world_sha256 = "bbbb";
  bus.publish(aula::lcmbus::kClockChannel, &foreign);
  drain(bus);
  EXPECT_NO_THROW(client.poll());  // not "another world": not our simulator at all
  EXPECT_EQ(client.foreignTicks(), 1);
}

// A simulator started after its clients (it loads DART and the world for tens of ms) says hello:
// a client not yet listed registers again at once, not at its next re-send 100 ms later; a
// listed client does not.
TEST(LockstepClient, RegistersAgainWhenASimulatorSaysHello) {
  Bus bus("memq://");
  Registrations registrations;
  bus.subscribe(aula::lcmbus::kLockstepRegisterChannel, &Registrations::on, &registrations);
  LockstepClient client(bus, "ctl", 20000, nullptr);
  drain(bus);
  ASSERT_EQ(registrations.clients.size(), 1u);  // at its start, before any simulator listened

  auto hello = tick(kOurs, -1, 0, {});
  bus.publish(aula::lcmbus::kHelloChannel, &hello);
  drain(bus);
  EXPECT_EQ(registrations.clients.size(), 2u);

  auto listed = tick(kOurs, 0, 0, {"ctl"});
  bus.publish(aula::lcmbus::kClockChannel, &listed);
  drain(bus);
  ASSERT_TRUE(client.registered());
  auto another = tick(kOther, -1, 0, {});
  bus.publish(aula::lcmbus::kHelloChannel, &another);
  drain(bus);
  EXPECT_EQ(registrations.clients.size(), 2u);
}

// The simulator is gone for a client once it has followed it: when its clock has been silent for
// 2 s of wall time that the client watched (killed), or at once when its last tick says it ended
// the run. A client that was itself stopped (a debugger, SIGSTOP) does not take its own absence
// for the simulator's silence: what was sent meanwhile is still queued, unread.
TEST(LockstepClient, KnowsWhenItsSimulatorIsGone) {
  using namespace std::chrono_literals;
  Bus bus("memq://");
  LockstepClient client(bus, "ctl", 20000, nullptr);
  EXPECT_EQ(client.simulatorGone(std::chrono::steady_clock::now() + 3s), "") << "no simulator yet: it waits for one";

  auto listed = tick(kOurs, 0, 0, {"ctl"});
  bus.publish(aula::lcmbus::kClockChannel, &listed);
  drain(bus);
  // Looks every 0.1 s (the component's housekeeping: every 50 ms) for `how_long`: what the last one said.
  auto t = std::chrono::steady_clock::now() + 5s;  // well after the look above
  auto watch = [&](std::chrono::steady_clock::duration how_long) {
    std::string said;
    for (const auto end = t + how_long; t < end;) said = client.simulatorGone(t += 100ms);
    return said;
  };
  EXPECT_EQ(client.simulatorGone(t), "") << "the look after a gap of its own starts the watch";
  EXPECT_EQ(watch(1900ms), "");
  EXPECT_EQ(watch(200ms), "the simulator stopped (no SIM_CLOCK for 2 s of wall time)");

  // Stopped for 3.5 s right after a look: its own absence, not the simulator's silence.
  bus.publish(aula::lcmbus::kClockChannel, &listed);
  drain(bus);
  t = std::chrono::steady_clock::now() + 10s;
  EXPECT_EQ(client.simulatorGone(t), "");
  t += 3500ms;
  EXPECT_EQ(client.simulatorGone(t), "") << "its own absence was taken for the simulator's silence";
  EXPECT_EQ(watch(1900ms), "");
  EXPECT_EQ(watch(200ms), "the simulator stopped (no SIM_CLOCK for 2 s of wall time)") << "watched, the silence counts";

  auto foreign = tick(kOther, 5, 100000, {"ctl"});
  foreign.ended = "not ours";
  bus.publish(aula::lcmbus::kClockChannel, &foreign);
  drain(bus);
  EXPECT_EQ(client.simulatorGone(), "") << "another simulator's word is not ours";

  auto last = tick(kOurs, 1, 20000, {});
  last.ended = "lockstep client 'referee' (pid 42) is gone without leaving the run";
  bus.publish(aula::lcmbus::kClockChannel, &last);
  drain(bus);
  EXPECT_EQ(client.simulatorGone(), "the simulator ended the run: lockstep client 'referee' (pid 42) is gone without leaving the run");
}

}  // namespace
