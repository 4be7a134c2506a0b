#pragma once
// A referee's report: an ordered JSON object written atomically (temp file + rename), so a
// reader never sees half a report. Numbers are printed with a fixed format so the same run
// gives byte-identical files.

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace aula::referee {

class Report {
 public:
  void set(const std::string& key, double value);
  void set(const std::string& key, long long value);
  void set(const std::string& key, int value) { set(key, static_cast<long long>(value)); }
  void set(const std::string& key, bool value);
  void set(const std::string& key, const std::string& value);
  void set(const std::string& key, const char* value) { set(key, std::string(value)); }
  void set(const std::string& key, const std::vector<double>& values);
  void set(const std::string& key, const std::vector<std::string>& values);
  void set(const std::string& key, const Report& object);  // a nested object
  // An object of counts by name, in the map's (sorted) order: {"ROOMBA_POSE": 1532}.
  void set(const std::string& key, const std::map<std::string, long long>& counts);
  // JSON the caller has encoded already (a compact array of a trace), kept as it is.
  void setJson(const std::string& key, std::string json) { put(key, std::move(json)); }

  std::string toJson() const;
  // Throws std::runtime_error naming the path on failure.
  void writeAtomically(const std::string& path) const;

  // The raw JSON text of a key ("" when absent), for tests and summaries.
  std::string raw(const std::string& key) const;

 private:
  void put(const std::string& key, std::string json);
  std::string json(int indent) const;
  std::vector<std::pair<std::string, std::string>> fields_;
};

// `text` as a JSON string, quoted and escaped; bytes that are not valid UTF-8 as U+FFFD.
std::string jsonString(const std::string& text);
// The text with every byte that is not part of valid UTF-8 as U+FFFD: a student's text (a print,
// an exception's message, a status) may hold anything, and reports and traces stay JSON that
// any reader parses.
std::string validUtf8(const std::string& text);

// Fixed, locale-independent number formatting used in reports ("12.345678").
std::string formatNumber(double value);


}  // namespace aula::referee
