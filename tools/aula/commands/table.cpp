// The command table: `aula NAME` runs the command of that name. A new command is one file in
// this folder (its declaration and what it does), one line in commands.hpp and one here.
#include "commands.hpp"

#include <aula/config/paths.hpp>
#include <aula/settings/tables.hpp>

namespace aula::commands {

cli::CommandTable table() {
  cli::CommandTable commands;
  commands.add(run());
  commands.add(config());
  commands.add(checkWorld());
  commands.add(newProject());
  commands.add(grade());
  commands.add(gradeTask());
  commands.add(calibrate());
  commands.add(regrade());
  commands.add(replay());
  return commands;
}

std::string moreHelp() {
  std::string out = "exercises:\n";
  for (const auto& ex : settings::exercises()) out += "  " + ex.name + "  " + ex.summary + "\n";
  out += "docs: " + config::docDir() + " (grading.md, worlds.md, exercises/)\n";
  return out;
}

}  // namespace aula::commands
