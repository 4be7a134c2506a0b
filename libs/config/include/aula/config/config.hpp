#pragma once
// JdeRobot-style property files: `TeleTaxi.Motors.Channel = TAXI_MOTORS`, `# comments`.
// Every value remembers where it came from (file:line or the command line), so that an error
// names the file, the line, the key and what is wrong.

#include <aula/config/config_error.hpp>

#include <map>
#include <cstdint>
#include <string>
#include <vector>

namespace aula::config {

class Config {
 public:
  Config() = default;

  // A .cfg is a few KB; a file past this (or a device, a folder) is refused at once.
  static constexpr uint64_t kMaxConfigBytes = 4u << 20;
  static Config fromFile(const std::string& path);
  static Config fromString(const std::string& text, const std::string& origin);

  // Sets (or replaces) a key; origin is reported in errors, e.g. "command line".
  void set(const std::string& key, const std::string& value, const std::string& origin);
  // Overlays every key of `other` (later wins): exercise files over simulator defaults, etc.
  void merge(const Config& other);

  bool has(const std::string& key) const { return entries_.count(key) != 0; }
  std::vector<std::string> keys() const;
  // Where a key's value came from: "config/teleTaxi.cfg:12", "command line". Empty if absent.
  std::string origin(const std::string& key) const;

  // Required getters throw ConfigError when the key is missing or malformed.
  std::string getString(const std::string& key) const;
  int getInt(const std::string& key) const;
  long long getInt64(const std::string& key) const;
  double getDouble(const std::string& key) const;
  bool getBool(const std::string& key) const;
  // Comma-separated lists: "120, -40".
  std::vector<double> getDoubleList(const std::string& key) const;
  std::vector<std::string> getStringList(const std::string& key) const;

  // With defaults: missing key -> fallback; present but malformed -> ConfigError.
  std::string getString(const std::string& key, const std::string& fallback) const;
  int getInt(const std::string& key, int fallback) const;
  long long getInt64(const std::string& key, long long fallback) const;
  double getDouble(const std::string& key, double fallback) const;
  bool getBool(const std::string& key, bool fallback) const;
  std::vector<double> getDoubleList(const std::string& key, const std::vector<double>& fallback) const;

 private:
  struct Entry {
    std::string value;
    std::string origin;
  };
  const Entry& require(const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

  std::map<std::string, Entry> entries_;
  std::string source_;  // file path or origin name, for "missing key" errors
};

// A process command line split the Aula way:
//   positional arguments (e.g. the world file),
//   process options `--name` or `--name=value` (no dot in the name: --headless, --seed=3),
//   cfg overrides `--Section.Key=value` (a dot in the name), applied over the .cfg file.
struct CommandLine {
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;              // name -> value ("" for bare flags)
  std::vector<std::pair<std::string, std::string>> overrides;

  // Options listed in `takes_value` may also be given as `--name VALUE`.
  // Throws ConfigError on malformed arguments (e.g. "--=3", "--X.=1").
  static CommandLine parse(int argc, const char* const* argv,
                           const std::vector<std::string>& takes_value = {});

  bool flag(const std::string& name) const { return options.count(name) != 0; }
  std::string option(const std::string& name, const std::string& fallback = "") const;
  // A number option; throws ConfigError ("--name=VALUE is not a number") when it does not parse.
  double optionDouble(const std::string& name, double fallback) const;
  // Rejects options not in `known` with a ConfigError listing them (usage errors, exit 2).
  void requireKnown(const std::vector<std::string>& known) const;
  void applyOverrides(Config& config) const;
};

}  // namespace aula::config
