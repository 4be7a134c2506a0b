// teletaxi [--config=config/teleTaxi.cfg] [--headless] [--lcm-url=URL] [--screenshot=FILE.png]
//          [--TeleTaxi.Key=value ...]
// The TeleTaxi academic component: the city map, your Gradient Path Planning, the taxi.
#include "src/taxi_window.hpp"

#include <aula/app/run_component.hpp>
#include <aula/component/algorithm_box_main.hpp>
#include <aula/teletaxi/taxi_box.hpp>
#include <aula/teletaxi/taxi_component.hpp>

namespace {
constexpr const char* kUsage =
    "usage: teletaxi [--config=config/teleTaxi.cfg] [--headless] [--lcm-url=URL] [--screenshot=FILE.png]\n"
    "         [--TeleTaxi.Key=value ...]\n"
    "The TeleTaxi academic component: the city map, your Gradient Path Planning, the taxi.\n";
}  // namespace

int main(int argc, char** argv) {
  if (aula::component::isAlgorithmBox(argc, argv)) return aula::component::runAlgorithmBox<aula::teletaxi::TaxiBox>();
  return aula::app::guardedMain("teletaxi", [&] {
    auto setup = aula::app::ProcessSetup::fromArgs(argc, argv, "teletaxi", {"screenshot"}, kUsage);
    aula::teletaxi::TaxiComponent component(*setup.bus, setup.cfg, setup.world, setup.lockstep_key);
    return aula::app::runComponent<aula::teletaxi::TaxiWindow>(
        setup, component, argc, argv,
        [](aula::teletaxi::TaxiWindow& window, const QString& png) { return window.screenshotWhenReady(png); });
  });
}
