#pragma once
// The LCM bus of a process: URL resolution, and a connection that fails loudly and receives only
// the channels the process subscribes to.

#include <aula/lcm/udpm_sender.hpp>

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace aula::config { class Config; struct CommandLine; }

namespace aula::lcmbus {

// The simulator's own channels (fixed: every process and stock tool finds the clock by name).
inline constexpr const char* kDefaultUrl = "udpm://239.255.76.67:7667?ttl=0";
inline constexpr const char* kClockChannel = "SIM_CLOCK";
inline constexpr const char* kControlChannel = "SIM_CONTROL";
inline constexpr const char* kLockstepRegisterChannel = "SIM_LOCKSTEP_REGISTER";
inline constexpr const char* kLockstepAckChannel = "SIM_LOCKSTEP_ACK";
// A simulator about to start asks (a sim_clock_t of its own, seq -1, no clients) whether another
// runs on the URL; a running one answers at once with its current SIM_CLOCK tick.
inline constexpr const char* kHelloChannel = "SIM_HELLO";

class BusError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// URL precedence: --lcm-url option, then the cfg key Aula.LcmUrl, then $LCM_DEFAULT_URL,
// then kDefaultUrl.
std::string resolveUrl(const config::CommandLine& cl, const config::Config& cfg);

// A UDP port the OS hands out (bound to port 0, then released): the kernel never hands out a
// port that a running run's LCM sockets are bound to. Throws BusError if it cannot.
int freeUdpPort();
// `url` with a port the OS hands out when it is a udpm:// URL whose port is 0 (the launcher's,
// and so `aula grade`'s: runs at once on one machine never meet on a port); else `url` as it is.
std::string withFreePort(const std::string& url);

// LCM keeps at most 30 undelivered messages per subscription and silently drops the rest. In
// lockstep a client may sleep while the simulator runs a whole sync period ahead (a 1 s
// referee period is 50 pose messages), so every Aula subscription queues up to this many:
// the lockstep protocol, not the queue, bounds how far a reader can fall behind.
inline constexpr int kQueueCapacity = 10000;

// The classic BPF program (linux/filter.h's sock_filter) that passes an LCM packet on the run's
// URL only when it carries one of `channels`: a short message (LCM's "LC02" header, 8 bytes after
// the UDP header) whose NUL-terminated channel name is one of them, or any fragment of a long
// message ("LC03": only the first fragment names its channel). Everything else is dropped by the
// kernel before it is queued on the socket.
struct SocketFilterInstruction {
  uint16_t code;
  uint8_t jump_if_true;
  uint8_t jump_if_false;
  uint32_t value;
};
// With a gate, messages on the gate's channel pass only when their first field (an int64 after
// LCM's type hash: sim_clock_t's utime) is at least `from_utime_us`: ticks before then are dropped.
struct TickGate {
  std::string channel;
  int64_t from_utime_us = 0;
};
std::vector<SocketFilterInstruction> channelFilter(const std::set<std::string>& channels,
                                                   const std::optional<TickGate>& gate = std::nullopt);

class UdpmReceiver;
struct LcmMessage;

// One process's LCM bus, with lcm::LCM's calls (publish, subscribe, handle...).
//
// Every channel stays on the run's one URL (udpm://GROUP:PORT), where every stock LCM tool sees it:
// messages go out as LCM's own datagrams (a short message, through a UdpmSender: a held burst in
// one system call; a long one, through LCM's publish). On udpm:// they come in through a UdpmReceiver on the
// thread that calls handle(), not LCM's receive thread (one wake-up and one recvmmsg for every
// datagram waiting, instead of two wake-ups and five system calls per message). Its socket
// carries a kernel socket filter (channelFilter) that passes only the channels the process
// subscribes to: the others are dropped before they are queued. Order is kept: what passes
// arrives as it was sent, on the one socket. The subscriptions are LCM's own (lcm::LCM::subscribe
// on an in-process lcm::LCM), and each message is handed to them by LCM's own dispatch
// (lcm_dispatch_handlers, what LCM's udpm provider calls), so handlers, decoding and queues are
// LCM's. A process that defers channels (deferWakeUps) is woken by a second socket on the URL
// that passes only what is not deferred (docs/architecture.md, "The bus"). Other URLs (memq://,
// file://) are one plain lcm::LCM.
class Bus {
 public:
  // Opens the bus or throws BusError with the reason and the fix (e.g. no multicast route).
  explicit Bus(std::string url);
  ~Bus();
  Bus(const Bus&) = delete;
  Bus& operator=(const Bus&) = delete;

  const std::string& url() const { return url_; }

  template <class Message>
  int publish(const std::string& channel, const Message* message) {
    std::vector<uint8_t>& bytes = holding_ ? holdSlot(channel) : encoded_;
    bytes.resize(static_cast<std::size_t>(message->getEncodedSize()));
    if (message->encode(bytes.data(), 0, static_cast<int>(bytes.size())) < 0) return -1;
    return holding_ ? 0 : send(channel, bytes.data(), static_cast<unsigned int>(bytes.size()));
  }
  int publish(const std::string& channel, const void* data, unsigned int size) {
    if (!holding_) return send(channel, data, size);
    const auto* bytes = static_cast<const uint8_t*>(data);
    holdSlot(channel).assign(bytes, bytes + size);
    return 0;
  }

  // Holds what is published from here until flush(), which sends it all in order, in one system
  // call on udpm:// (UdpmSender). A burst wakes a sleeping receiver once instead of once per
  // message: the simulator holds the sensor messages of a tick period while it steps the physics,
  // and sends them with the tick; a lockstep client sends its commands with its ack.
  void hold() { holding_ = true; }
  // Sends what was held, in order; 0, or the first failed publish's status.
  int flush();

