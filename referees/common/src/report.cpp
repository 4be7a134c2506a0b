#include "aula/referee/report.hpp"

#include <aula/config/paths.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include <unistd.h>

namespace aula::referee {

std::string validUtf8(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    size_t length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    bool valid = length != 0 && i + length <= text.size() && !(length == 2 && c < 0xC2);
    for (size_t k = 1; valid && k < length; ++k) valid = (static_cast<unsigned char>(text[i + k]) >> 6) == 0x2;
    if (valid) {
      out.append(text, i, length);
      i += length;
    } else {
      out += "\xEF\xBF\xBD";
      i += 1;
    }
  }
  return out;
}

std::string jsonString(const std::string& text) {
  const std::string s = validUtf8(text);  // a student's text may hold any byte; a report stays JSON
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string formatNumber(double value) {
  if (!std::isfinite(value)) return "null";  // JSON has no NaN/inf
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", value);
  std::string s = buf;
  // Trim trailing zeros but keep one decimal: 12.500000 -> 12.5, 3.000000 -> 3.0
  while (s.size() > 2 && s.back() == '0' && s[s.size() - 2] != '.') s.pop_back();
  if (s == "-0.0") s = "0.0";
  return s;
}

void Report::put(const std::string& key, std::string json) {
  for (auto& [k, v] : fields_) {
    if (k == key) {
      v = std::move(json);
      return;
    }
  }
  fields_.emplace_back(key, std::move(json));
}

void Report::set(const std::string& key, double value) { put(key, formatNumber(value)); }
void Report::set(const std::string& key, long long value) { put(key, std::to_string(value)); }
void Report::set(const std::string& key, bool value) { put(key, value ? "true" : "false"); }
void Report::set(const std::string& key, const std::string& value) { put(key, jsonString(value)); }
void Report::set(const std::string& key, const std::vector<double>& values) {
  std::string json = "[";
  for (size_t i = 0; i < values.size(); ++i) json += (i ? ", " : "") + formatNumber(values[i]);
  put(key, json + "]");
}

void Report::set(const std::string& key, const std::vector<std::string>& values) {
  std::string json = "[";
  for (size_t i = 0; i < values.size(); ++i) json += (i ? ", " : "") + jsonString(values[i]);
  put(key, json + "]");
}

void Report::set(const std::string& key, const Report& object) { put(key, object.json(2)); }

void Report::set(const std::string& key, const std::map<std::string, long long>& counts) {
  std::string json = "{";
  for (const auto& [name, count] : counts) json += (json.size() > 1 ? ", " : "") + jsonString(name) + ": " + std::to_string(count);
  put(key, json + "}");
}

std::string Report::raw(const std::string& key) const {
  for (const auto& [k, v] : fields_) {
    if (k == key) return v;
  }
  return "";
}

std::string Report::json(int indent) const {
  const std::string margin(indent, ' ');
  std::string out = "{\n";
  for (size_t i = 0; i < fields_.size(); ++i) {
    // A nested object's lines move right with it.
    std::string value = fields_[i].second;
    for (size_t at = value.find('\n'); at != std::string::npos; at = value.find('\n', at + 1)) value.insert(at + 1, margin);
    out += margin + "  " + jsonString(fields_[i].first) + ": " + value;
    out += i + 1 < fields_.size() ? ",\n" : "\n";
  }
  return out + margin + "}";
}

std::string Report::toJson() const { return json(0) + "\n"; }

void Report::writeAtomically(const std::string& path) const { config::writeFileAtomically(path, toJson(), "report"); }

}  // namespace aula::referee
