#include "aula/config/config.hpp"

#include <aula/config/paths.hpp>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace aula::config {
namespace {

std::string trim(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  const auto end = s.find_last_not_of(" \t\r\n");
  return s.substr(begin, end - begin + 1);
}

bool validKey(const std::string& key) {
  if (key.empty() || key.front() == '.' || key.back() == '.') return false;
  if (key.find("..") != std::string::npos) return false;
  for (char c : key) {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
    if (!ok) return false;
  }
  return true;
}

bool parseDouble(const std::string& text, double& out) {
  const std::string t = trim(text);
  if (t.empty()) return false;
  errno = 0;
  char* end = nullptr;
  out = std::strtod(t.c_str(), &end);
  return errno == 0 && end == t.c_str() + t.size() && std::isfinite(out);
}

bool parseInt64(const std::string& text, long long& out) {
  const std::string t = trim(text);
  if (t.empty()) return false;
  errno = 0;
  char* end = nullptr;
  out = std::strtoll(t.c_str(), &end, 10);
  return errno == 0 && end == t.c_str() + t.size();
}

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) items.push_back(trim(item));
  if (!text.empty() && text.back() == ',') items.push_back("");
  return items;
}

}  // namespace

Config Config::fromFile(const std::string& path) {
  return fromString(readSmallFile(path, kMaxConfigBytes, "config file"), path);
}

Config Config::fromString(const std::string& text, const std::string& origin) {
  Config config;
  config.source_ = origin;
  std::stringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string where = origin + ":" + std::to_string(number);
    const std::string content = trim(line);
    if (content.empty() || content.front() == '#') continue;
    const auto eq = content.find('=');
    if (eq == std::string::npos) {
      throw ConfigError(where + ": expected 'Key = value', got '" + content + "'");
    }
    const std::string key = trim(content.substr(0, eq));
    std::string value = trim(content.substr(eq + 1));
    if (!validKey(key)) {
      throw ConfigError(where + ": invalid key '" + key +
                        "' (letters, digits, '_', '-' and dots between names)");
    }
    // A trailing comment after the value: "Key = 3   # metres".
    const auto hash = value.find(" #");
    if (hash != std::string::npos) value = trim(value.substr(0, hash));
    const auto previous = config.entries_.find(key);
    if (previous != config.entries_.end()) {
      throw ConfigError(where + ": key '" + key + "' is already set at " +
                        previous->second.origin);
    }
    config.entries_[key] = Entry{value, where};
  }
  return config;
}

void Config::set(const std::string& key, const std::string& value, const std::string& origin) {
  if (!validKey(key)) throw ConfigError(origin + ": invalid key '" + key + "'");
  entries_[key] = Entry{value, origin};
}

void Config::merge(const Config& other) {
  for (const auto& [key, entry] : other.entries_) entries_[key] = entry;
}

std::vector<std::string> Config::keys() const {
  std::vector<std::string> out;
  for (const auto& [key, entry] : entries_) out.push_back(key);
  return out;
}

std::string Config::origin(const std::string& key) const {
  const auto it = entries_.find(key);
  return it == entries_.end() ? std::string() : it->second.origin;
}

const Config::Entry& Config::require(const std::string& key) const {
  const auto it = entries_.find(key);
  if (it == entries_.end()) {
    throw ConfigError((source_.empty() ? std::string("config") : source_) + ": missing key '" +
                      key + "'");
  }
  return it->second;
}

void Config::fail(const std::string& key, const std::string& what) const {
  const Entry& e = require(key);
  throw ConfigError(e.origin + ": " + key + " = '" + e.value + "': " + what);
}

std::string Config::getString(const std::string& key) const { return require(key).value; }

long long Config::getInt64(const std::string& key) const {
  long long v = 0;
  if (!parseInt64(require(key).value, v)) fail(key, "not an integer");
  return v;
}

int Config::getInt(const std::string& key) const {
  const long long v = getInt64(key);
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
    fail(key, "integer out of range");
  }
  return static_cast<int>(v);
}

double Config::getDouble(const std::string& key) const {
  double v = 0;
  if (!parseDouble(require(key).value, v)) fail(key, "not a finite number");
  return v;
}

