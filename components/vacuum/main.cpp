// vacuum-cleaner [--config=config/vacuumCleaner.cfg] [--headless] [--lcm-url=URL] [--screenshot=FILE.png [--screenshot-at=SIM_SECONDS]]
//                [--Vacuum.Key=value ...]
// The vacuum cleaner academic component: clean the house without localization.
#include "src/vacuum_window.hpp"

#include <aula/app/run_component.hpp>
#include <aula/component/algorithm_box_main.hpp>
#include <aula/vacuum/vacuum_box.hpp>
#include <aula/vacuum/vacuum_component.hpp>

namespace {
constexpr const char* kUsage =
    "usage: vacuum-cleaner [--config=config/vacuumCleaner.cfg] [--headless] [--lcm-url=URL] [--screenshot=FILE.png [--screenshot-at=SIM_SECONDS]]\n"
    "               [--Vacuum.Key=value ...]\n"
    "The vacuum cleaner academic component: clean the house without localization.\n";
}  // namespace

int main(int argc, char** argv) {
  if (aula::component::isAlgorithmBox(argc, argv)) return aula::component::runAlgorithmBox<aula::vacuum::VacuumBox>();
  return aula::app::guardedMain("vacuum-cleaner", [&] {
    auto setup = aula::app::ProcessSetup::fromArgs(argc, argv, "vacuum-cleaner", {"screenshot", "screenshot-at"}, kUsage);
    aula::vacuum::VacuumComponent component(*setup.bus, setup.cfg, setup.world, setup.lockstep_key);
    const double shot_at_s = setup.command_line.optionDouble("screenshot-at", 60.0);
    return aula::app::runComponent<aula::vacuum::VacuumWindow>(
        setup, component, argc, argv, [&](aula::vacuum::VacuumWindow& window, const QString& png) {
          window.screenshotAfter(png, static_cast<int64_t>(shot_at_s * 1e6));
          return true;
        });
  });
}
