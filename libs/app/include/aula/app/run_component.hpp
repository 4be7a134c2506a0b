#pragma once
// The one flow of every academic component process. Headless: handle the bus (the component
// runs the algorithm on sim time) until a signal. With a display: the component's window.
// Either way the component leaves the lockstep at the end, so the simulator never waits for it.
//
// Component needs poll(), leave(), containHangs(), algorithm().hung(); Window needs Window(Component&).
// A component that can find once running that its task is impossible (TeleTaxi: a destination the
// taxi cannot reach from where it stands) also has `std::optional<std::string> refusal() const`:
// headless, the process then ends with the reason as a ConfigError (exit code 2); the window
// shows it itself.
// screenshot(window, png_path) arranges `--screenshot=FILE.png` (returns false if it cannot).

#include <aula/app/bus_pump.hpp>
#include <aula/app/process_setup.hpp>

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

template <class Window, class Component, class Screenshot>
int runComponent(ProcessSetup& setup, Component& component, int argc, char** argv, Screenshot screenshot) {
  if (setup.headless) {
    runHeadless(*setup.bus, [&] { return refusalOf(component).has_value(); }, [&] { component.poll(); });
    component.leave();
    if (const auto why = refusalOf(component)) throw config::ConfigError(*why);
    return 0;
  }
  QApplication app(argc, argv);
  component.containHangs();  // a hung execute() halts the algorithm; the window stays
  Window window(component);
  BusPump pump(*setup.bus, [&] { component.poll(); });
  if (setup.command_line.flag("view-only")) {
    // A replay (aula replay): the window shows what it is sent, and nothing in it can act.
    for (QWidget* w : window.template findChildren<QWidget*>()) {
      const bool control = qobject_cast<QAbstractButton*>(w) != nullptr || qobject_cast<QComboBox*>(w) != nullptr ||
                           std::strcmp(w->metaObject()->className(), "aula::gui::Teleoperator") == 0;
      if (control) w->setEnabled(false);
    }
    window.setWindowTitle(window.windowTitle() + " - replay, view only");
  }
  window.show();
  int code = 1;
  if (!setup.command_line.flag("screenshot") ||
      screenshot(window, QString::fromStdString(setup.command_line.option("screenshot")))) {
    code = app.exec();
  }
  component.leave();
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
