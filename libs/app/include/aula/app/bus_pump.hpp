#pragma once
// LCM in an event loop without threads: in a Qt application a QSocketNotifier on the bus's file
// descriptor calls handle() when data arrive; headless, runHeadless() polls the same descriptor.
// Either way every LCM callback runs on the one main thread that also owns the widgets. The stop
// signals (Ctrl-C, the launcher's SIGTERM) are watched the same way: headless they end the loop,
// with a window they quit the application, so the process leaves lockstep and exits cleanly.

#include <aula/lcm/bus.hpp>
#include <aula/process/signal_watcher.hpp>
#include <lcm/lcm-cpp.hpp>

#include <QObject>
#include <QSocketNotifier>
#include <QTimer>

#include <functional>

namespace aula::app {

class BusPump : public QObject {
  Q_OBJECT
 public:
  // `housekeeping` runs every `housekeeping_ms` of wall time (re-registration, timeouts).
  BusPump(lcmbus::Bus& bus, std::function<void()> housekeeping, int housekeeping_ms = 50,
          QObject* parent = nullptr);

 private:
  void drain();
  lcmbus::Bus& bus_;
  QSocketNotifier notifier_;
  process::SignalWatcher stop_signals_;
  QSocketNotifier stop_notifier_;
  QTimer timer_;
  std::function<void()> housekeeping_;
};

// Headless loop: handles the bus until `done()` is true or SIGINT/SIGTERM arrives.
// `housekeeping` runs at least every 50 ms of wall time. Returns true when stopped by a signal.
bool runHeadless(lcmbus::Bus& bus, const std::function<bool()>& done,
                 const std::function<void()>& housekeeping);

}  // namespace aula::app
