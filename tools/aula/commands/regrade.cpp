// aula regrade FILE.lcmlog: a recorded run graded again from its log alone (no simulator). It
// trusts only a signed log whose events are as they were signed (log_signature.hpp), unless told
// --unsigned.
#include "commands.hpp"
#include "run_settings.hpp"

#include <aula/lcm/log_replay.hpp>
#include <aula/supervision/log_signature.hpp>
#include <aula/supervision/run_recorder.hpp>

#include <filesystem>
#include <iostream>

namespace aula::commands {
namespace {

// Why the log cannot be trusted, or "" when it can; says on the terminal what it found.
std::string distrust(const std::string& log, const std::string& key_path) {
  lcmbus::readRunRecord(log);  // a recorded run at all (else a usage error naming what it is)
  if (!supervision::isSigned(log)) {
    // A graded run's log is signed last: with its key beside it, a log that reads to no signature
    // was cut short or damaged after it was recorded (LCM's reader stops at the first bad event).
    if (std::filesystem::exists(key_path)) {
      return "it was cut or damaged after it was recorded: its key (" + key_path +
             ") says it was signed, but its signature, the log's last event, cannot be read";
    }
    return "it is not signed (recorded without a graded run's key)";
  }
  if (!std::filesystem::exists(key_path)) return "it is signed, but its key (" + key_path + ") is not there to check it";
  const supervision::LogCheck check = supervision::checkLog(log, supervision::readKeyFile(key_path));
  if (!check.intact) return "it was altered after it was signed: " + check.altered + " differ from what was signed";
  std::cout << log << ": signed and unaltered (" << check.events << " events)\n";
  return "";
}

int regradeLog(const cli::Arguments& args) {
  const std::string log = args.positional(0);
  const std::string key = args.given("key") ? args.text("key") : log + ".key";
  const std::string why = distrust(log, key);
  if (!why.empty() && !args.flag("unsigned")) {
    throw config::ConfigError(log + ": not regraded: " + why + " (--unsigned grades it anyway)");
  }
  if (!why.empty()) std::cerr << "aula: " << log << ": " << why << "; graded anyway (--unsigned)\n";
  return supervision::regrade(log, args.text("report"), binDir(), args.text("trace"));
}

}  // namespace

cli::Command regrade() {
  cli::Command c("regrade", "grade a run recorded with `aula run --record` again, from the log alone (no simulator)");
  c.positionals = {{"FILE.lcmlog", "the recorded run (signed in a graded run; its key beside it, FILE.lcmlog.key)"}};
  c.options.add(cli::valueOption("report", "FILE.json", "the referee's JSON report"))
      .add(cli::valueOption("trace", "FILE.json", "the referee's trace of the run (the same bytes as the live run's)"))
      .add(cli::valueOption("key", "FILE", "the log's key (default: FILE.lcmlog.key beside it)"))
      .flag("unsigned", false, "grade a log that is not signed, or whose signature does not hold");
  c.run = regradeLog;
  return c;
}

}  // namespace aula::commands
