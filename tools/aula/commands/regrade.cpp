// aula regrade FILE.lcmlog: a recorded run graded again from its log alone (no simulator).
#include "commands.hpp"
#include "run_settings.hpp"

#include <aula/supervision/run_recorder.hpp>

namespace aula::commands {

cli::Command regrade() {
  cli::Command c("regrade", "grade a run recorded with `aula run --record` again, from the log alone (no simulator)");
  c.positionals = {{"FILE.lcmlog", "the recorded run"}};
  c.options.add(cli::valueOption("report", "FILE.json", "the referee's JSON report"))
      .add(cli::valueOption("trace", "FILE.json", "the referee's trace of the run (the same bytes as the live run's)"));
  c.run = [](const cli::Arguments& args) {
    return supervision::regrade(args.positional(0), args.text("report"), binDir(), args.text("trace"));
  };
  return c;
}

}  // namespace aula::commands
