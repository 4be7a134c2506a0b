#include "aula/app/bus_pump.hpp"

#include <csignal>

#include <poll.h>
#include <sys/signalfd.h>
#include <unistd.h>

namespace aula::app {

BusPump::BusPump(lcm::LCM& bus, std::function<void()> housekeeping, int housekeeping_ms,
                 QObject* parent)
    : QObject(parent),
      bus_(bus),
      notifier_(bus.getFileno(), QSocketNotifier::Read),
      housekeeping_(std::move(housekeeping)) {
  connect(&notifier_, &QSocketNotifier::activated, this, [this] { drain(); });
  connect(&timer_, &QTimer::timeout, this, [this] {
    drain();  // memq:// has no descriptor activity; also catches anything the notifier missed
    if (housekeeping_) housekeeping_();
  });
  timer_.start(housekeeping_ms);
}

void BusPump::drain() {
  while (bus_.handleTimeout(0) > 0) {
  }
}

bool runHeadless(lcm::LCM& bus, const std::function<bool()>& done,
                 const std::function<void()>& housekeeping) {
  sigset_t mask;
  sigemptyset(&mask);
  sigaddset(&mask, SIGINT);
  sigaddset(&mask, SIGTERM);
  sigprocmask(SIG_BLOCK, &mask, nullptr);
  const int signal_fd = signalfd(-1, &mask, SFD_NONBLOCK | SFD_CLOEXEC);
  bool signalled = false;
  while (!done()) {
    signalfd_siginfo info;
    if (read(signal_fd, &info, sizeof info) == static_cast<ssize_t>(sizeof info)) {
      signalled = true;
      break;
    }
    bus.handleTimeout(50);
    while (bus.handleTimeout(0) > 0 && !done()) {
    }
    if (housekeeping) housekeeping();
  }
  close(signal_fd);
  return signalled;
}

}  // namespace aula::app
