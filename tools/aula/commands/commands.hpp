#pragma once
// Aula's commands, one file each (git's builtin/, cargo's commands/): each defines its
// declaration (name, summary, positional arguments, options) and what it does on the parsed,
// typed values. table.cpp lists them; main() dispatches through it.

#include <aula/cli/command.hpp>

namespace aula::commands {

cli::Command run();
cli::Command config();
cli::Command checkWorld();
cli::Command newProject();
cli::Command grade();
cli::Command gradeTask();
cli::Command regrade();
cli::Command replay();
cli::Command calibrate();

// Every command, in the order `aula --help` lists them.
cli::CommandTable table();
// What `aula --help` says after the commands: the exercises and where the docs are.
std::string moreHelp();

}  // namespace aula::commands
