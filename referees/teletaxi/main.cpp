// teletaxi-referee [--config=config/teleTaxi.cfg] [--headless] [--report=FILE.json] [--lcm-url=URL]
//                  [--picture=FILE.png] [--trace=FILE.json] [--screenshot=FILE.png]
// Grades a TeleTaxi run on simulated time. Headless, it prints the mark and writes the report
// when the episode ends, then exits.
#include "src/taxi_referee_node.hpp"
#include "src/taxi_referee_window.hpp"

#include <aula/app/run_referee.hpp>

namespace {
constexpr const char* kUsage =
    "usage: teletaxi-referee [--config=config/teleTaxi.cfg] [--headless] [--report=FILE.json] [--lcm-url=URL]\n"
    "                 [--picture=FILE.png] [--trace=FILE.json] [--screenshot=FILE.png]\n"
    "Grades a TeleTaxi run on simulated time. Headless, it prints the mark and writes the report\n"
    "when the episode ends, then exits.\n"
    "  --picture  at the end, a PNG of the city with the taxi's path, the start, the destination and the mark\n"
    "  --trace    at the end, the run as the referee graded it (poses at 10 Hz, its state, its events), for the\n"
    "             player of `aula grade`'s page\n";
}  // namespace

int main(int argc, char** argv) {
  return aula::app::guardedMain("teletaxi-referee", [&] {
    auto setup = aula::app::refereeSetup(argc, argv, "teletaxi-referee", kUsage);
    aula::teletaxi::TaxiRefereeNode node(*setup.bus, setup.cfg, setup.world, setup.run_key);
    return aula::app::runReferee<aula::teletaxi::TaxiRefereeNode, aula::teletaxi::TaxiRefereeWindow>(setup, node, argc, argv);
  });
}
