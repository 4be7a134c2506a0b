#pragma once
// Shared by the integration tests: a private LCM port per test process, running a program to its
// end, and small readers.
// Integration tests talk over a private UDP multicast port, so parallel ctest runs never cross
// (a different group on the same port still receives the cross-talk: isolate by port).

#include <aula/process/child_process.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <regex>
#include <sstream>
#include <optional>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../free_udp_port.hpp"

#include <unistd.h>

namespace aula::testing {

// This test process's private LCM URL: one port for the whole process.
inline std::string privateLcmUrl() {
  static const int port = freeUdpPort();
  return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0&recv_buf_size=4194304";
}

// A fresh folder of this test process's own under the test temp folder (never a fixed name).
inline std::string privateDir() {
  std::string pattern = std::filesystem::temp_directory_path().string() + "/aula_test_XXXXXX";
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

inline std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A number field of a referee's JSON report. A missing field fails the test (and gives NaN, so
// no comparison with it can pass by accident).
inline double jsonNumber(const std::string& json, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(json, m, std::regex("\"" + key + "\": ([-0-9.eE+]+)"))) {
    ADD_FAILURE() << "the report has no number field '" << key << "':\n" << json;
    return std::nan("");
  }
  return std::stod(m[1]);
}

struct Outcome {
  std::optional<int> code;  // none: still running at the limit (then stopped)
  std::string output;       // stderr, then stdout
  double wall_s = 0;
};

// Runs a program to its end (or `limit`), stdout and stderr together.
inline Outcome runToEnd(std::vector<std::string> args, std::chrono::seconds limit = std::chrono::seconds(60)) {
  // Two files: one file opened twice would let stdout and stderr overwrite each other.
  const std::string dir = privateDir();
  const auto start = std::chrono::steady_clock::now();
  process::ChildProcess child(std::move(args), dir + "/out.log", dir + "/err.log");
  Outcome out;
  out.code = child.wait(limit);
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!out.code) child.stop();
  out.output = readFile(dir + "/err.log") + readFile(dir + "/out.log");
  return out;
}

// One CSV line, with quoted fields.
inline std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// grades.csv as rows by student, each field by its column's name.
inline std::map<std::string, std::map<std::string, std::string>> readGrades(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  const auto header = csvFields(line);
  std::map<std::string, std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    const auto fields = csvFields(line);
    EXPECT_EQ(fields.size(), header.size()) << line;
    for (size_t i = 0; i < std::min(fields.size(), header.size()); ++i) rows[fields[0]][header[i]] = fields[i];
  }
  return rows;
}

}  // namespace aula::testing
