#include "aula/lcm/bus.hpp"

#include <aula/config/config.hpp>

#include <cstdlib>

namespace aula::lcmbus {

std::string resolveUrl(const config::CommandLine& cl, const config::Config& cfg) {
  const std::string from_option = cl.option("lcm-url");
  if (!from_option.empty()) return from_option;
  // A declared default does not hide LCM's own environment variable.
  if (cfg.has("Aula.LcmUrl") && cfg.origin("Aula.LcmUrl") != "default") return cfg.getString("Aula.LcmUrl");
  if (const char* env = std::getenv("LCM_DEFAULT_URL"); env != nullptr && *env != '\0') return env;
  return kDefaultUrl;
}

std::unique_ptr<lcm::LCM> openBus(const std::string& url) {
  auto bus = std::make_unique<lcm::LCM>(url);
  if (!bus->good()) {
    std::string why = "cannot open the LCM bus '" + url + "'";
    if (url.rfind("udpm://", 0) == 0) {
      why +=
          ": UDP multicast needs a multicast route. On a machine without a default route, run as "
          "root: 'ip link set lo multicast on; ip route add 224.0.0.0/4 dev lo'";
    }
    throw BusError(why);
  }
  return bus;
}

}  // namespace aula::lcmbus
