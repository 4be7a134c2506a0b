// autopark [--config=config/autopark.cfg] [--headless] [--lcm-url=URL] [--screenshot=FILE.png [--screenshot-at=SIM_SECONDS]]
//          [--Autopark.Key=value ...]
// The Autopark academic component: find the free slot and park the car in it.
#include "src/autopark_window.hpp"

#include <aula/app/run_component.hpp>
#include <aula/autopark/autopark_box.hpp>
#include <aula/autopark/autopark_component.hpp>
#include <aula/component/algorithm_box_main.hpp>

namespace {
constexpr const char* kUsage =
    "usage: autopark [--config=config/autopark.cfg] [--headless] [--lcm-url=URL] [--screenshot=FILE.png [--screenshot-at=SIM_SECONDS]]\n"
    "         [--Autopark.Key=value ...]\n"
    "The Autopark academic component: find the free slot and park the car in it.\n";
}  // namespace

int main(int argc, char** argv) {
  if (aula::component::isAlgorithmBox(argc, argv)) return aula::component::runAlgorithmBox<aula::autopark::AutoparkBox>();
  return aula::app::guardedMain("autopark", [&] {
    auto setup = aula::app::ProcessSetup::fromArgs(argc, argv, "autopark", {"screenshot", "screenshot-at"}, kUsage);
    aula::autopark::AutoparkComponent component(*setup.bus, setup.cfg, setup.world, setup.lockstep_key);
    const double shot_at_s = setup.command_line.optionDouble("screenshot-at", 40.0);
    return aula::app::runComponent<aula::autopark::AutoparkWindow>(
        setup, component, argc, argv, [&](aula::autopark::AutoparkWindow& window, const QString& png) {
          window.screenshotAfter(png, static_cast<int64_t>(shot_at_s * 1e6));
          return true;
        });
  });
}
