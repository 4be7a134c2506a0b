#pragma once
// The LCM bus of a process: URL resolution, and a connection that fails loudly and receives only
// the channels the process subscribes to.

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <memory>
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
std::vector<SocketFilterInstruction> channelFilter(const std::set<std::string>& channels);

// This process's UDP sockets bound to `port`: LCM's receiving sockets on a udpm:// URL.
std::set<int> udpSocketsBoundTo(int port);

// One process's LCM bus, with lcm::LCM's calls (publish, subscribe, handle...).
//
// Every channel stays on the run's one URL (udpm://GROUP:PORT), where every stock LCM tool sees it.
// On udpm://, the process's receiving socket (LCM's, read by LCM's receive thread) carries a
// kernel socket filter (channelFilter) that passes only the channels the process subscribes to:
// the others are dropped before they are queued, so they cost no read, no wake-up and no copy.
// Order is kept: what passes arrives as it was sent, on the one socket. Other URLs (memq://,
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
    return receiver_->publish(channel, message);
  }
  int publish(const std::string& channel, const void* data, unsigned int size) {
    return receiver_->publish(channel, data, size);
  }

  // lcm::LCM::subscribe with the queue above, and the channel let through the socket filter. A
  // channel given as a regular expression (".*", a recorder) lifts the filter: every channel.
  template <class... SubscribeArgs>
  lcm::Subscription* subscribe(const std::string& channel, SubscribeArgs&&... args) {
    lcm::Subscription* subscription = receiver_->subscribe(channel, std::forward<SubscribeArgs>(args)...);
    if (subscription != nullptr) subscription->setQueueCapacity(kQueueCapacity);
    receive(channel);
    return subscription;
  }
  void unsubscribe(lcm::Subscription* subscription) { receiver_->unsubscribe(subscription); }

  int handle() {
    const int status = receiver_->handle();
    if (status == 0) ++handled_;
    return status;
  }
  int handleTimeout(int timeout_ms) {
    const int status = receiver_->handleTimeout(timeout_ms);
    if (status > 0) ++handled_;
    return status;
  }
  // Messages handled so far (LCM hands over only the subscribed ones).
  long long handled() const { return handled_; }
  // The descriptor that becomes readable when a message waits (for select, poll, QSocketNotifier).
  int getFileno() { return receiver_->getFileno(); }

 private:
  void receive(const std::string& channel);
  void applyFilter();

  std::string url_;
  std::unique_ptr<lcm::LCM> receiver_;
  int receive_fd_ = -1;          // LCM's receiving socket (udpm://), -1 when not found
  bool receive_all_ = false;     // a pattern subscription: no filter
  std::set<std::string> channels_;  // let through the filter
  long long handled_ = 0;
  bool print_stats_ = false;  // $AULA_BUS_STATS set: say how many messages were handled, at the end
};

// Opens the bus (Bus's constructor, as a unique_ptr).
std::unique_ptr<Bus> openBus(const std::string& url);

}  // namespace aula::lcmbus
