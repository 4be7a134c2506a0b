// An LMS's export read into students and hand-ins, and the grades written back (lms_export.hpp).
#include "aula/grade/lms_export.hpp"

#include "lms_export_read.hpp"

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
using detail::classFolder;
using detail::ExportStudent;
using detail::folderWord;
using detail::layoutOfFolder;
using detail::readCanvas;
using detail::readMoodle;

namespace {

// A name as a spreadsheet cell: one that starts as a formula does ("=HYPERLINK(...)", a name a
// student may set) is kept as text. The LMSs match rows by the id, never by this column.
std::string nameCell(const std::string& name) {
  const bool formula = !name.empty() && std::string("=+-@\t\r").find(name[0]) != std::string::npos;
  return csvField(formula ? "'" + name : name);
}

// An export as downloaded, a zip: unpacked whole into OUT/lms-export/<n> (its entries are the
// LMS's names and the students' files as uploaded; each student's part is bounded again when it
// is staged). The folder it was unpacked into.
fs::path unpackExport(const fs::path& absolute, const std::string& path, const std::string& out_dir, const HandInLimits& limits,
                      int& exports) {
  if (!looksLikeZip(absolute.string())) throw ConfigError("aula grade: " + path + ": neither a folder nor an LMS's export zip");
  const fs::path folder = fs::path(out_dir) / "lms-export" / std::to_string(exports++);
  std::error_code error;
  fs::remove_all(folder, error);
  UnzipLimits whole{limits.max_bytes * 1000, limits.max_files * 1000, limits.max_depth + 2};
  uint64_t bytes = 0, files = 0;
  const std::string why = unzipSafely(absolute.string(), folder.string(), whole, bytes, files);
  if (!why.empty()) throw ConfigError("aula grade: " + path + ": " + why);
  return folder;
}

// `path`'s layout, when it is what --lms says (or --lms is auto); throws when it is not.
void checkLayout(const std::string& lms, const std::string& path, const std::string& layout) {
  if (!lms.empty() && lms != "auto") {
    if (layout != lms) {
      throw ConfigError("aula grade --lms=" + lms + ": " + path + " is not a " + lms + " export (" +
                        (layout.empty() ? "its files are not named as " + lms + " names them" : "it is " + layout + "'s") + ")");
    }
  }
}

// The students read so far, and the folders they are built from (readHandIns).
struct Reading {
  const std::string& out_dir;
  const HandInLimits& limits;
  std::vector<Student>& students;
  std::vector<std::string>& folders;
  std::set<std::string> used;

  // Stages `s`'s hand-in into OUT/hand-ins/<folder>, its folder made unique.
  void stage(Student s, const std::vector<HandInItem>& items, bool canvas) {
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
  }

  // A plain student folder, named after it; staged only when its code is not where the grade reads it.
  void plainFolder(const fs::path& absolute) {
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
  }
};

}  // namespace

std::string exportLayout(const std::string& folder) { return layoutOfFolder(classFolder(folder)); }

std::vector<Student> readHandIns(const std::vector<std::string>& given, const std::string& lms, const std::string& out_dir,
                                 const HandInLimits& limits, std::vector<std::string>& folders) {
  std::vector<Student> students;
  folders.clear();
  Reading reading{out_dir, limits, students, folders, {}};
  int exports = 0;
  for (const std::string& path : given) {
    fs::path absolute = fs::absolute(path).lexically_normal();
    // "alice/" is alice: its name, and a link is a link (with the slash, the system would follow it).
    if (!absolute.has_filename()) absolute = absolute.parent_path();
    const fs::path folder = fs::is_regular_file(absolute) ? unpackExport(absolute, path, out_dir, limits, exports) : absolute;
    const fs::path inside = classFolder(folder);
    const std::string layout = layoutOfFolder(inside);
    checkLayout(lms, path, layout);
    if (layout.empty()) {
      if (fs::is_regular_file(absolute)) {
        throw ConfigError("aula grade: " + path + ": a zip, but not a Moodle or Canvas export (its files are not named as theirs)");
      }
      reading.plainFolder(absolute);
      continue;
    }
    for (ExportStudent& e : layout == "moodle" ? readMoodle(inside) : readCanvas(inside)) {
      e.student.folder = folderWord(e.student.name) + "-" + e.student.lms_id;
      reading.stage(e.student, e.items, layout == "canvas");
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
