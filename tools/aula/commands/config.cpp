// aula config EXERCISE: every process's effective settings and where each came from.
#include "commands.hpp"
#include "run_settings.hpp"

#include <aula/config/paths.hpp>
#include <aula/settings/tables.hpp>

#include <iostream>

namespace aula::commands {
namespace {

int printConfig(const cli::Arguments& args) {
  const settings::Exercise& ex = exerciseArgument(args.positional(0), "config");
  config::Config overrides = settingsOf(args);
  if (args.given("world")) overrides.set(ex.section + ".World", args.text("world"), "command line --world");
  const std::string cfg = args.given("config") ? args.text("config") : config::dataPath(ex.config_file);
  const RunSettings run = resolveSettings(ex, cfg, overrides);
  if (args.flag("markdown")) {
    // The grading rules of docs/exercises/<exercise>.md (scripts/update-exercise-docs.sh).
    if (ex.referee_settings == nullptr) throw config::ConfigError("--markdown: '" + ex.name + "' has no referee");
    std::cout << run.effective.back().first->markdown(run.referee(), ex.section + ".Referee.");
    return 0;
  }
  std::cout << "world: " << run.world << "\nconfig: " << run.cfg_path << "\n";
  for (const auto& [table, cfg_of_process] : run.effective) {
    std::cout << "\n" << table->owner() << ":\n" << table->describe(cfg_of_process);
  }
  return 0;
}

}  // namespace

cli::Command config() {
  cli::Command c("config", "print the effective settings of each process of an exercise and where each came from");
  c.positionals = {{"EXERCISE", settings::exerciseNames(true)}};
  c.takes_settings = true;
  c.options.add(cli::valueOption("world", "FILE", "the world the run would use"))
      .add(cli::valueOption("config", "FILE.cfg", "the exercise's .cfg file (default: its own in the data folder)"))
      .flag("markdown", false, "print the referee's grading rules as a Markdown table (the exercise pages)");
  c.run = printConfig;
  return c;
}

}  // namespace aula::commands
