#pragma once
// The LCM bus of a process: URL resolution and a connection that fails loudly.

#include <lcm/lcm-cpp.hpp>

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace aula::config { class Config; struct CommandLine; }

namespace aula::lcmbus {

// Default channels of the simulator's own messages (overridable in simulator.cfg).
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

// Opens the bus or throws BusError with the reason and the fix (e.g. no multicast route).
std::unique_ptr<lcm::LCM> openBus(const std::string& url);

// LCM keeps at most 30 undelivered messages per subscription and silently drops the rest. In
// lockstep a client may sleep while the simulator runs a whole sync period ahead (a 1 s
// referee period is 50 pose messages), so every Aula subscription queues up to this many:
// the lockstep protocol, not the queue, bounds how far a reader can fall behind.
inline constexpr int kQueueCapacity = 10000;

// bus.subscribe(...) with the queue above: use it for every subscription.
template <class... SubscribeArgs>
lcm::Subscription* subscribe(lcm::LCM& bus, SubscribeArgs&&... args) {
  lcm::Subscription* subscription = bus.subscribe(std::forward<SubscribeArgs>(args)...);
  if (subscription != nullptr) subscription->setQueueCapacity(kQueueCapacity);
  return subscription;
}

}  // namespace aula::lcmbus
