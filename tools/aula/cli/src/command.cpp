#include "aula/cli/command.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace aula::cli {
using config::ConfigError;
using config::SettingSpec;
using config::SettingType;

Arguments::Arguments(std::vector<std::string> positional, config::Config options, std::set<std::string> given,
                     std::vector<std::pair<std::string, std::string>> settings)
    : positional_(std::move(positional)),
      options_(std::move(options)),
      given_(std::move(given)),
      settings_(std::move(settings)) {}

std::string Arguments::spelled(const std::string& option) const { return "--" + option + "=" + text(option); }

Command::Command(std::string name_, std::string summary_)
    : name(std::move(name_)), summary(std::move(summary_)), options("aula " + name) {}

namespace {

// "--world=FILE", "--engine=local|slurm", "--jobs=N": what a value is, said in the option itself.
// Text options declare their placeholder (valueOption: FILE, DIR, LIST); one that does not is a
// mistake in the declaration, refused here so that no generic "--out=VALUE" reaches a user.
std::string optionSyntax(const SettingSpec& spec, const std::string& command) {
  if (spec.type == SettingType::Bool) return "--" + spec.key;
  std::string placeholder;
  if (spec.type == SettingType::Choice) {
    for (const std::string& choice : spec.choices) placeholder += (placeholder.empty() ? "" : "|") + choice;
  } else if (spec.type == SettingType::Int) {
    placeholder = "N";
  } else if (spec.type == SettingType::Double) {
    placeholder = spec.unit == "s" ? "SECONDS" : "X";
  } else if (spec.unit.empty()) {
    throw std::logic_error("aula " + command + ": option --" + spec.key + " declares no placeholder (cli::valueOption)");
  } else {
    placeholder = spec.unit;
  }
  return "--" + spec.key + "=" + placeholder;
}

std::string wantedCount(const std::vector<Positional>& positionals) {
  std::string out;
  for (const Positional& p : positionals) out += " " + (p.optional ? "[" + p.name + "]" : p.name) + (p.many ? "..." : "");
  return out;
}

// "local or slurm": a choice's words as a sentence says them.
std::string choicesText(const std::vector<std::string>& choices) {
  std::string out;
  for (size_t i = 0; i < choices.size(); ++i) out += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  return out;
}

// Checks a given value against its declaration: "aula grade: --engine=cloud: local or slurm".
void checkValue(const config::SettingsTable& options, const SettingSpec& spec, const std::string& command,
                const std::string& value) {
  try {
    options.check(spec, spec.key, value, "aula " + command);
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    const std::string reason = spec.type == SettingType::Choice ? choicesText(spec.choices) : what.substr(what.rfind("': ") + 3);
    throw ConfigError("aula " + command + ": --" + spec.key + "=" + value + ": " + reason);
  }
}

}  // namespace

std::string Command::usageLine() const {
  return "usage: aula " + name + wantedCount(positionals) + (options.specs().empty() ? "" : " [options]") +
         (takes_settings ? " [--Section.Key=value ...]" : "");
}

std::string Command::help() const {
  std::ostringstream out;
  out << usageLine() << "\n" << summary << "\n";
  for (const Positional& p : positionals) out << "  " << p.name << "  " << p.help << "\n";
  if (!options.specs().empty()) out << "options:\n";
  for (const SettingSpec& spec : options.specs()) {
    out << "  " << optionSyntax(spec, name) << "\n      " << spec.help;
    const bool numeric = spec.type == SettingType::Int || spec.type == SettingType::Double;
    if (!spec.default_value.empty() && spec.type != SettingType::Bool) out << " (default " << spec.default_value << ")";
    const std::string range = spec.rangeText();
    if (!range.empty() && numeric) out << "; " << range;
    out << "\n";
  }
  out << "  --help\n      this help\n";
  if (takes_settings) {
    out << "  --Section.Key=value\n      a declared setting of the run's processes (`aula config EXERCISE` lists them)\n";
  }
  if (!details.empty()) out << details;
  return out.str();
}

