// aula-test-attacker --lcm-url=URL --attack=NAME [--after-s=S]
// An attacker on a run's bus, as any process of the user could be: it waits until the run's
// clock has passed `--after-s` seconds of sim time, then forges one kind of traffic and exits.
//   pose-flood   forged poses on ROOMBA_POSE sweeping the whole house
//   control      SIM_CONTROL: teleport the roomba, pause, reset the world
//   clock        SIM_CLOCK copies of the real tick with a huge seq
//   clock-instance  the same, from another simulator instance (another `instance` id)
//   none         nothing: exits 0 once the run has got that far (a test's cue)
//   lockstep     acks and a leave for the component's name (vacuum-cleaner)
//   episode      VACUUM_EPISODE: a reload (new generation) and a later start
//   garbage      10,000 random packets spread over every channel of the run
// Exit 0 when the attack was sent, 1 when the run never got that far (seen nothing in 30 s).
#include "forgery.hpp"

#include <aula/config/config.hpp>
#include <aula/episode_t.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/lockstep_ack_t.hpp>
#include <aula/lockstep_register_t.hpp>
#include <aula/sim_clock_t.hpp>
#include <aula/sim_control_t.hpp>

#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

// The latest real tick, once the run's sim time has passed `after_us`.
std::optional<aula::sim_clock_t> waitForTick(lcm::LCM& lcm, int64_t after_us) {
  std::optional<aula::sim_clock_t> last;
  struct Handler {
    std::optional<aula::sim_clock_t>* last;
    void on(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t* tick) { *last = *tick; }
  } handler{&last};
  auto* subscription = lcm.subscribe(aula::lcmbus::kClockChannel, &Handler::on, &handler);
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  while (Clock::now() < deadline && !(last && last->seq > 0 && last->utime >= after_us)) lcm.handleTimeout(20);
  lcm.unsubscribe(subscription);
  if (last && last->utime >= after_us) return last;
  return std::nullopt;
}

void poseFlood(lcm::LCM& lcm, const aula::sim_clock_t& tick) {
  // Stamped a little ahead of the run's time, so a referee that grades them would count them all.
  for (int round = 0; round < 3; ++round) {
    for (const auto& pose : aula::attacks::houseSweep(tick.utime + 100000 * (round + 1))) lcm.publish("ROOMBA_POSE", &pose);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

void control(lcm::LCM& lcm) {
  aula::sim_control_t msg{};
  msg.command = aula::sim_control_t::SET_POSE;
  msg.robot = "roomba";
  msg.x = 3.0;  // a free spot of the living room, far from the dock
  msg.y = 3.0;
  msg.yaw = 0.5;
  msg.auth_seq = 1000000;
  lcm.publish(aula::lcmbus::kControlChannel, &msg);
  msg.command = aula::sim_control_t::PAUSE;
  ++msg.auth_seq;
  lcm.publish(aula::lcmbus::kControlChannel, &msg);
  // At once: a 60 s episode can end within 200 ms of wall time, and a request after its end is
  // counted by no referee.
  msg.command = aula::sim_control_t::RESET;
  ++msg.auth_seq;
  lcm.publish(aula::lcmbus::kControlChannel, &msg);
}

void forgedClock(lcm::LCM& lcm, aula::sim_clock_t tick, bool other_instance) {
  if (other_instance) tick.instance ^= 0x5a5a5a5a5a5aLL;  // a simulator that listed our clients too
  tick.seq = 1000000000000LL;
  tick.utime += 500000000;  // and far in the future: a referee following it would end at once
  tick.auth_seq += 1000000;
  for (int i = 0; i < 20; ++i) {  // at once: all reach the referee well before the episode's end
    lcm.publish(aula::lcmbus::kClockChannel, &tick);
    ++tick.seq;
  }
}

void lockstep(lcm::LCM& lcm, const aula::sim_clock_t& tick) {
  aula::lockstep_ack_t ack{};
  ack.client = "vacuum-cleaner";
  for (int64_t seq = tick.seq; seq < tick.seq + 50; ++seq) {
    ack.seq = seq;
    ack.utime = tick.utime;
    lcm.publish(aula::lcmbus::kLockstepAckChannel, &ack);
  }
  aula::lockstep_register_t leave{};
  leave.client = "vacuum-cleaner";
  leave.period_us = 80000;
  leave.leave = true;
  lcm.publish(aula::lcmbus::kLockstepRegisterChannel, &leave);
}

void episode(lcm::LCM& lcm, const aula::sim_clock_t& tick) {
  aula::episode_t msg{};
  msg.utime = tick.utime;
  msg.exercise = "vacuum";
  msg.algorithm = "student";
  msg.running = true;
  msg.generation = 1;  // "the student reloaded": a referee that follows it starts grading afresh
  msg.started_utime = tick.utime;
  lcm.publish("VACUUM_EPISODE", &msg);
  msg.generation = 0;
  msg.started_utime = tick.utime;  // "the run started now": the time before it would not count
  lcm.publish("VACUUM_EPISODE", &msg);
}

void garbage(lcm::LCM& lcm) {
  const std::vector<std::string> channels = {
      "SIM_CLOCK",   "SIM_CONTROL",       "SIM_LOCKSTEP_REGISTER", "SIM_LOCKSTEP_ACK", "ROOMBA_POSE",
      "ROOMBA_LASER", "ROOMBA_BUMPER",    "ROOMBA_MOTORS",         "VACUUM_EPISODE",   "VACUUM_REFEREE"};
  std::mt19937 random(15);
  std::uniform_int_distribution<int> byte(0, 255), length(1, 300);
  std::vector<uint8_t> packet;
  for (int i = 0; i < 10000; ++i) {
    packet.resize(static_cast<size_t>(length(random)));
    for (auto& b : packet) b = static_cast<uint8_t>(byte(random));
    lcm.publish(channels[static_cast<size_t>(i) % channels.size()], packet.data(), static_cast<unsigned>(packet.size()));
    if (i % 500 == 499) std::this_thread::sleep_for(std::chrono::milliseconds(5));  // no flood control in LCM
  }
}

}  // namespace

int main(int argc, char** argv) {
  const auto cl = aula::config::CommandLine::parse(argc, argv, {"lcm-url", "attack", "after-s"});
  const std::string attack = cl.option("attack");
  lcm::LCM lcm(cl.option("lcm-url"));
  if (!lcm.good()) {
    std::cerr << "aula-test-attacker: cannot open " << cl.option("lcm-url") << "\n";
    return 1;
  }
  const auto tick = waitForTick(lcm, static_cast<int64_t>(cl.optionDouble("after-s", 5) * 1e6));
  if (!tick) {
    std::cerr << "aula-test-attacker: the run never reached " << cl.option("after-s") << " s of sim time\n";
    return 1;
  }
  if (attack == "pose-flood") poseFlood(lcm, *tick);
  else if (attack == "control") control(lcm);
  else if (attack == "clock") forgedClock(lcm, *tick, false);
  else if (attack == "clock-instance") forgedClock(lcm, *tick, true);
  else if (attack == "none") {}
  else if (attack == "lockstep") lockstep(lcm, *tick);
  else if (attack == "episode") episode(lcm, *tick);
  else if (attack == "garbage") garbage(lcm);
  else {
    std::cerr << "aula-test-attacker: unknown --attack=" << attack << "\n";
    return 2;
  }
  std::cerr << "aula-test-attacker: " << attack << " sent at " << tick->utime / 1e6 << " s of sim time\n";
  return 0;
}
