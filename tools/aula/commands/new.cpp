// aula new EXERCISE DIR [--python]: a student's own project, outside Aula's tree: the template
// (the API at its top), its build (C++) or stubs (Python), and a README that is the exercise's
// student page. Never overwrites.
#include "commands.hpp"
#include "run_settings.hpp"

#include <aula/config/paths.hpp>
#include <aula/settings/tables.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

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

void copyTemplate(const std::string& exercise, const std::string& name, const fs::path& root) {
  const std::string from = config::dataPath("templates/" + exercise + "/" + name);
  if (!fs::is_regular_file(from)) throw ConfigError("aula new: no template at " + from);
  std::error_code error;
  fs::copy_file(from, root / name, error);
  if (error) throw ConfigError("aula new: cannot write " + (root / name).string() + ": " + error.message());
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

// How to build and run, then the exercise's student page (goal, API in both languages, grading
// rules and their numbers, definitions), as installed with Aula's documentation.
void writeReadme(const settings::Exercise& ex, const fs::path& root, bool python, const std::string& run_line) {
  std::ofstream readme(root / "README.md");
  readme << "# My " << ex.name << " algorithm\n\n";
  if (python) {
    readme << "Edit `MyAlgorithm.py` (the API is at its top; `aula_" << ex.name
           << ".pyi` lets your editor complete it). Nothing to build.\n";
  } else {
    readme << "Edit `MyAlgorithm.cpp` (the API is at its top), then `cmake -S . -B build && cmake --build build`.\n";
  }
  readme << "Run it: `" << run_line << "` (add `--headless` for no windows, `--report-html=run.html` to watch it in a browser).\n\n";
  std::ifstream page(config::docDir() + "/exercises/" + ex.name + ".md");
  std::stringstream text;
  text << page.rdbuf();
  readme << text.str();
  if (!readme) throw ConfigError("aula new: cannot write into " + root.string());
}

int createProject(const cli::Arguments& args) {
  const settings::Exercise& ex = exerciseArgument(args.positional(0), "new");
  const std::string dir = args.positional(1);
  const bool python = args.flag("python");
  if (ex.referee_settings == nullptr) throw ConfigError("aula new: '" + ex.name + "' has no student algorithm");
  const fs::path root(dir);
  const std::vector<std::string> files =
      python ? std::vector<std::string>{"MyAlgorithm.py", "aula_" + ex.name + ".pyi", "aula_devices.pyi", "README.md"}
             : std::vector<std::string>{"MyAlgorithm.cpp", "CMakeLists.txt", "README.md"};
  // A project in the other language there already: a second algorithm beside it would be graded
  // instead of (or along with) the student's own.
  const char* other = python ? "MyAlgorithm.cpp" : "MyAlgorithm.py";
  if (fs::exists(root / other)) {
    throw ConfigError("aula new: " + (root / other).string() + " already exists: " + dir + " is a " +
                      (python ? "C++" : "Python") + " project; nothing was written (choose a new folder)");
  }
  refuseExisting(root, files);
  std::error_code error;
  fs::create_directories(root, error);
  if (error) throw ConfigError("aula new: cannot create " + dir + ": " + error.message());
  for (const std::string& name : files) {
    if (name != "README.md" && name != "CMakeLists.txt") copyTemplate(ex.name, name, root);
  }
  if (!python) writeCmakeProject(ex, root);
  const std::string algorithm = python ? dir + "/MyAlgorithm.py" : dir + "/build/libmy_algorithm.so";
  const std::string run_line = "aula run " + ex.name + " --algorithm=" + algorithm;
  writeReadme(ex, root, python, run_line);
  std::cout << "aula new: " << ex.name << " project in " << dir << (python ? " (Python)" : "") << "\n";
  if (!python) std::cout << "  cmake -S " << dir << " -B " << dir << "/build && cmake --build " << dir << "/build\n";
  std::cout << "  " << run_line << "\n";
  return 0;
}

}  // namespace

cli::Command newProject() {
  cli::Command c("new", "start your own algorithm in DIR: MyAlgorithm.cpp (or .py) with the API at its top, and a README");
  c.positionals = {{"EXERCISE", settings::exerciseNames(false)}, {"DIR", "a new folder (nothing is overwritten)"}};
  c.options.flag("python", false, "MyAlgorithm.py and the API's .pyi stubs instead of MyAlgorithm.cpp and CMakeLists.txt");
  c.details = "C++:    cmake -S DIR -B DIR/build && cmake --build DIR/build\n"
              "        aula run EXERCISE --algorithm=DIR/build/libmy_algorithm.so\n"
              "Python: aula run EXERCISE --algorithm=DIR/MyAlgorithm.py\n";
  c.run = createProject;
  return c;
}

}  // namespace aula::commands