// The words are split the one way every Aula program splits them (config::CommandLine: --name,
// --name=value, --name VALUE for the options that take one, --Section.Key=value); then each
// option is checked against this command's declaration.
Arguments Command::parse(const std::vector<std::string>& args) const {
  std::vector<std::string> takes_value;
  for (const SettingSpec& spec : options.specs()) {
    if (spec.type != SettingType::Bool) takes_value.push_back(spec.key);
  }
  std::vector<const char*> argv = {"aula"};
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  config::CommandLine words;
  try {
    words = config::CommandLine::parse(static_cast<int>(argv.size()), argv.data(), takes_value);
  } catch (const ConfigError& e) {
    throw ConfigError("aula " + name + ": " + e.what());
  }
  if (!takes_settings && !words.overrides.empty()) {
    throw ConfigError("aula " + name + ": takes no settings ('--" + words.overrides.front().first + "')");
  }
  config::Config given_values;
  std::set<std::string> given;
  for (const auto& [option, text] : words.options) {
    const SettingSpec* spec = options.find(option);
    if (spec == nullptr) {
      const std::string nearest = options.suggest(option);
      throw ConfigError("aula " + name + ": unknown option '--" + option + "'" +
                        (nearest.empty() ? "" : " (did you mean '--" + nearest + "'?)") + "; `aula " + name +
                        " --help` lists its options");
    }
    const std::string value = spec->type == SettingType::Bool && text.empty() ? "true" : text;
    checkValue(options, *spec, name, value);
    given_values.set(option, value, "aula " + name + " --" + option);
    given.insert(option);
  }
  checkCount(words.positional);
  return Arguments(std::move(words.positional), options.resolve(given_values), std::move(given), std::move(words.overrides));
}

void Command::checkCount(const std::vector<std::string>& positional) const {
  size_t required = 0;
  for (const Positional& p : positionals) required += p.optional ? 0 : 1;
  const bool many = !positionals.empty() && positionals.back().many;
  if (positional.size() < required || (!many && positional.size() > positionals.size())) {
    throw ConfigError("aula " + name + ": expected" + wantedCount(positionals) + ", got " +
                      (positional.empty() ? "nothing" : "'" + positional.front() + (positional.size() > 1 ? "' ..." : "'")) +
                      "\n" + usageLine());
  }
}

config::SettingSpec valueOption(const std::string& name, const std::string& placeholder, const std::string& help,
                                const std::string& default_value) {
  config::SettingSpec spec;
  spec.key = name;
  spec.unit = placeholder;
  spec.default_value = default_value;
  spec.help = help;
  return spec;
}

config::SettingSpec numberOption(const std::string& name, SettingType type, const std::string& unit, double min,
                                 double max, const std::string& help, bool min_exclusive) {
  config::SettingSpec spec;
  spec.key = name;
  spec.type = type;
  spec.unit = unit;
  spec.min = min;
  spec.max = max;
  spec.min_exclusive = min_exclusive;
  spec.help = help;
  return spec;
}

const Command* CommandTable::find(const std::string& name) const {
  for (const Command& command : commands_) {
    if (command.name == name) return &command;
  }
  return nullptr;
}

std::string CommandTable::help(const std::string& extra) const {
  std::ostringstream out;
  out << "usage: aula COMMAND [ARGUMENTS] [options]   (aula COMMAND --help: that command's options)\ncommands:\n";
  size_t width = 0;
  for (const Command& c : commands_) width = std::max(width, c.name.size());
  for (const Command& c : commands_) out << "  " << c.name << std::string(width + 2 - c.name.size(), ' ') << c.summary << "\n";
  out << "usage of each:\n";
  for (const Command& c : commands_) out << "  " << c.usageLine() << "\n";
  out << extra;
  return out.str();
}

int CommandTable::dispatch(int argc, const char* const* argv, const std::string& version, const std::string& extra_help) const {
  const std::vector<std::string> args(argv + std::min(argc, 2), argv + argc);
  const std::string first = argc > 1 ? argv[1] : "";
  if (first == "help" && argc > 2) {  // `aula help run`: as `aula run --help`
    if (const Command* asked = find(argv[2])) {
      std::cout << asked->help();
      return 0;
    }
    std::cerr << "aula help: unknown command '" << argv[2] << "'\n" << help(extra_help);
    return 2;
  }
  if (first == "--help" || first == "help") {
    std::cout << help(extra_help);
    return 0;
  }
  if (first == "--version") {
    std::cout << "aula " << version << "\n";
    return 0;
  }
  const Command* command = find(first);
  if (command == nullptr) {
    std::string nearest;
    size_t best = 3;
    for (const Command& c : commands_) {
      if (config::editDistance(first, c.name) < best) best = config::editDistance(first, c.name), nearest = c.name;
    }
    std::cerr << (first.empty() ? "aula: name a command\n"
                                : "aula: unknown command '" + first + "'" + (nearest.empty() ? "" : " (did you mean '" + nearest + "'?)") + "\n")
              << help(extra_help);
    return 2;
  }
  if (std::find(args.begin(), args.end(), "--help") != args.end()) {
    std::cout << command->help();
    return 0;
  }
  return command->run(command->parse(args));
}

}  // namespace aula::cli
