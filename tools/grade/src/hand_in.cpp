// A hand-in bounded, staged and its code found (hand_in.hpp).
#include "aula/grade/hand_in.hpp"

#include "hand_in_code.hpp"

#include <aula/grade/submission_build.hpp>
#include <aula/grade/zip_archive.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <set>

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace aula::grade {
namespace fs = std::filesystem;
using detail::copyFile;
using detail::endsWith;
using detail::listed;
using detail::takeCode;

namespace {

std::string mib(uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// The walk of checkHandIn: what it has counted, and the first reason to refuse.
struct Walk {
  const HandInLimits& limits;
  uint64_t bytes = 0, files = 0;
  std::string refused;
};

void check(Walk& walk, const std::string& path, const std::string& name, int depth) {
  if (!walk.refused.empty()) return;
  const std::string shown = name.empty() ? "the hand-in" : printableName(name);
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0) {
    walk.refused = "refused: " + shown + " cannot be read (" + std::strerror(errno) + ")";
    return;
  }
  if (!name.empty() && ++walk.files > walk.limits.max_files) {
    walk.refused = "refused: the hand-in holds more than " + std::to_string(walk.limits.max_files) + " files and folders";
    return;
  }
  if (S_ISLNK(st.st_mode)) {
    walk.refused = "refused: " + shown + " is a symbolic link: a hand-in holds its own files";
  } else if (S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode) || S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) {
    walk.refused = "refused: " + shown + " is not a file (a fifo, a socket or a device)";
  } else if (S_ISREG(st.st_mode)) {
    const uint64_t size = static_cast<uint64_t>(st.st_size), on_disk = static_cast<uint64_t>(st.st_blocks) * 512;
    // Counted as long as it says it is: what a copy of it would write.
    walk.bytes += size;
    if (size > kSparseSlackBytes && on_disk < size / 4) {
      walk.refused = "refused: " + shown + " is a sparse file (" + std::to_string(size) + " bytes, " +
                     std::to_string(on_disk) + " on disk)";
    } else if (walk.bytes > walk.limits.max_bytes) {
      walk.refused = "refused: the hand-in is larger than " + mib(walk.limits.max_bytes) + " (at " + shown + ")";
    }
  } else if (S_ISDIR(st.st_mode)) {
    if (depth > walk.limits.max_depth) {
      walk.refused = "refused: " + shown + " is more than " + std::to_string(walk.limits.max_depth) + " folders deep";
      return;
    }
    DIR* dir = ::opendir(path.c_str());
    if (dir == nullptr) {
      walk.refused = "refused: " + shown + " cannot be listed (" + std::strerror(errno) + ")";
      return;
    }
    std::vector<std::string> entries;
    while (const dirent* entry = ::readdir(dir)) {
      const std::string entry_name = entry->d_name;
      if (entry_name == "." || entry_name == "..") continue;
      entries.push_back(entry_name);
      // Bounded before it is sorted: a folder of a million entries is refused here, not listed.
      if (walk.files + entries.size() > walk.limits.max_files) break;
    }
    ::closedir(dir);
    std::sort(entries.begin(), entries.end());
    for (const std::string& entry : entries) {
      check(walk, path + "/" + entry, name.empty() ? entry : name + "/" + entry, depth + 1);
      if (!walk.refused.empty()) return;
    }
  } else {
    walk.refused = "refused: " + shown + " is not a file";
  }
}

}  // namespace

