// aula: Aula's front door. One table of commands (commands/table.cpp), one file per command.
#include "commands/commands.hpp"

#include <aula/process/guarded_main.hpp>
#include <aula/version.hpp>

int main(int argc, char** argv) {
  return aula::process::guardedMain("aula", [&] {
    return aula::commands::table().dispatch(argc, argv, aula::kVersion, aula::commands::moreHelp());
  });
}
