#include "aula/lcm/lockstep_client.hpp"

#include <aula/config/config.hpp>

#include "aula/lcm/bus.hpp"

#include <aula/lockstep_ack_t.hpp>
#include <aula/lockstep_register_t.hpp>

#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <utility>

namespace aula::lcmbus {
namespace {
constexpr auto kRegisterResend = std::chrono::milliseconds(100);
constexpr auto kForeignLogEvery = std::chrono::seconds(10);
constexpr int64_t kLongestNapUs = 1000000;
}

LockstepClient::LockstepClient(lcmbus::Bus& bus, std::string client_name, int64_t period_us,
                               TickHandler on_tick, const std::optional<auth::Key>& client_key)
    : bus_(bus), name_(std::move(client_name)), period_us_(period_us), on_tick_(std::move(on_tick)) {
  if (period_us_ <= 0) period_us_ = 1;
  if (client_key) signer_.emplace(*client_key);
  subscription_ = bus_.subscribe(kClockChannel, &LockstepClient::onClock, this);
  hello_subscription_ = bus_.subscribe(kHelloChannel, &LockstepClient::onHello, this);
  sendRegister(false);
}

LockstepClient::~LockstepClient() {
  leave();
  if (subscription_ != nullptr) bus_.unsubscribe(subscription_);
  if (hello_subscription_ != nullptr) bus_.unsubscribe(hello_subscription_);
}

// A simulator starting up says hello once it listens: a client started before it (a simulator
// loads DART and its world for tens of ms, a client is quicker) registers again at once instead
// of at its next re-send.
void LockstepClient::onHello(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t*) {
  if (!left_ && !registered_) sendRegister(false);
}

void LockstepClient::poll() {
  if (!world_mismatch_.empty()) throw config::ConfigError(world_mismatch_);
  if (left_ || registered_) return;
  if (std::chrono::steady_clock::now() - last_register_ >= kRegisterResend) sendRegister(false);
}

void LockstepClient::leave() {
  if (left_) return;
  left_ = true;
  sendRegister(true);
}

void LockstepClient::sendRegister(bool leave) {
  aula::lockstep_register_t msg{};
  msg.client = name_;
  msg.period_us = period_us_;
  msg.leave = leave;
  msg.pid = static_cast<int32_t>(::getpid());  // outside grading, a silent client is waited for while it lives
  if (signer_) auth::sign(*signer_, kLockstepRegisterChannel, msg);
  bus_.publish(kLockstepRegisterChannel, &msg);
  last_register_ = std::chrono::steady_clock::now();
}

std::string LockstepClient::simulatorGone(std::chrono::steady_clock::time_point now) const {
  if (last_look_ == std::chrono::steady_clock::time_point{} || now - last_look_ > kLookGap) watched_from_ = now;
  last_look_ = std::max(last_look_, now);
  if (!instance_locked_) return "";
  if (!last_tick_.ended.empty()) return "the simulator ended the run: " + last_tick_.ended;
  if (!silence_means_gone_ || now - std::max(last_clock_, watched_from_) < kSimulatorSilence) return "";
  return "the simulator stopped (no " + std::string(kClockChannel) + " for " + std::to_string(kSimulatorSilence.count()) +
         " s of wall time)";
}

void LockstepClient::sendAck(int64_t seq, int64_t utime) {
  aula::lockstep_ack_t ack{};
  ack.client = name_;
  ack.seq = seq;
  ack.utime = utime;
  if (signer_) auth::sign(*signer_, kLockstepAckChannel, ack);
  bus_.publish(kLockstepAckChannel, &ack);
}

void LockstepClient::expectWorld(const std::string& sha256, const std::string& path) {
  expected_world_sha256_ = sha256;
  expected_world_path_ = path;
}

void LockstepClient::noteForeignTick(const aula::sim_clock_t& tick) {
  ++foreign_ticks_;
  const auto now = std::chrono::steady_clock::now();
  if (foreign_ticks_ > 1 && tick.instance == last_logged_foreign_ && now - last_foreign_log_ < kForeignLogEvery) return;
  last_logged_foreign_ = tick.instance;
  last_foreign_log_ = now;
  std::cerr << name_ << ": ignoring " << kClockChannel << " ticks of another simulator (instance " << tick.instance
            << ", world '" << tick.world << "'; following instance " << instance_ << "): " << foreign_ticks_
            << " so far" << std::endl;
}

void LockstepClient::onClock(const lcm::ReceiveBuffer*, const std::string& channel,
                             const aula::sim_clock_t* tick) {
  if (accept_ && !accept_(channel, *tick)) return;
  if (instance_locked_ && tick->instance != instance_) {
    noteForeignTick(*tick);
    return;
  }
  if (!expected_world_sha256_.empty() && tick->world_sha256 != expected_world_sha256_) {
    world_mismatch_ = "the simulator runs world '" + tick->world + "' (sha256 " + tick->world_sha256.substr(0, 12) +
                      ") but this process was given " + expected_world_path_ + " (sha256 " +
                      expected_world_sha256_.substr(0, 12) + "): it will not grade another world; give all "
                      "three processes the same --world";
    return;
  }
  last_clock_ = std::chrono::steady_clock::now();
  lockstep_ = tick->lockstep;
  paused_ = tick->paused;
  rtf_ = tick->real_time_factor;
  last_tick_ = *tick;
  bool listed = false;
  for (const auto& c : tick->clients) listed = listed || c == name_;
  registered_ = listed && !left_;
  if (listed && !instance_locked_) {  // our simulator: from now on we follow it only
    instance_locked_ = true;
    instance_ = tick->instance;
  }

  if (tick->seq == last_seq_) {
    // The simulator re-sent a tick: our ack was lost. Ack again, do not run twice.
    if (registered_ && lockstep_) sendAck(tick->seq, tick->utime);
    return;
  }
  // A seq below the last one: the simulator is the one sender of its ticks, on one socket that
  // never reorders them, so the last one was not its (a forged tick with a huge seq, which a
  // client without the run's key cannot tell apart): follow the simulator again, or this client
  // would ignore every real tick from now on and stop acking.
  if (tick->utime < last_utime_) next_due_us_ = 0;  // world reset: time went back
  last_seq_ = tick->seq;
  last_utime_ = tick->utime;

  if (tick->utime >= next_due_us_) {
    next_due_us_ = (tick->utime / period_us_ + 1) * period_us_;
    // Ticks before the next due one need not wake this process (when its bus defers anything);
    // at most kLongestNap of sim time, so that what waits unread stays far below the socket's queue.
    bus_.wakeForTicksFrom(std::min(next_due_us_, tick->utime + kLongestNapUs));
    // What the period publishes (the commands) goes out with the ack, in one system call: the
    // simulator, waiting for the ack, is woken once.
    struct SentAtTheEnd {  // also when the period's work throws
      Bus& bus;
      ~SentAtTheEnd() { bus.flush(); }
    } held{bus_};
    bus_.hold();
    if (on_tick_) on_tick_(tick->utime);
    if (registered_ && lockstep_) sendAck(tick->seq, tick->utime);
  }
}

}  // namespace aula::lcmbus
