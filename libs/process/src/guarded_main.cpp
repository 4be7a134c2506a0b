#include "aula/process/guarded_main.hpp"

#include <aula/config/config.hpp>
#include <aula/process/exit_codes.hpp>
#include <aula/world/world_spec.hpp>

#include <filesystem>
#include <iostream>

namespace aula::process {

int guardedMain(const std::string& program, const std::function<int()>& body, const std::string& config_error_hint) {
  try {
    return body();
  } catch (const HelpShown&) {
    return kExitFinished;
  } catch (const config::ConfigError& e) {
    // "aula run: ..." already names the program: said once ("aula: aula run: ..." was not).
    const std::string what = e.what();
    std::cerr << (what.rfind(program + " ", 0) == 0 ? "" : program + ": ") << what << "\n" << config_error_hint;
    return kExitUsage;
  } catch (const world::WorldError& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return kExitUsage;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the user gave that cannot be used (missing, not a folder, no permission): their
    // input, said as the path and the system's reason, not the library's raw text.
    std::cerr << program << ": " << e.path1().string() << (e.path2().empty() ? "" : " -> " + e.path2().string()) << ": "
              << e.code().message() << "\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return kExitFailed;
  }
}

}  // namespace aula::process
