#include "aula/supervision/confinement.hpp"

#include <aula/config/paths.hpp>
#include <aula/world/world_spec.hpp>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include <sys/stat.h>
#include <unistd.h>

namespace aula::supervision {
namespace fs = std::filesystem;

TemporaryFile::~TemporaryFile() {
  if (!path_.empty()) ::unlink(path_.c_str());
}

std::string TemporaryFile::write(const std::string& content) {
  std::string pattern = (fs::temp_directory_path() / "aula-run-XXXXXX").string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0) throw std::runtime_error("cannot make a file in " + fs::temp_directory_path().string());
  path_ = pattern;
  const bool written = ::write(fd, content.data(), content.size()) == static_cast<ssize_t>(content.size());
  ::fchmod(fd, 0644);
  ::close(fd);
  if (!written) throw std::runtime_error("cannot write " + path_);
  return path_;
}

sandbox::Confinement componentConfinement(const ComponentFiles& files, const sandbox::Limits& limits) {
  sandbox::Confinement c;
  c.limits = limits;
  c.read_only = {files.program, files.cfg};
  c.read_only.insert(c.read_only.end(), files.runtime.begin(), files.runtime.end());
  c.read_only.insert(c.read_only.end(), files.world_inputs.begin(), files.world_inputs.end());
  if (!files.algorithm.empty()) c.read_only.push_back(files.algorithm);
  // Installed under /usr (the .deb), the built-in algorithms' folder is in the system's bind: an
  // empty folder there, with only the run's own built-in bound in it.
  const std::string references = config::libDir() + "/" + config::kReferencesFolder;
  if (references.rfind("/usr/", 0) == 0) c.hidden.push_back(references);
  // config::dataDir() looks for <data>/worlds: there, empty, beside whatever of it is bound.
  c.folders = {files.data_dir + "/worlds"};
  if (!files.world_cache_entry.empty()) {
    c.read_only_at.emplace_back(files.world_cache_entry, std::string(sandbox::kPrivateCache) + "/aula/" + files.world_cache_name);
  }
  return c;
}

ComponentFiles componentFiles(const std::string& program, const std::string& exercise, const std::string& cfg,
                              const std::string& world, const std::string& algorithm) {
  ComponentFiles files;
  files.program = program;
  // Aula's runtime, but not the built-in algorithms: a student's plugin must not load a reference.
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(config::libDir(), error)) {
    if (entry.path().filename() != config::kReferencesFolder) files.runtime.push_back(entry.path().string());
  }
  std::sort(files.runtime.begin(), files.runtime.end());
  files.data_dir = config::dataDir();
  files.cfg = fs::absolute(cfg).lexically_normal().string();
  const world::WorldFiles world_files = world::worldFilesOf(world);
  files.world_inputs = world_files.inputs;
  const std::string entry = config::cacheDir() + "/" + world_files.cache_entry;
  if (fs::is_regular_file(entry)) {
    files.world_cache_entry = entry;
    files.world_cache_name = world_files.cache_entry;
  }
  const bool is_path = algorithm.find('/') != std::string::npos || fs::path(algorithm).has_extension();
  if (is_path) files.algorithm = fs::absolute(algorithm).lexically_normal().string();
  else if (algorithm != "student") files.algorithm = config::builtinAlgorithmPath(exercise, algorithm);
  // A MyAlgorithm.py may import its own modules beside it: its folder (in a graded run, the copy
  // of the submission's .py files and nothing else).
  if (fs::path(files.algorithm).extension() == ".py") files.algorithm = fs::path(files.algorithm).parent_path().string();
  return files;
}

}  // namespace aula::supervision
