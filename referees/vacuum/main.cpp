// vacuum-cleaner-referee [--config=config/vacuumCleaner.cfg] [--headless] [--report=FILE.json]
// Measures the floor the roomba cleans in 900 s of simulated time and gives the mark.
#include "src/coverage_referee_node.hpp"
#include "src/coverage_referee_window.hpp"

#include <aula/app/bus_pump.hpp>
#include <aula/app/process_setup.hpp>

#include <QApplication>

#include <iostream>

int main(int argc, char** argv) {
  return aula::app::guardedMain("vacuum-cleaner-referee", [&] {
    auto setup = aula::app::ProcessSetup::fromArgs(argc, argv, "config/vacuumCleaner.cfg", {"report", "screenshot"});
    const std::string report_path = setup.command_line.option("report");
    aula::vacuum::CoverageRefereeNode node(*setup.bus, setup.cfg);
    auto finish = [&] {
      std::cout << node.summary() << std::flush;
      if (!report_path.empty()) node.report().writeAtomically(report_path);
    };
    if (setup.headless) {
      const bool signalled = aula::app::runHeadless(*setup.bus, [&] { return node.finished(); }, [&] { node.poll(); });
      node.leave();
      if (signalled && !node.finished()) std::cout << "(stopped before the end of the run)\n";
      finish();
      return 0;
    }
    QApplication app(argc, argv);
    aula::vacuum::CoverageRefereeWindow window(node);
    aula::app::BusPump pump(*setup.bus, [&] { node.poll(); });
    node.setOnFinished([&] {
      window.showMark();
      finish();
    });
    window.show();
    if (setup.command_line.flag("screenshot")) {
      window.screenshotWhenFinished(QString::fromStdString(setup.command_line.option("screenshot")));
    }
    const int code = app.exec();
    node.leave();
    return code;
  });
}
