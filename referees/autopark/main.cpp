// autopark-referee [--config=config/autopark.cfg] [--headless] [--report=FILE.json] [--lcm-url=URL]
//                  [--picture=FILE.png] [--trace=FILE.json] [--screenshot=FILE.png]
// Grades an Autopark run on simulated time from the true geometry. Headless, it prints the mark
// and writes the report when the car has parked (or at the timeout), then exits.
#include "src/parking_referee_node.hpp"
#include "src/parking_referee_window.hpp"

#include <aula/app/run_referee.hpp>

namespace {
constexpr const char* kUsage =
    "usage: autopark-referee [--config=config/autopark.cfg] [--headless] [--report=FILE.json] [--lcm-url=URL]\n"
    "                 [--picture=FILE.png] [--trace=FILE.json] [--screenshot=FILE.png]\n"
    "Grades an Autopark run on simulated time from the true geometry. Headless, it prints the mark\n"
    "and writes the report when the car has parked (or at the timeout), then exits.\n"
    "  --picture  at the end, a PNG of the street with the slot, the car's final pose, its trail, the gaps and the mark\n"
    "  --trace    at the end, the run as the referee graded it (poses at 10 Hz, its state, its events), for the\n"
    "             player of `aula grade`'s page\n";
}  // namespace

int main(int argc, char** argv) {
  return aula::app::guardedMain("autopark-referee", [&] {
    auto setup = aula::app::refereeSetup(argc, argv, "autopark-referee", kUsage);
    aula::autopark::ParkingRefereeNode node(*setup.bus, setup.cfg, setup.world, setup.run_key);
    return aula::app::runReferee<aula::autopark::ParkingRefereeNode, aula::autopark::ParkingRefereeWindow>(setup, node, argc, argv);
  });
}
