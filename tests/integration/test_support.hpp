#pragma once
// Shared by the integration tests: a private LCM port per test process, and small readers.
// Integration tests talk over a private UDP multicast port, so parallel ctest runs never cross
// (a different group on the same port still receives the cross-talk: isolate by port).

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include <unistd.h>

namespace aula::testing {

inline std::string privateLcmUrl() {
  const int port = 17000 + static_cast<int>(getpid() % 20000);
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

}  // namespace aula::testing
