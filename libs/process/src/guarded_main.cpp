#include "aula/process/guarded_main.hpp"

#include <aula/config/config.hpp>
#include <aula/process/exit_codes.hpp>
#include <aula/world/world_spec.hpp>

#include <iostream>

namespace aula::process {

int guardedMain(const std::string& program, const std::function<int()>& body, const std::string& config_error_hint) {
  try {
    return body();
  } catch (const HelpShown&) {
    return kExitFinished;
  } catch (const config::ConfigError& e) {
    std::cerr << program << ": " << e.what() << "\n" << config_error_hint;
    return kExitUsage;
  } catch (const world::WorldError& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return kExitFailed;
  }
}

}  // namespace aula::process
