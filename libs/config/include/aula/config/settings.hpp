#pragma once
// Declared settings: each process declares every key it reads once, in one SettingsTable (name,
// type, default, unit, allowed range, one line of help). The table is the only place a default
// lives. resolve() checks a Config (a .cfg file plus --Key=value overrides) against it: an unknown
// key, a value of the wrong type or out of range is a ConfigError naming the file and line (or
// the command-line argument), with a "did you mean ...?" for misspelt keys. What comes out has
// every declared key set, so a process reads it with the Config's required getters.

#include <aula/config/config.hpp>

#include <limits>
#include <string>
#include <vector>

namespace aula::config {

enum class SettingType { String, Int, Double, Bool, DoubleList, Choice };

// A named set of values for some of a table's settings: "original" gives a referee's rubric the
// thesis's scales. A preset setting (a Choice of its presets' names) selects one; the selected
// preset's values replace the declared defaults of the keys it governs, and a value given in a
// .cfg or on the command line still wins over both.
struct Preset {
  std::string name;  // "default", "original"
  std::string help;  // one line: what the preset is for
  std::vector<std::pair<std::string, std::string>> values;  // key -> value, as written in a .cfg
};

struct SettingSpec {
  std::string key;                 // "Vacuum.MaxV"; a trailing ".*" declares a family of keys
  SettingType type = SettingType::String;
  std::string default_value;       // as written in a .cfg; "" with required = false: empty
  std::string unit;                // "m/s", "s", "%"; "" when it has none
  double min = -std::numeric_limits<double>::infinity();  // numbers, and each item of a list
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;      // (min, max] instead of [min, max]
  size_t list_size = 0;            // DoubleList: exact number of items (0: any)
  std::vector<std::string> choices;  // Choice: the allowed words
  bool or_plugin = false;          // Choice: a plugin file (PATH.so) or a Python file (PATH.py) is allowed too
  bool free_point = false;         // DoubleList of 2: x, y that must be free floor on the exercise's map
  // A preset setting: `choices` are the presets' names; the keys it governs (declared before it,
  // in the same table) take the selected preset's value, or their own default when it has none.
  std::vector<Preset> presets;
  std::vector<std::string> governs;
  std::string help;

  const Preset* preset(const std::string& name) const;  // nullptr when not a preset of this setting

  std::string typeName() const;
  std::string rangeText() const;   // "[0.005, 1] s", "one of: student, reference", ""
};

class SettingsTable {
 public:
  explicit SettingsTable(std::string owner) : owner_(std::move(owner)) {}

  // Declaration helpers: the key, its default, unit, range and help.
  SettingsTable& text(const std::string& key, const std::string& def, const std::string& help);
  SettingsTable& choice(const std::string& key, const std::string& def, std::vector<std::string> choices,
                        const std::string& help);
  // A Choice of built-in algorithms, or the path of an algorithm plugin (PATH.so) or of a
  // student's Python file (PATH.py).
  SettingsTable& algorithm(const std::string& key, const std::string& def, std::vector<std::string> builtins,
                           const std::string& help);
  SettingsTable& real(const std::string& key, double def, const std::string& unit, double min, double max,
                      const std::string& help, bool min_exclusive = false);
  SettingsTable& integer(const std::string& key, long long def, const std::string& unit, long long min,
                         long long max, const std::string& help);
  SettingsTable& flag(const std::string& key, bool def, const std::string& help);
  SettingsTable& reals(const std::string& key, const std::string& def, size_t count, const std::string& unit,
                       double min, double max, const std::string& help);
  // A preset setting over `governs` (keys already declared here); `def` names one of `presets`.
  // Each preset's values are checked against their keys' declarations now (std::logic_error).
  SettingsTable& presets(const std::string& key, const std::string& def, std::vector<std::string> governs,
                         std::vector<Preset> presets, const std::string& help);
  SettingsTable& add(SettingSpec spec);

  const std::string& owner() const { return owner_; }
  const std::vector<SettingSpec>& specs() const { return specs_; }
  const SettingSpec* find(const std::string& key) const;
  bool declares(const std::string& key) const { return find(key) != nullptr; }
  // The declared key nearest to `key` by edit distance, or "" when none is close.
  std::string suggest(const std::string& key) const;
  // The preset setting that governs `key`, or nullptr.
  const SettingSpec* presetOf(const std::string& key) const;
  // The value preset `name` gives the governed `key`: its own, or the key's declared default.
  std::string presetValue(const std::string& key, const std::string& name) const;
  // Whether `value` is what preset `name` gives `key`, compared as the key's type ("30" = "30.0").
  bool isPresetValue(const std::string& key, const std::string& name, const std::string& value) const;

  // Checks `cfg` and returns the effective settings: every declared key, defaults filled in with
  // origin "default", or from the selected preset with origin "preset NAME (KEY)". Keys that one of `siblings` declares (the other processes that read the
  // same .cfg) are dropped; any other unknown key is a ConfigError.
  Config resolve(const Config& cfg, const std::vector<const SettingsTable*>& siblings = {}) const;
  // Checks one value against its declaration; throws ConfigError "<origin>: KEY = 'v': what".
  void check(const SettingSpec& spec, const std::string& key, const std::string& value,
             const std::string& origin) const;

  // The `--help` listing: one block per key (key, type, default, range, help).
  std::string help() const;
  // `aula config`: one line per key with its effective value and where it came from.
  std::string describe(const Config& effective) const;
  // The same as a Markdown table (setting, value, range, what it means) for the keys starting
  // with `prefix`: the exercise pages' grading rules come from here, never typed by hand.
  std::string markdown(const Config& effective, const std::string& prefix) const;

 private:
  std::string owner_;
  std::vector<SettingSpec> specs_;
};

// Levenshtein distance, for "did you mean".
size_t editDistance(const std::string& a, const std::string& b);

}  // namespace aula::config
