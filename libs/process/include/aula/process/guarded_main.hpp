#pragma once
// The one process skeleton: every Aula program runs its main() body through guardedMain, so all
// of them answer an error with the same exit code and a "program: message" line. Qt-free, so
// the simulator and the tools use it as well as the components and referees.

#include <functional>
#include <stdexcept>
#include <string>

namespace aula::process {

// `--help` was asked for and printed: the process ends with exit code 0.
class HelpShown : public std::runtime_error {
 public:
  HelpShown() : std::runtime_error("help shown") {}
};

// Runs `body` and maps Aula's errors to exit codes (exit_codes.hpp) with a message prefixed by
// `program`: HelpShown -> 0; config::ConfigError and world::WorldError -> kExitUsage (2); any
// other std::exception -> kExitFailed (1).
// `config_error_hint`, if not empty, is printed after a ConfigError's message (a tool's usage).
int guardedMain(const std::string& program, const std::function<int()>& body,
                const std::string& config_error_hint = "");

}  // namespace aula::process
