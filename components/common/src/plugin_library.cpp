#include "aula/component/plugin_library.hpp"

#include <aula/component/algorithm_plugin.hpp>
#include <aula/component/throw_site.hpp>
#include <aula/config/paths.hpp>
#include <aula/settings/tables.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>

#include <dlfcn.h>
#include <link.h>
#include <sys/stat.h>
#include <unistd.h>

namespace aula::component {
namespace fs = std::filesystem;

int64_t PluginLibrary::mtimeNs(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return -1;
  return static_cast<int64_t>(st.st_mtim.tv_sec) * 1'000'000'000 + st.st_mtim.tv_nsec;
}

namespace {

std::string localTime(int64_t ns) {
  const std::time_t t = static_cast<std::time_t>(ns / 1'000'000'000);
  std::tm tm{};
  localtime_r(&t, &tm);
  std::array<char, 32> text{};
  std::strftime(text.data(), text.size(), "%Y-%m-%d %H:%M:%S", &tm);
  return text.data();
}

bool looksLikeElf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<char, 4> magic{};
  in.read(magic.data(), magic.size());
  return in && magic[0] == 0x7f && magic[1] == 'E' && magic[2] == 'L' && magic[3] == 'F';
}

// A private copy to dlopen: the build may overwrite the original at any time, and glibc would
// hand back the already-loaded object for the same path. In the user's cache (a /tmp may be
// mounted noexec); where that is read-only (the grading sandbox), in the temporary folder.
std::string privateCopy(const std::string& path) {
  std::string why;
  for (const fs::path& dir : {fs::path(config::cacheDir()) / "plugins", fs::temp_directory_path() / "aula-plugins"}) {
    std::error_code error;
    fs::create_directories(dir, error);
    for (int attempt = 0;; ++attempt) {
      const fs::path copy = dir / (fs::path(path).stem().string() + "." + std::to_string(static_cast<long>(::getpid())) +
                                   "." + std::to_string(attempt) + ".so");
      if (fs::exists(copy)) continue;
      fs::copy_file(path, copy, error);
      if (!error) return copy.string();
      if (!why.empty()) why += "; ";
      why += "cannot copy the plugin to " + copy.string() + ": " + error.message();
      break;
    }
  }
  throw PluginError(path + ": " + why);
}

}  // namespace

bool PluginLibrary::isPythonFile(const std::string& path) { return fs::path(path).extension() == ".py"; }

std::string PluginLibrary::pythonHostPath(const std::string& exercise) {
  return (fs::path(config::libDir()) / "python" / ("libaula_" + exercise + "_python.so")).string();
}

PluginLibrary::PluginLibrary(const std::string& path, const std::string& exercise) : path_(path) {
  const bool python = isPythonFile(path);
  if (!fs::exists(path)) {
    throw PluginError(path + (python ? ": no such file" : ": no such plugin file (build it with cmake --build)"));
  }
  if (!fs::is_regular_file(path)) throw PluginError(path + ": not a file");
  mtime_ns_ = mtimeNs(path);
  built_at_ = localTime(mtime_ns_);
  if (python) {
    openPython(exercise);
    return;
  }
  if (!looksLikeElf(path)) throw PluginError(path + ": not a shared library (no ELF header)");

  const std::string copy = privateCopy(path);
  dlerror();
  handle_ = dlopen(copy.c_str(), RTLD_NOW | RTLD_LOCAL);
  const char* load_error = handle_ == nullptr ? dlerror() : nullptr;
  std::string why = load_error == nullptr ? "" : load_error;
  ::unlink(copy.c_str());  // mapped (or not) either way: the copy has done its job
  if (handle_ == nullptr) {
    // dlerror names the private copy; name the student's file instead.
    const auto at = why.find(copy);
    if (at != std::string::npos) why.replace(at, copy.size(), fs::path(path).filename().string());
    if (why.find("undefined symbol") != std::string::npos) {
      throw PluginError(path + ": undefined symbol: " + why +
                        " (the plugin calls something this Aula does not have; rebuild it against this Aula)");
    }
    throw PluginError(path + ": cannot load this shared library: " + why);
  }
  bindEntryPoints(exercise);
  findImage();
}

void PluginLibrary::openPython(const std::string& exercise) {
  const std::string host = pythonHostPath(exercise);
  // Never unloaded (RTLD_NODELETE): the interpreter inside lives as long as the process.
  dlerror();
  handle_ = dlopen(host.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (handle_ == nullptr) {
    const char* why = dlerror();
    throw PluginError(path_ + ": cannot load the Python host for " + exercise + " (" + host +
                      "): " + (why != nullptr ? why : "?"));
  }
  bindEntryPoints(exercise);
  const auto set_file = reinterpret_cast<const char* (*)(const char*)>(dlsym(handle_, "aula_python_set_file"));
  interrupt_ = reinterpret_cast<void (*)(const char*)>(dlsym(handle_, "aula_python_interrupt"));
  take_printed_ = reinterpret_cast<const char* (*)()>(dlsym(handle_, "aula_python_take_console"));
  if (set_file == nullptr || interrupt_ == nullptr || take_printed_ == nullptr) {
    throw PluginError(path_ + ": " + host + " is not an Aula Python host (no aula_python_set_file())");
  }
  if (const char* error = set_file(path_.c_str())) throw PluginError(path_ + ": " + error);
}

void PluginLibrary::bindEntryPoints(const std::string& exercise) {
  const std::string& path = path_;
  auto symbol = [&](const std::string& name) { return dlsym(handle_, name.c_str()); };
  const auto exercise_of = reinterpret_cast<const char* (*)()>(symbol("aula_algorithm_exercise"));
  const auto abi_of = reinterpret_cast<int (*)()>(symbol("aula_algorithm_abi_version"));
  if (exercise_of == nullptr || abi_of == nullptr) {
    dlclose(handle_);
    throw PluginError(path + ": not an Aula algorithm plugin (no aula_algorithm_exercise()); build it with "
                      "aula_add_algorithm(NAME ... EXERCISE " + exercise + " SOURCES MyAlgorithm.cpp)");
  }
  const std::string built_for = exercise_of();
  if (built_for != exercise) {
    dlclose(handle_);
    throw PluginError(path + ": wrong exercise: this is a " + built_for + " algorithm, not a " + exercise + " one");
  }
  if (abi_of() != kAlgorithmAbiVersion) {
    const int abi = abi_of();
    dlclose(handle_);
    throw PluginError(path + ": ABI mismatch: built for algorithm ABI " + std::to_string(abi) + ", this Aula has ABI " +
                      std::to_string(kAlgorithmAbiVersion) + "; rebuild it against this Aula");
  }
  // Built before the exercises had versions of their own: for each one's first (issue 59).
  const auto exercise_abi_of = reinterpret_cast<int (*)()>(symbol("aula_algorithm_exercise_abi_version"));
  const int exercise_abi = exercise_abi_of != nullptr ? exercise_abi_of() : 1;
  const int wanted = settings::requireExercise(exercise).abi_version;
  if (exercise_abi != wanted) {
    dlclose(handle_);
    throw PluginError(path + ": ABI mismatch: built for the " + exercise + " API version " + std::to_string(exercise_abi) +
                      ", this Aula's " + exercise + " API is version " + std::to_string(wanted) +
                      "; rebuild it against this Aula");
  }
  const std::string factory = "aula_" + exercise + "_algorithm_v1";
  factory_ = symbol(factory);
  if (factory_ == nullptr) {
    dlclose(handle_);
    throw PluginError(path + ": has no " + factory + "(); build it with aula_add_algorithm");
  }
}

std::string PluginLibrary::throwSite(const void* thrown) const {
  // Not from a Python file (its host says its own lines); frame 0 is __cxa_throw's own.
  const ThrowStack& stack = lastThrowOnThisThread();
  if (stack.object != thrown || stack.count < 2) return "";
  StudentLine line;
  return studentLines(image_, stack.frames + 1, stack.count - 1, nullptr, &line, 1) == 1 ? line.where : "";
}

namespace {

struct Segments {
  uintptr_t load_address = 0, begin = 0, end = 0;
};

int spanOfLoadedSegments(dl_phdr_info* info, size_t, void* data) {
  auto* span = static_cast<Segments*>(data);
  if (info->dlpi_addr != span->load_address) return 0;
  for (int i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& segment = info->dlpi_phdr[i];
    if (segment.p_type != PT_LOAD) continue;
    const uintptr_t from = info->dlpi_addr + segment.p_vaddr, to = from + segment.p_memsz;
    span->begin = span->begin == 0 ? from : std::min(span->begin, from);
    span->end = std::max(span->end, to);
  }
  return span->end != 0 ? 1 : 0;
}

}  // namespace

void PluginLibrary::findImage() {
  const link_map* map = nullptr;
  if (dlinfo(handle_, RTLD_DI_LINKMAP, &map) != 0 || map == nullptr || path_.size() >= sizeof image_.path) return;
  Segments span;
  span.load_address = map->l_addr;
  dl_iterate_phdr(spanOfLoadedSegments, &span);
  std::memcpy(image_.path, path_.c_str(), path_.size() + 1);
  image_.load_address = span.load_address;
  image_.begin = span.begin;
  image_.end = span.end;
  image_.mtime_ns = mtime_ns_;
}

std::function<void(const std::string&)> PluginLibrary::interrupter() const {
  if (interrupt_ == nullptr) return {};
  return [interrupt = interrupt_](const std::string& why) { interrupt(why.c_str()); };  // the host is never unloaded
}

std::string PluginLibrary::takePrinted() const {
  if (take_printed_ == nullptr) return {};
  const char* text = take_printed_();
  return text == nullptr ? std::string() : std::string(text);
}

PluginLibrary::~PluginLibrary() {
  if (handle_ != nullptr) dlclose(handle_);
}

bool PluginLibrary::changedOnDisk() const {
  const int64_t now = mtimeNs(path_);
  return now >= 0 && now != mtime_ns_;
}

}  // namespace aula::component
