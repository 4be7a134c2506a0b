// A submission's files, checked and copied (submission_build.hpp): only plain source names, never
// a link, never past kMaxSourceBytes; the rest is listed as not used.
#include "aula/grade/submission_build.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace aula::grade {
namespace fs = std::filesystem;

namespace {

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

bool endsAsSource(const std::string& name) {
  for (const char* extension : {".cpp", ".cc", ".cxx", ".hpp", ".h", ".hh", ".py"}) {
    const std::string ext = extension;
    if (name.size() >= ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0) return true;
  }
  return false;
}

}  // namespace

std::string printableName(const std::string& name) {
  std::string out;
  for (const unsigned char c : name) {
    if (out.size() >= 80) {
      out += "...";
      break;
    }
    if (c >= 0x20 && c < 0x7f && c != '\\' && c != '"' && c != '\'') {
      out += static_cast<char>(c);
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    }
  }
  return out;
}

bool isPlainSourceName(const std::string& name) {
  static const std::regex plain(kPlainSourceName);
  return std::regex_match(name, plain);
}

SubmissionFiles submissionFiles(const std::string& folder) {
  SubmissionFiles files;
  std::vector<fs::directory_entry> entries;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) entries.push_back(entry);
  if (error) {
    files.refused = "refused: cannot list " + printableName(folder) + ": " + error.message();
    return files;
  }
  std::sort(entries.begin(), entries.end(),
            [](const auto& a, const auto& b) { return a.path().filename() < b.path().filename(); });
  for (const auto& entry : entries) {
    const std::string name = entry.path().filename().string();
    const auto status = entry.symlink_status(error);
    const bool regular = !error && fs::is_regular_file(status);
    if (!endsAsSource(name)) {  // not a source: never used, whatever its name
      files.unused.push_back(printableName(name) + (fs::is_directory(status) ? "/" : ""));
      continue;
    }
    std::string why;
    if (!isPlainSourceName(name)) {
      why = "is not a plain source name (letters, digits, '_', '.', '-' and .cpp, .cc, .cxx, .hpp, .h, .hh or .py)";
    } else if (fs::is_symlink(status)) {
      why = "is a symbolic link: a submission's sources are its own files";
    } else if (!regular) {
      why = "is not a file";
    } else if (entry.file_size(error) > kMaxSourceBytes || error) {
      why = "is larger than " + std::to_string(kMaxSourceBytes >> 20) + " MiB";
    }
    if (!why.empty()) {
      files.refused = "refused: " + printableName(name) + " " + why;
      return files;
    }
    files.sources.push_back(name);
  }
  return files;
}

std::string copySources(const std::string& folder, const SubmissionFiles& files, const std::string& into) {
  std::error_code error;
  fs::create_directories(into, error);
  if (error) return "cannot make " + into + ": " + error.message();
  const std::set<std::string> taken(files.sources.begin(), files.sources.end());
  for (const auto& entry : fs::directory_iterator(into, error)) {
    if (taken.count(entry.path().filename().string()) == 0) fs::remove_all(entry.path(), error);
  }
  for (const std::string& name : files.sources) {
    const fs::path from = fs::path(folder) / name, to = fs::path(into) / name;
    const std::string bytes = readAll(from);
    if (fs::is_regular_file(to) && readAll(to) == bytes) continue;  // as built before: no rebuild
    std::ofstream out(to, std::ios::binary | std::ios::trunc);
    out << bytes;
    if (!out.flush()) return "cannot copy " + printableName(name) + " into " + into;
  }
  return "";
}

}  // namespace aula::grade
