#pragma once
// One algorithm plugin (a shared library built with aula_add_algorithm), loaded for one
// exercise. Every way a file can fail to be a usable plugin is a PluginError (a ConfigError:
// exit code 2) that names the file and says what is wrong: missing, not a shared library, an
// undefined symbol (dlerror's text), not an Aula algorithm, another exercise's, another ABI.
//
// The file is copied before dlopen and the copy unlinked at once, so rebuilding the plugin while
// it runs never touches the mapped code, and loading it again loads the new build (hot reload).
//
// A Python file (PATH.py) loads the exercise's Python host module instead, once for the process
// (the interpreter is never shut down: numpy cannot start twice), and gives it the file; the
// host reads the file afresh every time the factory makes an algorithm (hot reload again).

#include <aula/component/plugin_lines.hpp>
#include <aula/config/config.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace aula::component {

class PluginError : public config::ConfigError {
 public:
  using config::ConfigError::ConfigError;
};

class PluginLibrary {
 public:
  // Throws PluginError.
  PluginLibrary(const std::string& path, const std::string& exercise);
  ~PluginLibrary();
  PluginLibrary(const PluginLibrary&) = delete;
  PluginLibrary& operator=(const PluginLibrary&) = delete;

  // The exercise's factory `aula_<exercise>_algorithm_v1(seed)`; the caller owns the result and
  // must delete it before this library is destroyed.
  template <class Algorithm>
  std::unique_ptr<Algorithm> make(uint64_t seed) const {
    using Factory = Algorithm* (*)(uint64_t);
    return std::unique_ptr<Algorithm>(reinterpret_cast<Factory>(factory_)(seed));
  }

  // What raises `why` inside a call that overran its budget, when the algorithm can be
  // interrupted (a Python file), else empty (C++). It may block until the algorithm's code
  // yields: call it on a thread of its own. It stays valid after this library is gone.
  std::function<void(const std::string& why)> interrupter() const;
  // What a Python program printed (print() and its stderr) since the last take, at most the
  // host's last 64 KB; "" for a C++ plugin, whose output goes to the component's own stdout.
  std::string takePrinted() const;

  // Where the exception object `thrown` (as dynamic_cast<const void*> gives it) was thrown in
  // this plugin, from the stack __cxa_throw kept on this thread (throw_site.hpp): the student's
  // "MyAlgorithm.cpp:14" (addr2line on the plugin's debug info, inlined library frames skipped),
  // or "" when it was not thrown from here or the line cannot be told.
  std::string throwSite(const void* thrown) const;
  // Where a C++ plugin is mapped and its file, for naming its lines (a crash's handler reads it);
  // an empty path for a Python file.
  const PluginImage& image() const { return image_; }

  const std::string& path() const { return path_; }
  // A student's Python file rather than a shared library.
  static bool isPythonFile(const std::string& path);
  // The exercise's Python host module: <lib>/aula/python/libaula_<exercise>_python.so.
  static std::string pythonHostPath(const std::string& exercise);
  // The plugin file's modification time when it was loaded ("2026-11-23 17:04:12").
  const std::string& builtAt() const { return built_at_; }
  // True when the file on disk is newer than what is loaded (a rebuild since).
  bool changedOnDisk() const;
  // A file's modification time in ns since the epoch, or -1 when it cannot be read.
  static int64_t mtimeNs(const std::string& path);

 private:
  std::string path_, built_at_;
  void openPython(const std::string& exercise);
  void bindEntryPoints(const std::string& exercise);
  void findImage();

  int64_t mtime_ns_ = 0;
  void* handle_ = nullptr;
  void* factory_ = nullptr;
  void (*interrupt_)(const char*) = nullptr;
  const char* (*take_printed_)() = nullptr;
  PluginImage image_;
};

}  // namespace aula::component
