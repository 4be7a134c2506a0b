// An LMS's export read: its layout by its names, and its students with what they handed in
// (lms_export_read.hpp).
#include "lms_export_read.hpp"

#include <aula/config/config.hpp>

#include <algorithm>
#include <map>
#include <regex>

namespace aula::grade::detail {
namespace fs = std::filesystem;
using config::ConfigError;

namespace {

// The export's own names (its folders' and files'), as the LMSs write them.
const std::regex& moodleName() {
  // "Full Name_12345_assignsubmission_file_" (a folder; 4.1 and later without the last '_'), or
  // "Full Name_12345_assignsubmission_file_MyAlgorithm.py" (downloaded without folders).
  static const std::regex name(R"(^(.+)_([0-9]{1,18})_(assignsubmission|assignfeedback)_([a-z]+)(_(.*))?$)");
  return name;
}
const std::regex& canvasName() {
  static const std::regex name(R"(^([A-Za-z0-9-]*?)_((?:LATE|late)_)?([0-9]{1,18})_([0-9]{1,18})_(.+)$)");
  return name;
}

// What of a folder is the export's: its entries but hidden ones and a Mac's __MACOSX.
std::vector<fs::directory_entry> entriesOf(const fs::path& folder) {
  std::vector<fs::directory_entry> entries;
  std::error_code error;  // a folder that does not list is no export (a student's folder says why when it is graded)
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] == '.' || name == "__MACOSX") continue;
    entries.push_back(entry);
  }
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.path() < b.path(); });
  return entries;
}

}  // namespace

// An export zip unpacked has its class either at its top or in one folder (a zip of the folder).
fs::path classFolder(const fs::path& folder) {
  const auto entries = entriesOf(folder);
  if (entries.size() == 1 && entries[0].is_directory() && !std::regex_match(entries[0].path().filename().string(), moodleName())) {
    return entries[0].path();
  }
  return folder;
}

// An export's layout by its names. One Moodle name is enough (no student names a file
// "..._assignsubmission_file_"); Canvas's are plainer, so half the entries and two at least. An
// entry that does not fit the layout found then stops the grade, named (readMoodle, readCanvas),
// rather than the export being graded as one student's folder.
std::string layoutOfFolder(const fs::path& folder) {
  const auto entries = entriesOf(folder);
  const auto count = [&](const std::regex& pattern, bool dirs_ok) {
    return static_cast<size_t>(std::count_if(entries.begin(), entries.end(), [&](const fs::directory_entry& e) {
      return (dirs_ok || !e.is_directory()) && std::regex_match(e.path().filename().string(), pattern);
    }));
  };
  if (count(moodleName(), true) >= 1) return "moodle";
  const size_t canvas = count(canvasName(), false);
  if (canvas >= 2 && 2 * canvas >= entries.size()) return "canvas";
  if (canvas >= 1 && canvas == entries.size()) return "canvas";  // a class of one
  return "";
}

// A name as a folder of the grade's: ASCII letters and digits, the rest as '_', at most 40.
std::string folderWord(const std::string& name) {
  std::string word;
  for (const unsigned char c : name) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (plain) {
      word += static_cast<char>(c);
    } else if (!word.empty() && word.back() != '_') {
      word += '_';
    }
    if (word.size() >= 40) break;
  }
  while (!word.empty() && word.back() == '_') word.pop_back();
  return word.empty() ? "student" : word;
}

std::vector<ExportStudent> readMoodle(const fs::path& folder) {
  std::map<std::string, ExportStudent> by_id;
  for (const auto& entry : entriesOf(folder)) {
    const std::string name = entry.path().filename().string();
    std::smatch m;
    if (!std::regex_match(name, m, moodleName())) {
      throw ConfigError("aula grade: " + entry.path().string() + ": not a participant's folder of a Moodle export "
                        "(\"Full Name_PARTICIPANTID_assignsubmission_file_\")");
    }
    ExportStudent& s = by_id[m[2].str()];
    s.student.lms = "moodle";
    s.student.lms_id = m[2].str();
    s.student.name = m[1].str();
    if (entry.is_directory() && !entry.is_symlink()) {
      s.student.lms_folders.push_back(name);
      for (const auto& inside : fs::directory_iterator(entry.path())) {
        s.items.push_back({inside.path().string(), inside.path().filename().string()});
      }
    } else {  // downloaded without folders: the file's own name is what follows the prefix
      s.student.lms_folders.push_back(m[1].str() + "_" + m[2].str() + "_" + m[3].str() + "_" + m[4].str() + "_");
      const std::string file = m[6].str();
      s.items.push_back({entry.path().string(), file.empty() ? name : file});
    }
  }
  std::vector<ExportStudent> students;
  for (auto& [id, s] : by_id) {
    // The file submission's folder first: the feedback goes under it.
    std::sort(s.student.lms_folders.begin(), s.student.lms_folders.end(), [](const std::string& a, const std::string& b) {
      return (a.find("_assignsubmission_file") != std::string::npos) > (b.find("_assignsubmission_file") != std::string::npos);
    });
    std::sort(s.items.begin(), s.items.end(), [](const HandInItem& a, const HandInItem& b) { return a.name < b.name; });
    students.push_back(std::move(s));
  }
  return students;
}

std::vector<ExportStudent> readCanvas(const fs::path& folder) {
  struct File {
    long long attachment;
    std::string path, name;
  };
  std::map<std::string, ExportStudent> by_id;
  std::map<std::string, std::vector<File>> files;
  for (const auto& entry : entriesOf(folder)) {
    const std::string name = entry.path().filename().string();
    std::smatch m;
    if (entry.is_directory() || !std::regex_match(name, m, canvasName())) {
      throw ConfigError("aula grade: " + entry.path().string() + ": not a file of a Canvas export "
                        "(\"sortablename_USERID_ATTACHMENTID_filename\")");
    }
    ExportStudent& s = by_id[m[3].str()];
    s.student.lms = "canvas";
    s.student.lms_id = m[3].str();
    s.student.name = m[1].str().empty() ? "user " + m[3].str() : m[1].str();
    s.student.late = s.student.late || m[2].matched;
    files[m[3].str()].push_back({std::stoll(m[4].str()), entry.path().string(), m[5].str()});
  }
  std::vector<ExportStudent> students;
  for (auto& [id, s] : by_id) {
    // One name handed in twice (two attachments): the later attachment is the later copy,
    // named as a renamed copy is ("MyAlgorithm (1).py"), so the latest is taken.
    auto& theirs = files[id];
    std::sort(theirs.begin(), theirs.end(), [](const File& a, const File& b) { return a.attachment < b.attachment; });
    std::map<std::string, int> seen;
    for (const File& f : theirs) {
      const int copy = seen[f.name]++;
      std::string name = f.name;
      if (copy > 0) {
        const fs::path p(f.name);
        name = p.stem().string() + " (" + std::to_string(copy) + ")" + p.extension().string();
      }
      s.items.push_back({f.path, name});
    }
    students.push_back(std::move(s));
  }
  return students;
}

}  // namespace aula::grade::detail