bool Config::getBool(const std::string& key) const {
  std::string v = require(key).value;
  for (auto& c : v) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (v == "true" || v == "yes" || v == "on" || v == "1") return true;
  if (v == "false" || v == "no" || v == "off" || v == "0") return false;
  fail(key, "not a boolean (true/false, yes/no, on/off, 1/0)");
}

std::vector<double> Config::getDoubleList(const std::string& key) const {
  std::vector<double> out;
  for (const auto& item : splitList(require(key).value)) {
    double v = 0;
    if (!parseDouble(item, v)) fail(key, "item '" + item + "' is not a finite number");
    out.push_back(v);
  }
  return out;
}

std::vector<std::string> Config::getStringList(const std::string& key) const {
  const std::string& value = require(key).value;
  if (trim(value).empty()) return {};
  return splitList(value);
}

std::string Config::getString(const std::string& key, const std::string& fallback) const {
  return has(key) ? getString(key) : fallback;
}
int Config::getInt(const std::string& key, int fallback) const {
  return has(key) ? getInt(key) : fallback;
}
long long Config::getInt64(const std::string& key, long long fallback) const {
  return has(key) ? getInt64(key) : fallback;
}
double Config::getDouble(const std::string& key, double fallback) const {
  return has(key) ? getDouble(key) : fallback;
}
bool Config::getBool(const std::string& key, bool fallback) const {
  return has(key) ? getBool(key) : fallback;
}
std::vector<double> Config::getDoubleList(const std::string& key,
                                          const std::vector<double>& fallback) const {
  return has(key) ? getDoubleList(key) : fallback;
}

CommandLine CommandLine::parse(int argc, const char* const* argv,
                               const std::vector<std::string>& takes_value) {
  CommandLine cl;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.size() < 3 || arg.rfind("--", 0) != 0) {
      if (!arg.empty() && arg[0] == '-' && arg != "-") {
        throw ConfigError("command line: unknown argument '" + arg + "' (options are --name)");
      }
      cl.positional.push_back(arg);
      continue;
    }
    const std::string body = arg.substr(2);
    const auto eq = body.find('=');
    const std::string name = body.substr(0, eq);
    if (name.empty()) throw ConfigError("command line: malformed argument '" + arg + "'");
    const bool has_value = eq != std::string::npos;
    std::string value = has_value ? body.substr(eq + 1) : "";
    if (name.find('.') != std::string::npos) {
      if (!validKey(name)) throw ConfigError("command line: invalid cfg key in '" + arg + "'");
      if (!has_value) throw ConfigError("command line: cfg override '" + arg + "' needs =value");
      cl.overrides.emplace_back(name, value);
      continue;
    }
    if (!has_value) {
      bool wants = false;
      for (const auto& t : takes_value) wants = wants || t == name;
      if (wants) {
        if (i + 1 >= argc) throw ConfigError("command line: --" + name + " needs a value");
        value = argv[++i];
      }
    }
    cl.options[name] = value;
  }
  return cl;
}

std::string CommandLine::option(const std::string& name, const std::string& fallback) const {
  const auto it = options.find(name);
  return it == options.end() ? fallback : it->second;
}

double CommandLine::optionDouble(const std::string& name, double fallback) const {
  const auto it = options.find(name);
  if (it == options.end()) return fallback;
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(it->second, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != it->second.size() || !std::isfinite(value)) {
    throw ConfigError("--" + name + "=" + it->second + " is not a number");
  }
  return value;
}

void CommandLine::requireKnown(const std::vector<std::string>& known) const {
  std::string unknown;
  for (const auto& [name, value] : options) {
    bool ok = false;
    for (const auto& k : known) ok = ok || k == name;
    if (!ok) unknown += (unknown.empty() ? "--" : ", --") + name;
  }
  if (!unknown.empty()) throw ConfigError("command line: unknown option(s) " + unknown);
}

void CommandLine::applyOverrides(Config& config) const {
  for (const auto& [key, value] : overrides) config.set(key, value, "command line --" + key);
}

}  // namespace aula::config
