#include "aula/config/paths.hpp"

#include <aula/config/config_error.hpp>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <unistd.h>

namespace aula::config {
namespace fs = std::filesystem;

namespace {

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value == nullptr ? std::string() : std::string(value);
}

}  // namespace

std::string dataDir() {
  const std::string from_env = environment("AULA_DATA_DIR");
  if (!from_env.empty()) {
    if (!fs::is_directory(from_env)) throw ConfigError("AULA_DATA_DIR=" + from_env + ": not a folder");
    return fs::absolute(from_env).lexically_normal().string();
  }
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (error) throw ConfigError("cannot find Aula's data folder (/proc/self/exe unreadable); set AULA_DATA_DIR");
  const fs::path share = self.parent_path().parent_path() / "share" / "aula";
  if (!fs::is_directory(share / "worlds")) {
    throw ConfigError("cannot find Aula's data folder: " + share.string() + "/worlds does not exist; set AULA_DATA_DIR");
  }
  return share.lexically_normal().string();
}

std::string libDir() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  const fs::path bin = error ? fs::path(".") : self.parent_path();
  return (bin.parent_path() / "lib" / "aula").lexically_normal().string();
}

std::string builtinAlgorithmPath(const std::string& exercise, const std::string& name) {
  return (fs::path(libDir()) / kReferencesFolder / ("libaula_" + exercise + "_" + name + ".so")).string();
}

std::string docDir() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  const fs::path bin = error ? fs::path(".") : self.parent_path();
  return (bin.parent_path() / "share" / "doc" / "aula").lexically_normal().string();
}

std::string dataPath(const std::string& relative) {
  if (!relative.empty() && relative.front() == '/') return relative;
  return dataDir() + "/" + relative;
}

std::string resolveWorldPath(const std::string& value, const std::string& what) {
  if (value.empty()) throw ConfigError(what + ": no world file given");
  if (fs::is_regular_file(value)) return fs::absolute(value).lexically_normal().string();
  if (value.front() != '/') {
    const std::string data = dataDir();
    for (const std::string& candidate : {data + "/" + value, data + "/worlds/" + value}) {
      if (fs::is_regular_file(candidate)) return fs::path(candidate).lexically_normal().string();
    }
    throw ConfigError(what + ": no such world file '" + value + "' (looked here, in " + data + " and in " + data +
                      "/worlds)");
  }
  throw ConfigError(what + ": no such world file '" + value + "'");
}

std::string cacheDir() {
  std::string base = environment("XDG_CACHE_HOME");
  if (base.empty()) {
    const std::string home = environment("HOME");
    base = (home.empty() ? fs::temp_directory_path().string() : home + "/.cache");
  }
  const fs::path dir = fs::path(base) / "aula";
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) throw ConfigError("cannot create the cache folder " + dir.string() + ": " + error.message());
  return dir.string();
}

void requireWritableFolder(const std::string& file_path, const std::string& what) {
  if (file_path.empty()) throw ConfigError(what + ": no file name");
  const fs::path folder = fs::path(file_path).parent_path().empty() ? fs::path(".") : fs::path(file_path).parent_path();
  if (fs::is_directory(fs::path(file_path))) throw ConfigError(what + ": '" + file_path + "' is a folder, not a file");
  if (!fs::is_directory(folder)) throw ConfigError(what + ": the folder '" + folder.string() + "' does not exist");
  if (access(folder.c_str(), W_OK | X_OK) != 0) throw ConfigError(what + ": the folder '" + folder.string() + "' is not writable");
}

std::string readSmallFile(const std::string& path, uint64_t max_bytes, const std::string& what) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error || status.type() == fs::file_type::not_found) throw ConfigError(what + " " + path + ": no such file");
  if (status.type() == fs::file_type::directory) throw ConfigError(what + " " + path + ": a folder, not a file");
  if (status.type() != fs::file_type::regular) {
    throw ConfigError(what + " " + path + ": not a regular file (a device or a pipe may never end)");
  }
  const uint64_t size = fs::file_size(path, error);
  if (error || size > max_bytes) {
    throw ConfigError(what + " " + path + ": larger than " + std::to_string(max_bytes) + " bytes, which no " + what + " is");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(what + " " + path + ": cannot open it (" + std::strerror(errno) + ")");
  std::string text(size, '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  text.resize(static_cast<size_t>(in.gcount()));
  return text;
}

void writeFileAtomically(const std::string& path, const std::string& content, const std::string& what) {
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  auto fail = [&](const std::string& step, int error) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot " + step + " " + what + ": " + std::strerror(error));
  };
  {
    std::ofstream out(tmp, std::ios::trunc | std::ios::binary);
    if (!out) fail("write", errno);
    out << content;
    out.flush();
    if (!out) fail("write", errno != 0 ? errno : EIO);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) fail("move into place", errno);
}

}  // namespace aula::config
