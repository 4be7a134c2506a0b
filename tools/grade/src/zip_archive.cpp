// Zip files read and written with minizip (zip_archive.hpp). A hand-in's zip is untrusted: every
// entry is checked before a byte of it is written, and written with O_EXCL | O_NOFOLLOW under a
// folder this code made, so no name and no link in it reaches outside.
#include "aula/grade/zip_archive.hpp"

#include <aula/grade/submission_build.hpp>

#include <minizip/unzip.h>
#include <minizip/zip.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace aula::grade {
namespace fs = std::filesystem;

namespace {

struct Unzip {
  unzFile file;
  explicit Unzip(const std::string& path) : file(unzOpen64(path.c_str())) {}
  ~Unzip() {
    if (file != nullptr) unzClose(file);
  }
};

// The entry's name as its parts, or why it may not be unpacked.
std::string entryParts(const std::string& name, std::vector<std::string>& parts) {
  if (name.empty()) return "an entry has no name";
  if (name.find('\0') != std::string::npos) return printableName(name) + " has a NUL in its name";
  std::string unified = name;
  for (char& c : unified) c = c == '\\' ? '/' : c;  // a Windows tool's separator is a separator
  if (unified[0] == '/') return printableName(name) + " is an absolute path: outside the hand-in";
  size_t at = 0;
  while (at <= unified.size()) {
    const size_t slash = std::min(unified.find('/', at), unified.size());
    const std::string part = unified.substr(at, slash - at);
    if (part == "..") return printableName(name) + " is outside the hand-in (a \"..\" in its path)";
    if (!part.empty() && part != ".") parts.push_back(part);
    at = slash + 1;
  }
  if (parts.empty()) return printableName(name) + " names no file";
  return "";
}

std::string mib(uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// The current entry of `zip`, read and checked against `limits` before any of it is written.
struct Entry {
  std::string name;
  std::vector<std::string> parts;
  bool directory = false;
};

// Reads the current entry into `entry`: "" or why it may not be unpacked.
std::string checkEntry(unzFile zip, const UnzipLimits& limits, uint64_t bytes, uint64_t& files, Entry& entry) {
  unz_file_info64 info;
  char name_buffer[4096];
  if (unzGetCurrentFileInfo64(zip, &info, name_buffer, sizeof name_buffer, nullptr, 0, nullptr, 0) != UNZ_OK) {
    return "is damaged (an entry does not read)";
  }
  const std::string name(name_buffer, info.size_filename < sizeof name_buffer ? info.size_filename : sizeof name_buffer - 1);
  entry.name = name;
  const std::string bad = entryParts(name, entry.parts);
  if (!bad.empty()) return bad;
  entry.directory = name.back() == '/' || name.back() == '\\';
  // The made-by system 3 is Unix: the high half of the external attributes is the file's mode.
  const uint32_t mode = (info.version >> 8) == 3 ? static_cast<uint32_t>(info.external_fa >> 16) : 0;
  if (mode != 0 && !S_ISREG(mode) && !S_ISDIR(mode)) {
    return printableName(name) + (S_ISLNK(mode) ? " is a symbolic link" : " is not a file (a device, a fifo or a socket)");
  }
  if ((info.flag & 1) != 0) return printableName(name) + " is encrypted";
  if (static_cast<int>(entry.parts.size()) - (entry.directory ? 0 : 1) > limits.max_depth) {
    return printableName(name) + " is more than " + std::to_string(limits.max_depth) + " folders deep";
  }
  if (++files > limits.max_files) return "holds more than " + std::to_string(limits.max_files) + " files";
  if (info.uncompressed_size > limits.max_bytes - std::min(bytes, limits.max_bytes)) {
    return printableName(name) + " unpacks to more than the " + mib(limits.max_bytes) + " a hand-in may hold";
  }
  return "";
}

// Writes the current entry's data, already opened as `out`, counting what comes out: "" or why not.
std::string writeEntry(unzFile zip, const std::string& name, int out, const UnzipLimits& limits, uint64_t& bytes,
                       std::vector<char>& buffer) {
  std::string why;
  if (unzOpenCurrentFile(zip) != UNZ_OK) why = printableName(name) + " is damaged (its headers disagree)";
  while (why.empty()) {
    const int got = unzReadCurrentFile(zip, buffer.data(), static_cast<unsigned>(buffer.size()));
    if (got < 0) {
      why = printableName(name) + " is damaged";
      break;
    }
    if (got == 0) break;
    bytes += static_cast<uint64_t>(got);
    // What the entry says of its size is the zip's word: a bomb's is a lie, what comes out is counted.
    if (bytes > limits.max_bytes) {
      why = printableName(name) + " unpacks to more than the " + mib(limits.max_bytes) + " a hand-in may hold";
      break;
    }
    if (::write(out, buffer.data(), static_cast<size_t>(got)) != got) why = "cannot write " + printableName(name);
  }
  if (unzCloseCurrentFile(zip) == UNZ_CRCERROR && why.empty()) why = printableName(name) + " is damaged (its CRC)";
  return why;
}

std::string unzipInto(unzFile zip, const std::string& into, const UnzipLimits& limits, uint64_t& bytes, uint64_t& files) {
  unz_global_info64 global;
  if (unzGetGlobalInfo64(zip, &global) != UNZ_OK) return "not a zip it can read";
  if (global.number_entry > limits.max_files) {
    return "has " + std::to_string(global.number_entry) + " entries, more than the " + std::to_string(limits.max_files) +
           " a hand-in may hold";
  }
  std::set<std::string> written;
  std::vector<char> buffer(1 << 16);
  for (int status = unzGoToFirstFile(zip); status != UNZ_END_OF_LIST_OF_FILE; status = unzGoToNextFile(zip)) {
    if (status != UNZ_OK) return "is damaged (its list of entries does not read)";
    Entry entry;
    const std::string bad = checkEntry(zip, limits, bytes, files, entry);
    if (!bad.empty()) return bad;
    const std::string& name = entry.name;
    fs::path path = into;
    for (size_t i = 0; i + (entry.directory ? 0 : 1) < entry.parts.size(); ++i) {
      path /= entry.parts[i];
      if (::mkdir(path.c_str(), 0755) != 0 && errno != EEXIST) return "cannot make a folder for " + printableName(name);
      struct stat st;
      if (::lstat(path.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) return printableName(name) + " is inside a file";
    }
    if (entry.directory) continue;
    path /= entry.parts.back();
    if (!written.insert(path.string()).second) return printableName(name) + " is in the zip twice";
    const int out = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (out < 0) return printableName(name) + " cannot be written (" + std::strerror(errno) + ")";
    const std::string why = writeEntry(zip, name, out, limits, bytes, buffer);
    ::close(out);
    if (!why.empty()) return why;
  }
  return "";
}

}  // namespace

std::string unzipSafely(const std::string& zip, const std::string& into, const UnzipLimits& limits, uint64_t& bytes,
                        uint64_t& files) {
  Unzip file(zip);
  if (file.file == nullptr) return "not a zip it can read";
  std::error_code error;
  fs::create_directories(into, error);
  if (error) return "cannot make " + into + ": " + error.message();
  const std::string why = unzipInto(file.file, into, limits, bytes, files);
  if (!why.empty()) fs::remove_all(into, error);  // nothing half-unpacked is graded
  return why;
}

bool looksLikeZip(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  in.read(magic, 4);
  return in.gcount() == 4 && magic[0] == 'P' && magic[1] == 'K' &&
         ((magic[2] == 3 && magic[3] == 4) || (magic[2] == 5 && magic[3] == 6));
}

void writeZip(const std::string& path, const std::vector<ZipItem>& items) {
  zipFile zip = zipOpen64(path.c_str(), APPEND_STATUS_CREATE);
  if (zip == nullptr) throw std::runtime_error("cannot write the zip " + path);
  bool ok = true;
  for (const ZipItem& item : items) {
    zip_fileinfo info{};
    // A fixed, valid date (1980-01-01, DOS time's first day; zeros read as day 0): the same
    // grade writes the same bytes.
    info.tmz_date.tm_mday = 1;
    info.tmz_date.tm_year = 1980;
    info.external_fa = static_cast<uLong>(item.unix_mode) << 16;
    // Made by Unix (3 << 8), so that readers take the high half of external_fa as the mode.
    ok = ok && zipOpenNewFileInZip4_64(zip, item.name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr, Z_DEFLATED,
                                       Z_DEFAULT_COMPRESSION, 0, -MAX_WBITS, DEF_MEM_LEVEL, Z_DEFAULT_STRATEGY, nullptr, 0,
                                       (3 << 8) | 20, 0, item.bytes.size() >= 0xffffffffu ? 1 : 0) == ZIP_OK;
    for (size_t at = 0; ok && at < item.bytes.size(); at += 1u << 30) {
      const size_t chunk = std::min<size_t>(1u << 30, item.bytes.size() - at);
      ok = zipWriteInFileInZip(zip, item.bytes.data() + at, static_cast<unsigned>(chunk)) == ZIP_OK;
    }
    ok = ok && zipCloseFileInZip(zip) == ZIP_OK;
  }
  if (zipClose(zip, nullptr) != ZIP_OK || !ok) throw std::runtime_error("cannot write the zip " + path);
}

}  // namespace aula::grade
