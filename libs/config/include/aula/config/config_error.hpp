#pragma once
// The one error every reader of the user's input throws: a .cfg, a command line, a setting, a path
// or a file the user named. Its own header so that the paths (paths.hpp) and the files (config.hpp)
// both throw it without either including the other.

#include <stdexcept>

namespace aula::config {

// Malformed file, missing key or a value of the wrong type. Processes exit with code 2.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace aula::config
