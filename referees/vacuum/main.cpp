// vacuum-cleaner-referee [--config=config/vacuumCleaner.cfg] [--headless] [--report=FILE.json]
//                        [--picture=FILE.png] [--trace=FILE.json] [--lcm-url=URL] [--screenshot=FILE.png]
// Measures the floor the roomba cleans in 900 s of simulated time and gives the mark.
#include "src/coverage_referee_node.hpp"
#include "src/coverage_referee_window.hpp"

#include <aula/app/run_referee.hpp>

namespace {
constexpr const char* kUsage =
    "usage: vacuum-cleaner-referee [--config=config/vacuumCleaner.cfg] [--headless] [--report=FILE.json]\n"
    "                       [--picture=FILE.png] [--trace=FILE.json] [--lcm-url=URL] [--screenshot=FILE.png]\n"
    "Measures the floor the roomba cleans in 900 s of simulated time and gives the mark.\n"
    "  --picture  at the end, a PNG of the house with the cleaned floor, the robot and the mark\n"
    "  --trace    at the end, the run as the referee graded it (poses at 10 Hz, its state, its events), for the\n"
    "             player of `aula grade`'s page\n";
}  // namespace

int main(int argc, char** argv) {
  return aula::app::guardedMain("vacuum-cleaner-referee", [&] {
    auto setup = aula::app::refereeSetup(argc, argv, "vacuum-cleaner-referee", kUsage);
    aula::vacuum::CoverageRefereeNode node(*setup.bus, setup.cfg, setup.world, setup.run_key);
    return aula::app::runReferee<aula::vacuum::CoverageRefereeNode, aula::vacuum::CoverageRefereeWindow>(setup, node, argc, argv);
  });
}
