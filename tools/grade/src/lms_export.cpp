// An LMS's export read into students and hand-ins, and the grades written back (lms_export.hpp).
#include "aula/grade/lms_export.hpp"

#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>
#include <aula/grade/student_page.hpp>
#include <aula/grade/submission_build.hpp>
#include <aula/grade/zip_archive.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

namespace aula::grade {
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

// One student of an export, with their items (what they handed in).
struct ExportStudent {
  Student student;
  std::vector<HandInItem> items;
};

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

// A name as a spreadsheet cell: one that starts as a formula does ("=HYPERLINK(...)", a name a
// student may set) is kept as text. The LMSs match rows by the id, never by this column.
std::string nameCell(const std::string& name) {
  const bool formula = !name.empty() && std::string("=+-@\t\r").find(name[0]) != std::string::npos;
  return csvField(formula ? "'" + name : name);
}

}  // namespace

std::string exportLayout(const std::string& folder) { return layoutOfFolder(classFolder(folder)); }

std::vector<Student> readHandIns(const std::vector<std::string>& given, const std::string& lms, const std::string& out_dir,
                                 const HandInLimits& limits, std::vector<std::string>& folders) {
  std::vector<Student> students;
  folders.clear();
  std::set<std::string> used;
  int exports = 0;
  auto stage = [&](Student s, const std::vector<HandInItem>& items, bool canvas) {
    std::string folder = s.folder;
    for (int n = 2; !used.insert(folder).second; ++n) folder = s.folder + "-" + std::to_string(n);
    s.folder = folder;
    const fs::path code = fs::path(out_dir) / "hand-ins" / folder;
    const StagedHandIn staged =
        stageHandIn(items, (fs::path(out_dir) / "hand-ins-as-found" / folder).string(), code.string(), limits, canvas);
    s.hand_in = (s.late ? "late; " : "") + staged.summary();
    s.refused = staged.refused;
    folders.push_back(code.string());
    students.push_back(s);
  };
  for (const std::string& path : given) {
    fs::path absolute = fs::absolute(path).lexically_normal();
    // "alice/" is alice: its name, and a link is a link (with the slash, the system would follow it).
    if (!absolute.has_filename()) absolute = absolute.parent_path();
    fs::path folder = absolute;
    if (fs::is_regular_file(absolute)) {
      if (!looksLikeZip(absolute.string())) throw ConfigError("aula grade: " + path + ": neither a folder nor an LMS's export zip");
      // The export as downloaded: unpacked whole (its entries are the LMS's names and the
      // students' files as uploaded; each student's part is bounded again when it is staged).
      folder = fs::path(out_dir) / "lms-export" / std::to_string(exports++);
      std::error_code error;
      fs::remove_all(folder, error);
      UnzipLimits whole{limits.max_bytes * 1000, limits.max_files * 1000, limits.max_depth + 2};
      uint64_t bytes = 0, files = 0;
      const std::string why = unzipSafely(absolute.string(), folder.string(), whole, bytes, files);
      if (!why.empty()) throw ConfigError("aula grade: " + path + ": " + why);
    }
    const fs::path inside = classFolder(folder);
    const std::string layout = layoutOfFolder(inside);
    if (!lms.empty() && lms != "auto") {
      if (layout != lms) {
        throw ConfigError("aula grade --lms=" + lms + ": " + path + " is not a " + lms + " export (" +
                          (layout.empty() ? "its files are not named as " + lms + " names them" : "it is " + layout + "'s") + ")");
      }
    }
    if (layout.empty()) {
      if (fs::is_regular_file(absolute)) {
        throw ConfigError("aula grade: " + path + ": a zip, but not a Moodle or Canvas export (its files are not named as theirs)");
      }
      // A plain student folder, named after it; staged only when its code is not where the grade reads it.
      Student s;
      s.folder = absolute.filename().string();
      s.name = s.folder;
      if (!used.insert(s.folder).second) {
        throw ConfigError("aula grade: two submissions are named '" + s.folder + "' (a student is named after the folder)");
      }
      if (fs::exists(absolute / "MyAlgorithm.cpp") || fs::exists(absolute / "MyAlgorithm.py") || fs::is_symlink(absolute)) {
        folders.push_back(absolute.string());
        students.push_back(s);
      } else {
        used.erase(s.folder);
        stage(s, {{absolute.string(), ""}}, false);
      }
      continue;
    }
    for (ExportStudent& e : layout == "moodle" ? readMoodle(inside) : readCanvas(inside)) {
      e.student.folder = folderWord(e.student.name) + "-" + e.student.lms_id;
      stage(e.student, e.items, layout == "canvas");
    }
  }
  return students;
}

