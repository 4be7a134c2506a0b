// aula new EXERCISE DIR: a student's own project, outside Aula's tree. Never overwrites.
#include "commands.hpp"
#include "run_settings.hpp"

#include <aula/config/paths.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>

namespace aula::commands {
namespace {
namespace fs = std::filesystem;
using config::ConfigError;

void refuseExisting(const fs::path& root, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    if (fs::exists(root / name)) {
      throw ConfigError("aula new: " + (root / name).string() + " already exists; nothing was written (choose a new folder)");
    }
  }
}

// The plugin's CMake project: this Aula's own package first (installed: <prefix>/lib/cmake/Aula;
// a build tree: build/).
void writeCmakeProject(const settings::Exercise& ex, const fs::path& root) {
  const fs::path prefix = fs::path(binDir()).parent_path();
  std::ofstream cmake(root / "CMakeLists.txt");
  cmake << "# Your " << ex.name << " algorithm as a plugin: libmy_algorithm.so in build/.\n"
        << "cmake_minimum_required(VERSION 3.16)\n"
        << "project(my_algorithm CXX)\n"
        << "find_package(Aula REQUIRED HINTS \"" << (prefix / "lib" / "cmake" / "Aula").string() << "\" \""
        << prefix.string() << "\")\n"
        << "aula_add_algorithm(NAME my_algorithm EXERCISE " << ex.name << " SOURCES MyAlgorithm.cpp)\n";
  if (!cmake) throw ConfigError("aula new: cannot write into " + root.string());
}

void writeReadme(const settings::Exercise& ex, const fs::path& root) {
  std::ofstream readme(root / "README.md");
  readme << "# My " << ex.name << " algorithm\n"
         << "Edit `MyAlgorithm.cpp` (the API is at its top), then `cmake -S . -B build && cmake --build build`.\n"
         << "Run it: `aula run " << ex.name << " --algorithm=build/libmy_algorithm.so` (add `--headless` for no windows).\n";
  if (!readme) throw ConfigError("aula new: cannot write into " + root.string());
}

int createProject(const cli::Arguments& args) {
  const settings::Exercise& ex = exerciseArgument(args.positional(0), "new");
  const std::string dir = args.positional(1);
  if (ex.referee_settings == nullptr) throw ConfigError("aula new: '" + ex.name + "' has no student algorithm");
  const fs::path root(dir);
  refuseExisting(root, {"MyAlgorithm.cpp", "CMakeLists.txt", "README.md"});
  const std::string template_path = config::dataPath("templates/" + ex.name + "/MyAlgorithm.cpp");
  if (!fs::is_regular_file(template_path)) throw ConfigError("aula new: no template at " + template_path);
  std::error_code error;
  fs::create_directories(root, error);
  if (error) throw ConfigError("aula new: cannot create " + dir + ": " + error.message());
  fs::copy_file(template_path, root / "MyAlgorithm.cpp", error);
  if (error) throw ConfigError("aula new: cannot write " + (root / "MyAlgorithm.cpp").string() + ": " + error.message());
  writeCmakeProject(ex, root);
  writeReadme(ex, root);
  std::cout << "aula new: " << ex.name << " project in " << dir << "\n"
            << "  cmake -S " << dir << " -B " << dir << "/build && cmake --build " << dir << "/build\n"
            << "  aula run " << ex.name << " --algorithm=" << dir << "/build/libmy_algorithm.so\n";
  return 0;
}

}  // namespace

cli::Command newProject() {
  cli::Command c("new", "start your own algorithm in DIR: MyAlgorithm.cpp (the API at its top), CMakeLists.txt, README.md");
  c.positionals = {{"EXERCISE", "teletaxi, vacuum or autopark"}, {"DIR", "a new folder (nothing is overwritten)"}};
  c.details = "then: cmake -S DIR -B DIR/build && cmake --build DIR/build\n"
              "      aula run EXERCISE --algorithm=DIR/build/libmy_algorithm.so\n";
  c.run = createProject;
  return c;
}

}  // namespace aula::commands
