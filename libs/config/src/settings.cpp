#include "aula/config/settings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <iomanip>
#include <sstream>

namespace aula::config {
namespace {

std::string numberText(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::ostringstream out;
  out << std::setprecision(10) << v;
  return out.str();
}

bool endsWith(const std::string& text, const std::string& tail) {
  return text.size() > tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

bool isFamily(const std::string& key) { return endsWith(key, ".*"); }

bool matches(const SettingSpec& spec, const std::string& key) {
  if (isFamily(spec.key)) {
    const std::string prefix = spec.key.substr(0, spec.key.size() - 1);  // keeps the dot
    return key.size() > prefix.size() && key.compare(0, prefix.size(), prefix) == 0;
  }
  return spec.key == key;
}

}  // namespace

size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string SettingSpec::typeName() const {
  switch (type) {
    case SettingType::String: return "text";
    case SettingType::Int: return "integer";
    case SettingType::Double: return "number";
    case SettingType::Bool: return "boolean";
    case SettingType::DoubleList:
      return list_size == 0 ? "list of numbers" : std::to_string(list_size) + " numbers";
    case SettingType::Choice: return "choice";
  }
  return "text";
}

std::string SettingSpec::rangeText() const {
  if (type == SettingType::Choice) {
    std::string out = "one of: ";
    for (size_t i = 0; i < choices.size(); ++i) out += (i ? ", " : "") + choices[i];
    return or_plugin ? out + ", or a plugin PATH.so, or a Python file PATH.py" : out;
  }
  if (type != SettingType::Int && type != SettingType::Double && type != SettingType::DoubleList) return "";
  if (std::isinf(min) && std::isinf(max)) return unit;
  std::string out = (min_exclusive ? "(" : "[") + numberText(min) + ", " + numberText(max) + "]";
  return unit.empty() ? out : out + " " + unit;
}

const Preset* SettingSpec::preset(const std::string& name) const {
  for (const Preset& p : presets) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

SettingsTable& SettingsTable::add(SettingSpec spec) {
  if (find(spec.key) != nullptr) throw std::logic_error("setting '" + spec.key + "' declared twice in " + owner_);
  // An empty default is no default: a command's option read only when given (aula/cli).
  if (!isFamily(spec.key) && !spec.default_value.empty()) check(spec, spec.key, spec.default_value, "default of " + owner_);
  specs_.push_back(std::move(spec));
  return *this;
}

namespace {

SettingSpec spec(const std::string& key, SettingType type, std::string def, const std::string& unit, double min,
                 double max, const std::string& help) {
  SettingSpec s;
  s.key = key;
  s.type = type;
  s.default_value = std::move(def);
  s.unit = unit;
  s.min = min;
  s.max = max;
  s.help = help;
  return s;
}

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

SettingsTable& SettingsTable::text(const std::string& key, const std::string& def, const std::string& help) {
  return add(spec(key, SettingType::String, def, "", -kInf, kInf, help));
}

SettingsTable& SettingsTable::choice(const std::string& key, const std::string& def, std::vector<std::string> choices,
                                     const std::string& help) {
  SettingSpec s = spec(key, SettingType::Choice, def, "", -kInf, kInf, help);
  s.choices = std::move(choices);
  return add(std::move(s));
}

SettingsTable& SettingsTable::algorithm(const std::string& key, const std::string& def,
                                        std::vector<std::string> builtins, const std::string& help) {
  SettingSpec s = spec(key, SettingType::Choice, def, "", -kInf, kInf, help);
  s.choices = std::move(builtins);
  s.or_plugin = true;
  return add(std::move(s));
}

SettingsTable& SettingsTable::real(const std::string& key, double def, const std::string& unit, double min, double max,
                                   const std::string& help, bool min_exclusive) {
  SettingSpec s = spec(key, SettingType::Double, numberText(def), unit, min, max, help);
  s.min_exclusive = min_exclusive;
  return add(std::move(s));
}

SettingsTable& SettingsTable::integer(const std::string& key, long long def, const std::string& unit, long long min,
                                      long long max, const std::string& help) {
  return add(spec(key, SettingType::Int, std::to_string(def), unit, static_cast<double>(min), static_cast<double>(max),
                  help));
}

SettingsTable& SettingsTable::flag(const std::string& key, bool def, const std::string& help) {
  return add(spec(key, SettingType::Bool, def ? "true" : "false", "", -kInf, kInf, help));
}

SettingsTable& SettingsTable::reals(const std::string& key, const std::string& def, size_t count,
                                    const std::string& unit, double min, double max, const std::string& help) {
  SettingSpec s = spec(key, SettingType::DoubleList, def, unit, min, max, help);
  s.list_size = count;
  return add(std::move(s));
}

SettingsTable& SettingsTable::presets(const std::string& key, const std::string& def, std::vector<std::string> governs,
                                      std::vector<Preset> presets, const std::string& help) {
  SettingSpec s = spec(key, SettingType::Choice, def, "", -kInf, kInf, help);
  for (const std::string& governed : governs) {
    const SettingSpec* target = find(governed);
    if (target == nullptr || isFamily(governed) || target->key != governed) {
      throw std::logic_error(owner_ + ": preset setting " + key + " governs '" + governed + "', which is not declared before it");
    }
    if (presetOf(governed) != nullptr) throw std::logic_error(owner_ + ": '" + governed + "' is governed by two presets");
  }
  for (const Preset& preset : presets) {
    s.choices.push_back(preset.name);
    for (const auto& [governed, value] : preset.values) {
      if (std::find(governs.begin(), governs.end(), governed) == governs.end()) {
        throw std::logic_error(owner_ + ": preset " + key + " = " + preset.name + " sets '" + governed + "', which it does not govern");
      }
      check(*find(governed), governed, value, "preset " + preset.name + " of " + owner_);
    }
  }
  s.governs = std::move(governs);
  s.presets = std::move(presets);
  return add(std::move(s));
}

const SettingSpec* SettingsTable::presetOf(const std::string& key) const {
  for (const auto& spec : specs_) {
    if (std::find(spec.governs.begin(), spec.governs.end(), key) != spec.governs.end()) return &spec;
  }
  return nullptr;
}

std::string SettingsTable::presetValue(const std::string& key, const std::string& name) const {
  const SettingSpec* selector = presetOf(key);
  const Preset* preset = selector != nullptr ? selector->preset(name) : nullptr;
  if (preset == nullptr) throw std::logic_error(owner_ + ": no preset '" + name + "' governs '" + key + "'");
  for (const auto& [governed, value] : preset->values) {
    if (governed == key) return value;
  }
  return find(key)->default_value;
}

bool SettingsTable::isPresetValue(const std::string& key, const std::string& name, const std::string& value) const {
  Config both;
  both.set("preset", presetValue(key, name), "preset");
  both.set("value", value, "value");
  switch (find(key)->type) {
    case SettingType::Int:
    case SettingType::Double: return both.getDouble("preset") == both.getDouble("value");
    case SettingType::DoubleList: return both.getDoubleList("preset") == both.getDoubleList("value");
    case SettingType::Bool: return both.getBool("preset") == both.getBool("value");
    case SettingType::String:
    case SettingType::Choice: break;
  }
  return both.getString("preset") == both.getString("value");
}

const SettingSpec* SettingsTable::find(const std::string& key) const {
  for (const auto& spec : specs_) {
    if (matches(spec, key)) return &spec;
  }
  return nullptr;
}

std::string SettingsTable::suggest(const std::string& key) const {
  std::string best;
  size_t best_distance = std::max<size_t>(3, key.size() / 3) + 1;
  for (const auto& spec : specs_) {
    const size_t d = editDistance(key, spec.key);
    if (d < best_distance) {
      best_distance = d;
      best = spec.key;
    }
  }
  return best;
}

void SettingsTable::check(const SettingSpec& spec, const std::string& key, const std::string& value,
                          const std::string& origin) const {
  // Config's typed getters parse the one way every value is parsed; a scratch Config lends
  // them the origin for their messages.
  Config one;
  one.set(key, value, origin);
  auto fail = [&](const std::string& what) {
    throw ConfigError(origin + ": " + key + " = '" + value + "': " + what);
  };
  auto inRange = [&](double v) {
    const bool low_ok = spec.min_exclusive ? v > spec.min : v >= spec.min;
    if (!low_ok || v > spec.max) fail("out of range " + spec.rangeText());
  };
  switch (spec.type) {
    case SettingType::String:
      break;
    case SettingType::Choice:
      // A plugin's file is checked by the component that loads it (missing, wrong exercise...).
      if (spec.or_plugin && (value.find('/') != std::string::npos || endsWith(value, ".so") || endsWith(value, ".py"))) {
        break;
      }
      if (std::find(spec.choices.begin(), spec.choices.end(), value) == spec.choices.end()) {
        fail("expected " + spec.rangeText());
      }
      break;
    case SettingType::Bool:
      one.getBool(key);
      break;
    case SettingType::Int:
      inRange(static_cast<double>(one.getInt64(key)));
      break;
    case SettingType::Double:
      inRange(one.getDouble(key));
      break;
    case SettingType::DoubleList: {
      const auto items = one.getDoubleList(key);
      if (spec.list_size != 0 && items.size() != spec.list_size) {
        fail("expected " + std::to_string(spec.list_size) + " comma-separated numbers" +
             (spec.unit.empty() ? "" : " (" + spec.unit + ")") + ", got " + std::to_string(items.size()));
      }
      for (double v : items) inRange(v);
      break;
    }
  }
}

Config SettingsTable::resolve(const Config& cfg, const std::vector<const SettingsTable*>& siblings) const {
  Config out;
  for (const std::string& key : cfg.keys()) {
    if (const SettingSpec* spec = find(key)) {
      check(*spec, key, cfg.getString(key), cfg.origin(key));
      out.set(key, cfg.getString(key), cfg.origin(key));
      continue;
    }
    const bool theirs = std::any_of(siblings.begin(), siblings.end(),
                                    [&](const SettingsTable* t) { return t->declares(key); });
    if (theirs) continue;
    std::string message = cfg.origin(key) + ": unknown key '" + key + "'";
    std::string suggestion = suggest(key);
    for (const SettingsTable* t : siblings) {
      if (!suggestion.empty()) break;
      suggestion = t->suggest(key);
    }
    if (!suggestion.empty()) message += " (did you mean '" + suggestion + "'?)";
    throw ConfigError(message + "; `" + owner_ + " --help` lists the settings");
  }
  // A preset fills the keys it governs that the .cfg and the command line leave unset.
  for (const auto& selector : specs_) {
    if (selector.presets.empty()) continue;
    const std::string name = out.has(selector.key) ? out.getString(selector.key) : selector.default_value;
    for (const std::string& key : selector.governs) {
      if (!out.has(key)) out.set(key, presetValue(key, name), "preset " + name + " (" + selector.key + ")");
    }
  }
  for (const auto& spec : specs_) {
    if (isFamily(spec.key) || out.has(spec.key)) continue;
    out.set(spec.key, spec.default_value, "default");
  }
  return out;
}

std::string SettingsTable::help() const {
  std::ostringstream out;
  for (const auto& spec : specs_) {
    out << "  " << spec.key << "  (" << spec.typeName();
    if (!isFamily(spec.key)) out << ", default '" << spec.default_value << "'";
    const std::string range = spec.rangeText();
    if (!range.empty()) out << ", " << range;
    if (const SettingSpec* selector = presetOf(spec.key)) out << ", set by " << selector->key;
    out << ")\n      " << spec.help << "\n";
    for (const Preset& preset : spec.presets) {
      out << "      " << preset.name << ": " << preset.help;
      for (size_t i = 0; i < preset.values.size(); ++i) {
        out << (i ? ", " : "; ") << preset.values[i].first << " = " << preset.values[i].second;
      }
      out << "\n";
    }
  }
  return out.str();
}

std::string SettingsTable::describe(const Config& effective) const {
  std::ostringstream out;
  for (const std::string& key : effective.keys()) {
    const SettingSpec* spec = find(key);
    out << "  " << key << " = " << effective.getString(key);
    if (spec != nullptr && !spec->unit.empty()) out << " " << spec->unit;
    out << "    [" << effective.origin(key) << "]\n";
  }
  return out.str();
}

std::string SettingsTable::markdown(const Config& effective, const std::string& prefix) const {
  std::ostringstream out;
  out << "| setting | value | range | what it means |\n|---|---|---|---|\n";
  for (const SettingSpec& spec : specs_) {
    if (spec.key.rfind(prefix, 0) != 0 || !effective.has(spec.key)) continue;
    const std::string unit = spec.unit.empty() ? "" : " " + spec.unit;
    std::string value = effective.getString(spec.key) + unit;
    std::string help = spec.help;
    // What another preset would give instead, where it differs: the page shows every preset's numbers.
    if (const SettingSpec* selector = presetOf(spec.key)) {
      const std::string selected = effective.getString(selector->key);
      for (const Preset& preset : selector->presets) {
        if (preset.name == selected || isPresetValue(spec.key, preset.name, effective.getString(spec.key))) continue;
        value += "; `" + preset.name + "`: " + presetValue(spec.key, preset.name) + unit;
      }
    }
    for (const Preset& preset : spec.presets) help += "; `" + preset.name + "`: " + preset.help;
    for (size_t at = help.find('|'); at != std::string::npos; at = help.find('|', at + 2)) help.replace(at, 1, "\\|");
    out << "| `" << spec.key << "` | " << value << " | " << spec.rangeText() << " | " << help << " |\n";
  }
  return out.str();
}

}  // namespace aula::config