// Shared with the finding of the code (hand_in_code.cpp), which copies what it takes the same way.
namespace detail {

// Copies the regular file `from` to `to`, at most `budget` bytes of it, never through a link.
std::string copyFile(const std::string& from, const std::string& to, uint64_t& budget) {
  const int in = ::open(from.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (in < 0) return std::string("cannot be read (") + std::strerror(errno) + ")";
  const int out = ::open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (out < 0) {
    ::close(in);
    return std::string("cannot be copied (") + std::strerror(errno) + ")";
  }
  char buffer[1 << 16];
  std::string why;
  for (;;) {
    const ssize_t got = ::read(in, buffer, sizeof buffer);
    if (got <= 0) {
      if (got < 0) why = "cannot be read";
      break;
    }
    // It changed since it was checked: still never more than the hand-in's bound.
    if (static_cast<uint64_t>(got) > budget) {
      why = "grew past the hand-in's bound while it was copied";
      break;
    }
    budget -= static_cast<uint64_t>(got);
    if (::write(out, buffer, static_cast<size_t>(got)) != got) {
      why = "cannot be copied";
      break;
    }
  }
  ::close(in);
  ::close(out);
  return why;
}

bool endsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

}  // namespace detail

namespace {

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// Copies what was handed in into `into`, each zip unpacked into a folder of its name; "" or why not.
std::string copyHandIn(const std::string& path, const fs::path& into, const std::string& name, const HandInLimits& limits,
                       uint64_t& budget, uint64_t& files) {
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0) return "refused: " + printableName(name) + " cannot be read";
  if (S_ISDIR(st.st_mode)) {
    std::error_code error;
    fs::create_directories(into, error);
    if (error) return "cannot make " + into.string();
    std::vector<std::string> entries;
    for (const auto& entry : fs::directory_iterator(path, error)) entries.push_back(entry.path().filename().string());
    std::sort(entries.begin(), entries.end());
    for (const std::string& entry : entries) {
      const std::string why = copyHandIn(path + "/" + entry, into / entry, name.empty() ? entry : name + "/" + entry, limits, budget, files);
      if (!why.empty()) return why;
    }
    return "";
  }
  if (!S_ISREG(st.st_mode)) return "refused: " + printableName(name) + " is not a file";
  if (endsWith(lower(name), ".zip") && looksLikeZip(path)) {
    // A zip's contents count against the hand-in's bounds with everything else in it.
    UnzipLimits left;
    left.max_bytes = budget;
    left.max_files = limits.max_files > files ? limits.max_files - files : 0;
    left.max_depth = limits.max_depth;
    uint64_t bytes = 0, unpacked = 0;
    const std::string why = unzipSafely(path, into.string(), left, bytes, unpacked);
    if (!why.empty()) return "refused: " + printableName(name) + ": " + why;
    budget -= std::min(budget, bytes);
    files += unpacked;
    return "";
  }
  const std::string why = copyFile(path, into.string(), budget);
  return why.empty() ? "" : "refused: " + printableName(name) + " " + why;
}

// Every file under `root`, as "a/b.py", sorted.
std::vector<std::string> filesUnder(const fs::path& root) {
  std::vector<std::string> files;
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(root, error); !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    if (it->is_regular_file()) files.push_back(it->path().lexically_relative(root).generic_string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

std::string checkHandIn(const std::vector<HandInItem>& items, const HandInLimits& limits) {
  Walk walk{limits, 0, 0, ""};
  for (const HandInItem& item : items) {
    check(walk, item.path, item.name, item.name.empty() ? 0 : 1);
    if (!walk.refused.empty()) break;
  }
  return walk.refused;
}

std::string StagedHandIn::summary() const {
  if (!refused.empty()) return refused;
  std::string text = "handed in " + std::to_string(found.size()) + (found.size() == 1 ? " file" : " files");
  if (!found.empty()) text += " (" + listed(found) + ")";
  std::string took;
  for (const std::string& t : taken) took += (took.empty() ? "" : ", ") + t;
  return text + "; graded " + took;
}

StagedHandIn stageHandIn(const std::vector<HandInItem>& items, const std::string& as_found, const std::string& code,
                         const HandInLimits& limits, bool canvas_copies) {
  StagedHandIn staged;
  std::error_code error;
  fs::remove_all(as_found, error);
  fs::remove_all(code, error);
  fs::create_directories(code, error);
  staged.refused = checkHandIn(items, limits);
  if (!staged.refused.empty()) return staged;
  fs::create_directories(as_found, error);
  uint64_t budget = limits.max_bytes, files = 0;
  for (const HandInItem& item : items) {
    const fs::path into = item.name.empty() ? fs::path(as_found) : fs::path(as_found) / item.name;
    if (!item.name.empty()) fs::create_directories(into.parent_path(), error);
    staged.refused = copyHandIn(item.path, into, item.name, limits, budget, files);
    if (!staged.refused.empty()) {
      fs::remove_all(as_found, error);  // nothing of a refused hand-in stays
      return staged;
    }
  }
  const std::vector<std::string> files_found = filesUnder(as_found);
  for (const std::string& f : files_found) staged.found.push_back(printableName(f));
  takeCode(as_found, files_found, code, canvas_copies, staged);
  return staged;
}

}  // namespace aula::grade
