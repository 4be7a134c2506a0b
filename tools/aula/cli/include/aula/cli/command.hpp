#pragma once
// The `aula` front door, git's `builtin/` way: one file per command (tools/aula/commands/), each
// declaring its command here (name, summary, positional arguments, options) and running on the
// parsed, typed values; one table (commands/table.cpp) maps names to commands.
// Options are declared with the settings machinery every process uses (config::SettingsTable:
// type, default, unit, range, help), keyed by the option's name ("world", "headless"), so one
// parser checks them all: an option a command does not declare is a usage error naming the
// command with a "did you mean", and `aula COMMAND --help` prints the declaration.

#include <aula/config/settings.hpp>

#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace aula::cli {

struct Positional {
  std::string name;  // "EXERCISE", "SUBMISSION"
  std::string help;
  bool many = false;      // the last one may repeat: SUBMISSION...
  bool optional = false;  // the last ones may be left out
};

// What a command was given: its positional arguments, its options as typed values (the declared
// default when not given) and, when it takes them, --Section.Key=value settings for the run.
class Arguments {
 public:
  Arguments(std::vector<std::string> positional, config::Config options, std::set<std::string> given,
            std::vector<std::pair<std::string, std::string>> settings);

  const std::vector<std::string>& positional() const { return positional_; }
  const std::string& positional(size_t i) const { return positional_.at(i); }
  bool given(const std::string& option) const { return given_.count(option) != 0; }
  const std::set<std::string>& givenOptions() const { return given_; }
  std::string text(const std::string& option) const { return options_.getString(option); }
  double real(const std::string& option) const { return options_.getDouble(option); }
  long long integer(const std::string& option) const { return options_.getInt64(option); }
  bool flag(const std::string& option) const { return options_.getBool(option); }
  // "--world=FILE" as given, for messages.
  std::string spelled(const std::string& option) const;
  const std::vector<std::pair<std::string, std::string>>& settings() const { return settings_; }

 private:
  std::vector<std::string> positional_;
  config::Config options_;
  std::set<std::string> given_;
  std::vector<std::pair<std::string, std::string>> settings_;
};

struct Command {
  std::string name;     // "run"
  std::string summary;  // one line for `aula --help`
  std::vector<Positional> positionals;
  config::SettingsTable options;  // keys are option names, without the dashes
  bool takes_settings = false;    // accepts --Section.Key=value (a declared setting of the run's processes)
  std::string details;            // more help after the options (examples), may be empty
  std::function<int(const Arguments&)> run;

  Command(std::string name_, std::string summary_);
  // `aula NAME --help`: usage line, summary, positionals, options from their declaration.
  std::string help() const;
  std::string usageLine() const;
  // Parses `args` (what follows the command's name) against the declaration; throws
  // config::ConfigError (exit 2) naming the command and the nearest declared option.
  Arguments parse(const std::vector<std::string>& args) const;

 private:
  void checkCount(const std::vector<std::string>& positional) const;
};

// Declaration helpers: a text value shown as `--name=PLACEHOLDER` (FILE, DIR, LIST: every text
// option declares one; `help()` refuses one that does not), with a default or none, and a number
// in [min, max] ((min, max] when min_exclusive) with its unit and no default.
config::SettingSpec valueOption(const std::string& name, const std::string& placeholder, const std::string& help,
                                const std::string& default_value = "");
config::SettingSpec numberOption(const std::string& name, config::SettingType type, const std::string& unit, double min,
                                 double max, const std::string& help, bool min_exclusive = false);

// The table: names to commands, in the order `aula --help` lists them.
class CommandTable {
 public:
  void add(Command command) { commands_.push_back(std::move(command)); }
  const Command* find(const std::string& name) const;
  // `aula --help`: every command with its summary, then `extra` (the exercises).
  std::string help(const std::string& extra) const;
  // Runs argv[1]'s command on the rest; `aula`, `aula --help`, `aula --version` and an unknown
  // command are answered here. Throws config::ConfigError for usage errors.
  int dispatch(int argc, const char* const* argv, const std::string& version, const std::string& extra_help) const;

 private:
  std::vector<Command> commands_;
};

}  // namespace aula::cli
