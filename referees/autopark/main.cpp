// autopark-referee [--config=config/autopark.cfg] [--headless] [--report=FILE.json] [--lcm-url=URL]
//                  [--screenshot=FILE.png]
// Grades an Autopark run on simulated time from the true geometry. Headless, it prints the mark
// and writes the report when the car has parked (or at the timeout), then exits.
#include "src/parking_referee_node.hpp"
#include "src/parking_referee_window.hpp"

#include <aula/app/run_referee.hpp>

int main(int argc, char** argv) {
  return aula::app::guardedMain("autopark-referee", [&] {
    auto setup = aula::app::ProcessSetup::fromArgs(argc, argv, "config/autopark.cfg", {"report", "screenshot"});
    aula::autopark::ParkingRefereeNode node(*setup.bus, setup.cfg);
    return aula::app::runReferee<aula::autopark::ParkingRefereeNode, aula::autopark::ParkingRefereeWindow>(setup, node, argc, argv);
  });
}