  // lcm::LCM::subscribe with the queue above, and the channel let through the socket filter. A
  // channel given as a regular expression (".*", a recorder) lifts the filter: every channel.
  template <class... SubscribeArgs>
  lcm::Subscription* subscribe(const std::string& channel, SubscribeArgs&&... args) {
    lcm::Subscription* subscription = subscriptions().subscribe(channel, std::forward<SubscribeArgs>(args)...);
    if (subscription != nullptr) {
      subscription->setQueueCapacity(kQueueCapacity);
      subscribed_.emplace(subscription, channel);
    }
    pass(channel);
    return subscription;
  }
  // LCM's unsubscribe; a channel that nothing of this bus subscribes to any more (nor listens to:
  // listen()) is dropped by the socket filter again.
  void unsubscribe(lcm::Subscription* subscription);
  // Lets `channel` through the socket filter now, before anything subscribes to it: its messages
  // wait in the socket, in order, until handle() hands them to the subscriptions made by then (the
  // simulator's clients register while it loads its world). subscribe() does it too.
  void listen(const std::string& channel);

  // Waits for the next message and hands it to its subscriptions: 0, or -1 on an error or a
  // signal.
  int handle();
  // The same, waiting at most `timeout_ms` (0: only what is already queued): 1 when a message was
  // handed over, 0 when none came in time, -1 on an error.
  int handleTimeout(int timeout_ms);
  // Hands `data` to this process's own subscriptions on `channel` as if it had come in (nothing
  // is sent): a simulator driven by recorded commands (aula-sim --commands).
  void inject(const std::string& channel, const void* data, unsigned int size);
  // Messages on `channel` no longer wake this process by themselves: they wait in the kernel, in
  // order, until something else wakes it, and are then handled first (a referee grades a second
  // of poses at its own tick, instead of waking at every tick). On udpm:// only; what wakes the
  // process is then read on a second socket of the URL (the "doorbell", UdpmReceiver::wakeOnly).
  void deferWakeUps(const std::string& channel);
  // Every channel let through so far but `waking` defers its wake-ups, and the doorbell passes
  // every tick (wakeForTicksFrom no longer changes it: a new filter each control period costs
  // more than the ticks it would keep out). A lockstep component is woken once a burst, by its
  // tick, the burst's last datagram.
  void wakeOnlyFor(const std::set<std::string>& waking);
  // And clock ticks (kClockChannel) before `utime_us` do not wake it either: a lockstep client
  // that is not due until then (LockstepClient). Only once some channel is deferred.
  void wakeForTicksFrom(int64_t utime_us);
  // Messages handled so far (only the subscribed ones reach the process).
  long long handled() const { return handled_; }
  // The descriptor that becomes readable when a message waits (for select, poll, QSocketNotifier).
  // On udpm:// one read takes every datagram waiting, so once it fires call handleTimeout(0)
  // until it returns 0.
  int getFileno();

 private:
  lcm::LCM& subscriptions() { return dispatcher_ ? *dispatcher_ : *lcm_; }
  void pass(const std::string& channel);  // let `channel` through the socket filter
  std::vector<uint8_t>& holdSlot(const std::string& channel);
  // One message now: on udpm://, a short one through sender_, a long one through LCM's publish
  // (its fragments); else LCM's publish.
  int send(const std::string& channel, const void* data, unsigned int size);
  bool sendsItself(const std::string& channel, std::size_t size) const;  // through sender_
  void dispatch(const LcmMessage& message, int64_t received_utime);
  void selfTest();
  void updateFilters();   // the receiver's socket filters: channels_, then the doorbell's
  void updateDoorbell();  // what wakes the process: channels_ but deferred_, ticks from the gate

  std::string url_;
  std::unique_ptr<lcm::LCM> lcm_;         // the URL's LCM: publishes (and receives, off udpm://)
  std::unique_ptr<lcm::LCM> dispatcher_;  // udpm://: an in-process LCM holding the subscriptions
  std::unique_ptr<UdpmReceiver> receiver_;  // udpm://: the run's multicast socket, read here
  std::unique_ptr<UdpmSender> sender_;      // udpm://: LCM's short messages, sent here
  std::vector<uint8_t> encoded_;            // a message published at once, encoded (reused)
  std::vector<UdpmSender::Message> burst_;  // flush()'s (reused)
  bool receive_all_ = false;     // a pattern subscription: no filter
  bool holding_ = false;         // hold() until flush()
  std::vector<std::pair<std::string, std::vector<uint8_t>>> held_;  // reused: the first held_count_ wait
  std::size_t held_count_ = 0;
  std::set<std::string> channels_;  // let through the filter
  std::set<std::string> listened_;  // listen() without a subscription: kept through unsubscribe()
  std::map<lcm::Subscription*, std::string> subscribed_;  // each subscription's channel
  std::set<std::string> deferred_;  // never wake the process (deferWakeUps)
  int64_t wake_for_ticks_from_us_ = 0;
  bool gate_ticks_ = true;  // wakeForTicksFrom moves the doorbell's tick gate
  long long handled_ = 0;
  bool print_stats_ = false;  // $AULA_BUS_STATS set: say how many messages were handled, at the end
};

// Opens the bus (Bus's constructor, as a unique_ptr).
std::unique_ptr<Bus> openBus(const std::string& url);

}  // namespace aula::lcmbus
