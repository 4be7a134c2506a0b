// teletaxi [--config=config/teleTaxi.cfg] [--headless] [--lcm-url=URL] [--screenshot=FILE.png]
//          [--TeleTaxi.Key=value ...]
// The TeleTaxi academic component: the city map, your Gradient Path Planning, the taxi.
#include "src/taxi_window.hpp"

#include <aula/app/bus_pump.hpp>
#include <aula/app/process_setup.hpp>
#include <aula/teletaxi/taxi_component.hpp>

#include <QApplication>

#include <iostream>

int main(int argc, char** argv) {
  return aula::app::guardedMain("teletaxi", [&] {
    auto setup = aula::app::ProcessSetup::fromArgs(argc, argv, "config/teleTaxi.cfg", {"screenshot"});
    aula::teletaxi::TaxiComponent component(*setup.bus, setup.cfg);
    if (setup.headless) {
      aula::app::runHeadless(*setup.bus, [] { return false; }, [&] { component.poll(); });
      component.leave();
      return 0;
    }
    QApplication app(argc, argv);
    aula::teletaxi::TaxiWindow window(component);
    aula::app::BusPump pump(*setup.bus, [&] { component.poll(); });
    window.show();
    if (setup.command_line.flag("screenshot")) {
      return window.screenshotWhenReady(QString::fromStdString(setup.command_line.option("screenshot"))) ? app.exec() : 1;
    }
    const int code = app.exec();
    component.leave();
    return code;
  });
}
