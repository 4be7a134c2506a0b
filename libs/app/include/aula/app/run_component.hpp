#pragma once
// The one flow of every academic component process. Headless: handle the bus (the component
// runs the algorithm on sim time) until a signal. With a display: the component's window.
// Either way the component leaves the lockstep at the end, so the simulator never waits for it.
//
// The simulator gone (it ended the run, or its clock stopped: killed in its terminal), the
// component says why and ends, exit code 1, windows or not; a replay's viewer (--view-only) does
// not watch, since a replay pauses and ends.
//
// Component needs poll(), leave(), containHangs(), reportCrashesTo(fd), algorithm().hung(),
// simulatorGone(), watchedByLauncher(); Window needs Window(Component&). The launcher's `--crash-fd` pipe gets a
// crash's one line before the component dies of it.
// A component that can find once running that its task is impossible (TeleTaxi: a destination the
// taxi cannot reach from where it stands) also has `std::optional<std::string> refusal() const`:
// headless, the process then ends with the reason as a ConfigError (exit code 2); the window
// shows it itself.
// screenshot(window, png_path) arranges `--screenshot=FILE.png` (returns false if it cannot).

#include <aula/app/bus_pump.hpp>
#include <aula/app/main_window.hpp>
#include <aula/app/process_setup.hpp>
#include <aula/process/exit_codes.hpp>

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QString>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

namespace aula::app {

template <class C, class = void>
struct CanRefuse : std::false_type {};
template <class C>
struct CanRefuse<C, std::void_t<decltype(std::declval<const C&>().refusal())>> : std::true_type {};

template <class Component>
std::optional<std::string> refusalOf(const Component& component) {
  if constexpr (CanRefuse<Component>::value) {
    return component.refusal();
  } else {
    return std::nullopt;
  }
}

// Why the component cannot go on without its simulator, or "" (always "" for a replay's viewer).
template <class Component>
std::string simulatorGoneFor(const ProcessSetup& setup, const Component& component) {
  return setup.command_line.flag("view-only") ? std::string() : component.simulatorGone();
}

inline int endWithoutSimulator(const ProcessSetup& setup, const std::string& why) {
  std::cerr << setup.program << ": " << why << ": the component ends" << std::endl;
  return process::kExitFailed;
}

template <class Window, class Component, class Screenshot>
int runComponent(ProcessSetup& setup, Component& component, int argc, char** argv, Screenshot screenshot) {
  if (setup.command_line.flag("crash-fd")) {  // started by `aula run`, which watches every process
    component.reportCrashesTo(static_cast<int>(setup.command_line.optionDouble("crash-fd", -1)));
    component.watchedByLauncher();
  }
  if (setup.headless) {
    // Woken by its ticks only: the period's sensor messages come before the tick in the same
    // burst and wait in the socket. On a CPU shared with another task, a datagram that woke it
    // mid-burst switched the simulator out in the middle of it, once per datagram (EEVDF).
    setup.bus->wakeOnlyFor({lcmbus::kClockChannel});
    std::string gone;
    runHeadless(*setup.bus, [&] { return refusalOf(component).has_value() || !gone.empty(); }, [&] {
      component.poll();
      gone = simulatorGoneFor(setup, component);
    });
    component.leave();
    if (const auto why = refusalOf(component)) throw config::ConfigError(*why);
    return gone.empty() ? 0 : endWithoutSimulator(setup, gone);
  }
  QApplication app(argc, argv);
  component.containHangs();  // a hung execute() halts the algorithm; the window stays
  Window window(component);
  std::string gone;
  BusPump pump(*setup.bus, [&] {
    component.poll();
    if (gone.empty() && !(gone = simulatorGoneFor(setup, component)).empty()) QCoreApplication::exit(process::kExitFailed);
  });
  if (setup.command_line.flag("view-only")) {
    // A replay (aula replay): the window shows what it is sent, and nothing in it can act. It
    // names the recorded algorithm (--view-only=NAME), not the one this process loaded to
    // start, which the panel would show.
    for (QWidget* w : window.template findChildren<QWidget*>()) {
      const bool control = qobject_cast<QAbstractButton*>(w) != nullptr || qobject_cast<QComboBox*>(w) != nullptr ||
                           std::strcmp(w->metaObject()->className(), "aula::gui::Teleoperator") == 0;
      if (control) w->setEnabled(false);
      if (w->objectName() == "AlgorithmPanel") w->hide();
    }
    const std::string recorded = setup.command_line.option("view-only");
    window.setWindowTitle(window.windowTitle() + QString::fromStdString(" - replay of " + (recorded.empty() ? "a run" : recorded)) +
                          ", view only");
  }
  placeMainWindow(window, setup.program, setup.cfg);
  quitWhenClosed(window);
  window.show();
  int code = 1;
  if (!setup.command_line.flag("screenshot") ||
      screenshot(window, QString::fromStdString(setup.command_line.option("screenshot")))) {
    code = app.exec();
  }
  component.leave();
  if (!gone.empty()) code = endWithoutSimulator(setup, gone);
  if (component.algorithm().hung()) {
    // A call into the student's code is still running on its thread, in the algorithm, the
    // plugin and the devices: nothing may be destroyed under it.
    std::cout.flush();
    std::cerr.flush();
    std::_Exit(code);
  }
  return code;
}

}  // namespace aula::app
