// What a submission's build is given (submission_build.hpp): its CMake project, and the installed
// Aula it builds against.
#include "aula/grade/submission_build.hpp"

#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

namespace aula::grade {
namespace fs = std::filesystem;
using config::ConfigError;

namespace {

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

void writeBuildProject(const std::string& project, const std::string& exercise, const std::string& aula_config_dir) {
  // The teacher's path, in a bracket argument (nothing in it is evaluated); the exercise is one of
  // Aula's names. Nothing else varies.
  if (aula_config_dir.find("]==]") != std::string::npos || exercise.find_first_not_of("abcdefghijklmnopqrstuvwxyz") != std::string::npos) {
    throw ConfigError("aula grade: cannot write a build project for " + aula_config_dir);
  }
  std::ostringstream cmake;
  cmake << "# A submission as a plugin (written by aula grade): every C++ source of the checked copy in src/.\n"
        << "cmake_minimum_required(VERSION 3.16)\n"
        << "project(aula_submission CXX)\n"
        << "find_package(Aula REQUIRED CONFIG PATHS [==[" << aula_config_dir << "]==] NO_DEFAULT_PATH)\n"
        << "file(GLOB sources LIST_DIRECTORIES false ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp\n"
        << "     ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cc ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cxx)\n"
        << "aula_add_algorithm(NAME my_algorithm EXERCISE " << exercise << " SOURCES ${sources})\n";
  // The same project is left as it is: a resumed grade does not make its plugin look older than
  // its project (aula run refuses a stale build).
  const fs::path path = fs::path(project) / "CMakeLists.txt";
  if (readAll(path) == cmake.str()) return;
  std::ofstream out(path);
  out << cmake.str();
  if (!out.flush()) throw ConfigError("aula grade: cannot write " + path.string());
}

AulaSdk findAulaSdk(const std::string& aula_prefix) {
  AulaSdk sdk;
  for (const fs::path& candidate : {fs::path(aula_prefix) / "lib" / "cmake" / "Aula", fs::path(aula_prefix)}) {
    if (fs::is_regular_file(candidate / "AulaConfig.cmake")) {
      sdk.config_dir = fs::absolute(candidate).lexically_normal().string();
      break;
    }
  }
  if (sdk.config_dir.empty()) {
    throw ConfigError("aula grade: no Aula package (AulaConfig.cmake) in " + aula_prefix + "/lib/cmake/Aula or " +
                      aula_prefix + ": is Aula installed whole?");
  }
  const fs::path import_prefix = fs::path(sdk.config_dir).parent_path().parent_path().parent_path();
  std::set<std::string> includes;
  for (const auto& entry : fs::directory_iterator(sdk.config_dir)) {
    const std::string name = entry.path().filename().string();
    const bool package = (name.rfind("Aula", 0) == 0 && entry.path().extension() == ".cmake") || entry.path().extension() == ".in";
    if (!entry.is_regular_file() || !package) continue;
    sdk.files.push_back(entry.path().string());
    // The include folders its targets name ("${_IMPORT_PREFIX}/include" when installed).
    std::istringstream text(readAll(entry.path()));
    for (std::string line; std::getline(text, line);) {
      const auto key = line.find("INTERFACE_INCLUDE_DIRECTORIES \"");
      if (key == std::string::npos) continue;
      const auto open = line.find('"', key), close = line.rfind('"');
      std::stringstream list(line.substr(open + 1, close - open - 1));
      for (std::string dir; std::getline(list, dir, ';');) {
        const std::string token = "${_IMPORT_PREFIX}";
        if (dir.rfind(token, 0) == 0) dir = import_prefix.string() + dir.substr(token.size());
        if (fs::is_directory(dir)) includes.insert(fs::path(dir).lexically_normal().string());
      }
    }
  }
  std::sort(sdk.files.begin(), sdk.files.end());
  sdk.include_dirs.assign(includes.begin(), includes.end());
  sdk.lib_dir = config::libDir();
  return sdk;
}

}  // namespace aula::grade
