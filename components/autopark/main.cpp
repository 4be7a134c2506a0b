// autopark [--config=config/autopark.cfg] [--headless] [--lcm-url=URL] [--screenshot=FILE.png [--screenshot-at=SIM_SECONDS]]
//          [--Autopark.Key=value ...]
// The Autopark academic component: find the free slot and park the car in it.
#include "src/autopark_window.hpp"

#include <aula/app/bus_pump.hpp>
#include <aula/app/process_setup.hpp>
#include <aula/autopark/autopark_component.hpp>

#include <QApplication>


int main(int argc, char** argv) {
  return aula::app::guardedMain("autopark", [&] {
    auto setup = aula::app::ProcessSetup::fromArgs(argc, argv, "config/autopark.cfg", {"screenshot", "screenshot-at"});
    aula::autopark::AutoparkComponent component(*setup.bus, setup.cfg);
    if (setup.headless) {
      aula::app::runHeadless(*setup.bus, [] { return false; }, [&] { component.poll(); });
      component.leave();
      return 0;
    }
    QApplication app(argc, argv);
    aula::autopark::AutoparkWindow window(component);
    aula::app::BusPump pump(*setup.bus, [&] { component.poll(); });
    window.show();
    if (setup.command_line.flag("screenshot")) {
      const double at_s = setup.command_line.optionDouble("screenshot-at", 40.0);
      window.screenshotAfter(QString::fromStdString(setup.command_line.option("screenshot")), static_cast<int64_t>(at_s * 1e6));
    }
    const int code = app.exec();
    component.leave();
    return code;
  });
}
