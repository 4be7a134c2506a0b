// vacuum-cleaner [--config=config/vacuumCleaner.cfg] [--headless] [--lcm-url=URL] [--screenshot=FILE.png]
//                [--Vacuum.Key=value ...]
// The vacuum cleaner academic component: clean the house without localization.
#include "src/vacuum_window.hpp"

#include <aula/app/bus_pump.hpp>
#include <aula/app/process_setup.hpp>
#include <aula/vacuum/vacuum_component.hpp>

#include <QApplication>

int main(int argc, char** argv) {
  return aula::app::guardedMain("vacuum-cleaner", [&] {
    auto setup = aula::app::ProcessSetup::fromArgs(argc, argv, "config/vacuumCleaner.cfg", {"screenshot"});
    aula::vacuum::VacuumComponent component(*setup.bus, setup.cfg);
    if (setup.headless) {
      aula::app::runHeadless(*setup.bus, [] { return false; }, [&] { component.poll(); });
      component.leave();
      return 0;
    }
    QApplication app(argc, argv);
    aula::vacuum::VacuumWindow window(component);
    aula::app::BusPump pump(*setup.bus, [&] { component.poll(); });
    window.show();
    if (setup.command_line.flag("screenshot")) {
      window.screenshotAfter(QString::fromStdString(setup.command_line.option("screenshot")), 60'000'000);
    }
    const int code = app.exec();
    component.leave();
    return code;
  });
}