void saveStudents(const std::string& out_dir, const std::vector<Student>& students, const std::string& assignment) {
  nlohmann::ordered_json json;
  json["assignment"] = assignment;
  json["students"] = nlohmann::ordered_json::array();
  for (const Student& s : students) {
    json["students"].push_back({{"folder", s.folder}, {"name", s.name}, {"lms", s.lms}, {"lms_id", s.lms_id},
                                {"lms_folders", s.lms_folders}, {"late", s.late}, {"hand_in", s.hand_in},
                                {"refused", s.refused}});
  }
  config::writeFileAtomically((fs::path(out_dir) / "students.json").string(), json.dump(1) + "\n", "the class's students");
}

std::map<std::string, Student> loadStudents(const std::string& out_dir, std::string* assignment) {
  std::map<std::string, Student> students;
  const fs::path path = fs::path(out_dir) / "students.json";
  if (!fs::is_regular_file(path)) return students;
  try {
    const auto json = nlohmann::json::parse(config::readSmallFile(path.string(), 64u << 20, "the class's students"));
    if (assignment != nullptr) *assignment = json.value("assignment", std::string());
    for (const auto& item : json.at("students")) {
      Student s;
      s.folder = item.at("folder").get<std::string>();
      s.name = item.value("name", s.folder);
      s.lms = item.value("lms", std::string());
      s.lms_id = item.value("lms_id", std::string());
      s.lms_folders = item.value("lms_folders", std::vector<std::string>{});
      s.late = item.value("late", false);
      s.hand_in = item.value("hand_in", std::string());
      s.refused = item.value("refused", std::string());
      students[s.folder] = s;
    }
  } catch (const nlohmann::json::exception& e) {
    throw ConfigError(path.string() + ": not the grade's list of students (" + e.what() + ")");
  }
  return students;
}

std::string markReason(const StudentGrade& g) {
  std::string reason;
  if (g.runs > 0 && g.runs_failed == g.runs && g.max == 0) {
    reason = "0: " + g.failures;  // it never ran: its reason is the mark's
  } else {
    reason = "median " + twoDecimals(g.median) + " of " + std::to_string(g.runs) + (g.runs == 1 ? " run" : " runs") +
             " (min " + twoDecimals(g.min) + ", max " + twoDecimals(g.max) + ")";
    if (g.runs_failed > 0) reason += "; " + std::to_string(g.runs_failed) + " failed: " + g.failures;
  }
  // What the student may read: no teacher's folder, capped like their page's texts.
  return forTheStudent(reason, {});
}

std::string lmsGradesCsv(const std::string& lms, const std::vector<StudentGrade>& grades,
                         const std::map<std::string, Student>& students, const std::string& assignment) {
  std::string csv = lms == "moodle" ? "Identifier,Full name,Grade,Maximum Grade,Feedback comments\n"
                                    : "Student,ID,SIS User ID,Section," + csvField(assignment) + "\n";
  for (const StudentGrade& g : grades) {
    const auto s = students.find(g.student);
    if (s == students.end() || s->second.lms != lms || s->second.lms_id.empty()) continue;
    if (lms == "moodle") {
      csv += csvField("Participant " + s->second.lms_id) + "," + nameCell(s->second.name) + "," + twoDecimals(g.median) +
             ",10.00," + csvField(markReason(g)) + "\n";
    } else {
      csv += nameCell(s->second.name) + "," + s->second.lms_id + ",,," + twoDecimals(g.median) + "\n";
    }
  }
  return csv;
}

void writeLmsFiles(const std::string& out_dir, const std::vector<StudentGrade>& grades) {
  std::string assignment;
  const auto students = loadStudents(out_dir, &assignment);
  std::string lms;
  for (const auto& [folder, s] : students) {
    if (s.lms.empty()) continue;
    if (!lms.empty() && lms != s.lms) throw ConfigError("aula grade: a class from both Moodle and Canvas: its grades go back to one LMS");
    lms = s.lms;
  }
  if (lms.empty()) return;
  config::writeFileAtomically((fs::path(out_dir) / "lms-grades.csv").string(), lmsGradesCsv(lms, grades, students, assignment),
                              "the LMS's grades");
  if (lms != "moodle") return;
  // Each participant's run pages, in the folder the download named (Moodle reads the participant
  // id from it), as "Upload multiple feedback files in a zip" takes them.
  std::vector<ZipItem> items;
  for (const auto& [folder, s] : students) {
    if (s.lms != "moodle" || s.lms_folders.empty()) continue;
    const fs::path runs = fs::path(out_dir) / "runs" / folder;
    std::vector<fs::path> pages;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(runs, error)) {
      if (entry.is_regular_file() && entry.path().extension() == ".html") pages.push_back(entry.path());
    }
    std::sort(pages.begin(), pages.end());
    std::string dir = s.lms_folders.front();
    if (dir.back() != '_') dir += '_';
    for (const fs::path& page : pages) {
      items.push_back({dir + "/" + page.filename().string(), config::readSmallFile(page.string(), 256u << 20, "a run's page")});
    }
  }
  const std::string zip = (fs::path(out_dir) / "lms-feedback.zip").string();
  const std::string part = zip + ".part";
  writeZip(part, items);
  fs::rename(part, zip);
}

}  // namespace aula::grade
