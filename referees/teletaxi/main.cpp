// teletaxi-referee [--config=config/teleTaxi.cfg] [--headless] [--report=FILE.json] [--lcm-url=URL]
// Grades a TeleTaxi run on simulated time. Headless, it prints the mark and writes the report
// when the episode ends, then exits.
#include "src/taxi_referee_node.hpp"
#include "src/taxi_referee_window.hpp"

#include <aula/app/bus_pump.hpp>
#include <aula/app/process_setup.hpp>

#include <QApplication>

#include <iostream>

int main(int argc, char** argv) {
  return aula::app::guardedMain("teletaxi-referee", [&] {
    auto setup = aula::app::ProcessSetup::fromArgs(argc, argv, "config/teleTaxi.cfg", {"report", "screenshot"});
    const std::string report_path = setup.command_line.option("report");
    aula::teletaxi::TaxiRefereeNode node(*setup.bus, setup.cfg);
    auto finish = [&] {
      std::cout << node.summary() << std::flush;
      if (!report_path.empty()) node.report().writeAtomically(report_path);
    };
    if (setup.headless) {
      const bool signalled =
          aula::app::runHeadless(*setup.bus, [&] { return node.finished(); }, [&] { node.poll(); });
      node.leave();
      if (signalled && !node.finished()) std::cout << "(stopped before the end of the episode)\n";
      finish();
      return 0;
    }
    QApplication app(argc, argv);
    aula::teletaxi::TaxiRefereeWindow window(node);
    aula::app::BusPump pump(*setup.bus, [&] { node.poll(); });
    node.setOnFinished([&] {
      window.showMark();
      finish();
    });
    window.show();
    if (setup.command_line.flag("screenshot")) {
      return window.screenshotWhenReady(QString::fromStdString(setup.command_line.option("screenshot"))) ? app.exec() : 1;
    }
    const int code = app.exec();
    node.leave();
    return code;
  });
}
