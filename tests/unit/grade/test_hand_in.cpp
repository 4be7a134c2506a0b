// A student's hand-in and an LMS's export, as aula grade takes them (hand_in.hpp, lms_export.hpp,
// zip_archive.hpp): bounded before anything is copied (sparse files, special files, links, size,
// count, depth), zips unpacked without letting anything out (".." entries, links, a bomb, 10,000
// entries: refused with the reason), the code found (renamed copies, subfolders, another name),
// Moodle's and Canvas's exports read into names and ids, and the grades written back in each LMS's
// import format. Every export and zip here is written by the test.
#include <aula/grade/grade_plan.hpp>
#include <aula/grade/grades.hpp>
#include <aula/grade/hand_in.hpp>
#include <aula/grade/lms_export.hpp>
#include <aula/grade/zip_archive.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace aula::grade;

namespace {

std::string scratch() {
  std::string pattern = (fs::temp_directory_path() / "aula_hand_in_XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

void writeFile(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Bytes on disk under `dir`, as the disk holds them.
uint64_t diskUsage(const fs::path& dir) {
  uint64_t total = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    struct stat st;
    if (::lstat(entry.path().c_str(), &st) == 0) total += static_cast<uint64_t>(st.st_blocks) * 512;
  }
  return total;
}

const char* kBounce = "class MyAlgorithm:\n    def __init__(self, seed):\n        pass\n\n    def execute(self, api):\n        api.motors.sendV(0.2)\n";

StagedHandIn stageFolder(const fs::path& folder, const fs::path& dir, const HandInLimits& limits = {}) {
  return stageHandIn({{folder.string(), ""}}, (dir / "as-found").string(), (dir / "code").string(), limits, false);
}

}  // namespace

// Issue 57's attack: 1500 sparse 1 MiB headers (a few KB on disk) beside a MyAlgorithm.cpp. A copy
// would write 1.5 GB into the grade's folder; the hand-in is refused, with its reason, before a
// byte of it is copied, and the grade's folder stays small.
TEST(HandIn, SparseHeadersAreRefusedBeforeAnythingIsCopied) {
  const fs::path dir = scratch();
  const fs::path student = dir / "class" / "mallory";
  writeFile(student / "MyAlgorithm.cpp", "#include \"h0000.hpp\"\n");
  for (int i = 0; i < 1500; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "h%04d.hpp", i);
    const int fd = ::open((student / name).c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::write(fd, "#pragma once\n", 13), 13);
    ASSERT_EQ(::ftruncate(fd, 1 << 20), 0);  // 1 MiB long, a page on disk
    ::close(fd);
  }
  ASSERT_LT(diskUsage(student), 16u << 20) << "the file system did not keep the files sparse";
  const std::string why = checkHandIn({{student.string(), ""}}, HandInLimits{});
  EXPECT_NE(why.find("refused: h0000.hpp is a sparse file (1048576 bytes, "), std::string::npos) << why;

  // Through the grade's own path: the student's row says why, and nothing of it was copied.
  GradeRequest request;
  request.exercise = "vacuum";
  request.submissions = {student.string()};
  request.out_dir = (dir / "out").string();
  request.jobs = 1;
  const auto subs = compileSubmissions(request, "/nonexistent-prefix");
  ASSERT_EQ(subs.size(), 1u);
  EXPECT_NE(subs[0].compile_error.find("is a sparse file"), std::string::npos) << subs[0].compile_error;
  EXPECT_TRUE(subs[0].plugin.empty());
  EXPECT_LT(fs::exists(dir / "out") ? diskUsage(dir / "out") : 0, 64u << 10);

  fs::remove_all(dir);
}

TEST(HandIn, SpecialFilesLinksAndTooMuchAreRefusedWithTheirReason) {
  const fs::path dir = scratch();
  auto refusal = [&](const std::string& name, const std::function<void(const fs::path&)>& make,
                     const HandInLimits& limits = {}) {
    const fs::path student = dir / name;
    writeFile(student / "MyAlgorithm.py", kBounce);
    make(student);
    return checkHandIn({{student.string(), ""}}, limits);
  };
  EXPECT_EQ(refusal("fine", [](const fs::path&) {}), "");
  EXPECT_EQ(refusal("fifo", [](const fs::path& s) { ASSERT_EQ(::mkfifo((s / "pipe").c_str(), 0644), 0); }),
            "refused: pipe is not a file (a fifo, a socket or a device)");
  EXPECT_EQ(refusal("link", [](const fs::path& s) { fs::create_symlink("/etc/passwd", s / "helpers.py"); }),
            "refused: helpers.py is a symbolic link: a hand-in holds its own files");
  EXPECT_EQ(refusal("socket",
                    [](const fs::path& s) {
                      const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
                      sockaddr_un address{};
                      address.sun_family = AF_UNIX;
                      std::snprintf(address.sun_path, sizeof address.sun_path, "%s", (s / "sock").c_str());
                      ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
                      ::close(fd);
                    }),
            "refused: sock is not a file (a fifo, a socket or a device)");
  HandInLimits small;
  small.max_bytes = 1 << 20;
  small.max_files = 5;
  small.max_depth = 3;
  EXPECT_EQ(refusal("large", [](const fs::path& s) { writeFile(s / "data.bin", std::string(2 << 20, 'x')); }, small),
            "refused: the hand-in is larger than 1 MiB (at data.bin)");
  EXPECT_EQ(refusal("many", [](const fs::path& s) { for (int i = 0; i < 9; ++i) writeFile(s / ("f" + std::to_string(i)), "x"); }, small),
            "refused: the hand-in holds more than 5 files and folders");
  EXPECT_EQ(refusal("deep", [](const fs::path& s) { writeFile(s / "a" / "b" / "c" / "d" / "x.py", "x"); }, small),
            "refused: a/b/c/d is more than 3 folders deep");
  // A student's folder that is itself a link (to /etc): refused, never read.
  fs::create_directory_symlink("/etc", dir / "etc_link");
  EXPECT_EQ(checkHandIn({{(dir / "etc_link").string(), ""}}, HandInLimits{}),
            "refused: the hand-in is a symbolic link: a hand-in holds its own files");
  // Given as "etc_link/" too: the link itself is the student's folder, never followed.
  std::vector<std::string> folders;
  const auto students = readHandIns({(dir / "etc_link").string() + "/"}, "auto", (dir / "out").string(), HandInLimits{}, folders);
  ASSERT_EQ(folders.size(), 1u);
  EXPECT_EQ(students[0].folder, "etc_link");
  EXPECT_EQ(checkHandIn({{folders[0], ""}}, HandInLimits{}), "refused: the hand-in is a symbolic link: a hand-in holds its own files");
  fs::remove_all(dir);
}

// Hostile zips, each refused with its reason; nothing of them is written outside the hand-in
// (nor kept inside it).
TEST(HandIn, HostileZipsAreRefusedAndWriteNothingOutside) {
  const fs::path dir = scratch();
  struct Case {
    std::string name;
    std::vector<ZipItem> items;
    std::string reason;
  };
  std::vector<ZipItem> many;
  for (int i = 0; i < 10000; ++i) many.push_back({"f/" + std::to_string(i) + ".txt", "x"});
  const std::vector<Case> cases = {
      {"dotdot", {{"MyAlgorithm.py", kBounce}, {"../../evil.py", "import os"}}, "../../evil.py is outside the hand-in"},
      {"absolute", {{"/tmp/aula-evil-absolute.py", "x"}}, "/tmp/aula-evil-absolute.py is an absolute path: outside the hand-in"},
      {"link", {{"MyAlgorithm.py", kBounce}, {"passwd", "/etc/passwd", 0120777}}, "passwd is a symbolic link"},
      {"bomb", {{"MyAlgorithm.py", kBounce}, {"zeros.bin", std::string(100u << 20, '\0')}},
       "zeros.bin unpacks to more than the 64 MiB a hand-in may hold"},
      {"many", many, "has 10000 entries, more than the 2000 a hand-in may hold"},
      {"twice", {{"MyAlgorithm.py", kBounce}, {"MyAlgorithm.py", "x"}}, "MyAlgorithm.py is in the zip twice"}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path student = dir / "class" / c.name;
    fs::create_directories(student);
    writeZip((student / "submission.zip").string(), c.items);
    if (c.name == "bomb") {
      EXPECT_LT(fs::file_size(student / "submission.zip"), 1u << 20);
    }
    const fs::path work = dir / "work" / c.name;
    const StagedHandIn staged = stageFolder(student, work);
    EXPECT_NE(staged.refused.find("refused: submission.zip: " + c.reason), std::string::npos) << staged.refused;
    EXPECT_FALSE(fs::exists(work / "as-found")) << "a refused hand-in keeps nothing";
    EXPECT_TRUE(fs::is_empty(work / "code"));
  }
  {  // A bomb that lies: its directory says 1000 bytes; what comes out is bounded, and refused.
    const fs::path student = dir / "class" / "liar";
    fs::create_directories(student);
    const fs::path zip = student / "submission.zip";
    writeZip(zip.string(), {{"MyAlgorithm.py", kBounce}, {"zeros.bin", std::string(100u << 20, '\0')}});
    std::string bytes = readAll(zip);
    const std::string central("PK\x01\x02", 4);
    const size_t second = bytes.find(central, bytes.find(central) + 4);
    ASSERT_NE(second, std::string::npos);
    bytes.replace(second + 24, 4, std::string("\xe8\x03\x00\x00", 4));  // uncompressed size: 1000
    std::ofstream(zip, std::ios::binary | std::ios::trunc) << bytes;
    const StagedHandIn staged = stageFolder(student, dir / "work" / "liar");
    EXPECT_NE(staged.refused.find("refused: submission.zip: zeros.bin is damaged"), std::string::npos) << staged.refused;
    EXPECT_FALSE(fs::exists(dir / "work" / "liar" / "as-found"));
  }
  EXPECT_FALSE(fs::exists(dir / "evil.py"));
  EXPECT_FALSE(fs::exists(dir / "work" / "evil.py"));
  EXPECT_FALSE(fs::exists(dir / "work" / "dotdot" / "evil.py"));
  EXPECT_FALSE(fs::exists("/tmp/aula-evil-absolute.py"));
  fs::remove_all(dir);
}

TEST(HandIn, TheCodeIsFoundAndTheLatestCopyTaken) {
  const fs::path dir = scratch();
  auto stage = [&](const std::string& name, const std::vector<std::pair<std::string, std::string>>& files) {
    const fs::path student = dir / "class" / name;
    fs::create_directories(student);
    for (const auto& [file, text] : files) writeFile(student / file, text);
    return stageFolder(student, dir / "work" / name);
  };
  // Renamed copies: the latest is graded, under the name the grade builds.
  StagedHandIn s = stage("copies", {{"MyAlgorithm.py", "old"}, {"MyAlgorithm (1).py", "older"}, {"MyAlgorithm (2).py", kBounce}});
  EXPECT_EQ(s.refused, "");
  ASSERT_EQ(s.taken.size(), 1u);
  EXPECT_EQ(s.taken[0], "MyAlgorithm.py (from MyAlgorithm (2).py)");
  EXPECT_EQ(readAll(dir / "work" / "copies" / "code" / "MyAlgorithm.py"), kBounce);
  EXPECT_NE(s.summary().find("handed in 3 files"), std::string::npos) << s.summary();
  s = stage("dash", {{"MyAlgorithm.py", "old"}, {"MyAlgorithm-1.py", kBounce}});
  EXPECT_EQ(s.taken, std::vector<std::string>{"MyAlgorithm.py (from MyAlgorithm-1.py)"});
  // In a subfolder, with its helpers; a build folder's sources are not the student's.
  s = stage("sub", {{"project/src/MyAlgorithm.cpp", "int a;"}, {"project/src/helpers.hpp", "int b;"},
                    {"project/build/CMakeFiles/CompilerIdCXX/CMakeCXXCompilerId.cpp", "int c;"}, {"README.md", "hi"}});
  EXPECT_EQ(s.refused, "");
  EXPECT_EQ(s.taken, (std::vector<std::string>{"MyAlgorithm.cpp (from project/src/MyAlgorithm.cpp)",
                                              "helpers.hpp (from project/src/helpers.hpp)"}));
  // In a zip, in a folder.
  const fs::path zipped = dir / "class" / "zipped";
  fs::create_directories(zipped);
  writeZip((zipped / "Lab 3.zip").string(), {{"lab3/", ""}, {"lab3/MyAlgorithm.py", kBounce}, {"lab3/notes.txt", "n"}});
  s = stageFolder(zipped, dir / "work" / "zipped");
  EXPECT_EQ(s.refused, "");
  EXPECT_EQ(s.taken, std::vector<std::string>{"MyAlgorithm.py (from Lab 3.zip/lab3/MyAlgorithm.py)"});
  EXPECT_EQ(readAll(dir / "work" / "zipped" / "code" / "MyAlgorithm.py"), kBounce);
  // One source of another name: unambiguous, taken as MyAlgorithm.
  s = stage("other", {{"cleaner.py", kBounce}, {"report.pdf", "%PDF"}});
  EXPECT_EQ(s.taken, std::vector<std::string>{"MyAlgorithm.py (from cleaner.py)"});
  // Two: which one is the student's to say.
  s = stage("two", {{"a.py", "x"}, {"b.py", "y"}});
  EXPECT_NE(s.refused.find("no MyAlgorithm.cpp or MyAlgorithm.py, and 2 sources (a.py, b.py)"), std::string::npos) << s.refused;
  s = stage("both", {{"MyAlgorithm.py", "x"}, {"MyAlgorithm.cpp", "y"}});
  EXPECT_NE(s.refused.find("both MyAlgorithm.cpp and MyAlgorithm.py"), std::string::npos);
  s = stage("empty", {});
  EXPECT_EQ(s.refused, "nothing handed in");
  EXPECT_EQ(s.summary(), "nothing handed in");
  s = stage("pdf", {{"report.pdf", "%PDF"}});
  EXPECT_EQ(s.refused, "no C++ or Python source handed in (found: report.pdf)");
  fs::remove_all(dir);
}

namespace {

// A Moodle "Download all submissions" of three participants, as its folders.
fs::path moodleExport(const fs::path& root) {
  writeFile(root / "Ada Lovelace_1021_assignsubmission_file_" / "MyAlgorithm.py", kBounce);
  writeFile(root / "Ada Lovelace_1021_assignsubmission_onlinetext_" / "onlinetext.html", "<p>see my file</p>");
  writeFile(root / "José Núñez_1187_assignsubmission_file" / "MyAlgorithm (1).py", kBounce);  // Moodle 4.1: no last '_'
  writeFile(root / "José Núñez_1187_assignsubmission_file" / "MyAlgorithm.py", "old");
  fs::create_directories(root / "Bob Empty_1200_assignsubmission_file_");
  return root;
}

std::vector<ZipItem> zipOfFolder(const fs::path& root) {
  std::vector<ZipItem> items;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string name = entry.path().lexically_relative(root).generic_string();
    if (entry.is_directory()) {
      items.push_back({name + "/", "", 040755});
    } else {
      items.push_back({name, readAll(entry.path())});
    }
  }
  return items;
}

StudentGrade gradeOf(const std::string& folder, double median, const std::string& failures = "") {
  StudentGrade g;
  g.student = folder;
  g.median = g.min = g.max = median;
  g.runs = 1;
  g.runs_failed = failures.empty() ? 0 : 1;
  g.failures = failures;
  return g;
}

}  // namespace

TEST(LmsExport, AMoodleExportIsReadAsItsZipAndItsFolder) {
  const fs::path dir = scratch();
  const fs::path root = moodleExport(dir / "moodle");
  EXPECT_EQ(exportLayout(root.string()), "moodle");
  {  // A file of the teacher's among the participants' folders: the export, named, not a student's folder.
    writeFile(root / "grading.csv", "x");
    std::vector<std::string> folders;
    try {
      readHandIns({root.string()}, "auto", (dir / "out-odd").string(), HandInLimits{}, folders);
      ADD_FAILURE() << "an odd entry in an export was taken";
    } catch (const aula::config::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("grading.csv: not a participant's folder of a Moodle export"), std::string::npos) << e.what();
    }
    fs::remove(root / "grading.csv");
  }
  writeZip((dir / "export.zip").string(), zipOfFolder(root));
  for (const fs::path& given : {root, dir / "export.zip"}) {
    SCOPED_TRACE(given.string());
    const fs::path out = dir / ("out-" + given.filename().string());
    std::vector<std::string> folders;
    const auto students = readHandIns({given.string()}, "auto", out.string(), HandInLimits{}, folders);
    ASSERT_EQ(students.size(), 3u);
    ASSERT_EQ(folders.size(), 3u);
    EXPECT_EQ(students[0].name, "Ada Lovelace");
    EXPECT_EQ(students[0].lms_id, "1021");
    EXPECT_EQ(students[0].folder, "Ada_Lovelace-1021");
    EXPECT_EQ(students[0].lms_folders.front(), "Ada Lovelace_1021_assignsubmission_file_");
    EXPECT_EQ(students[0].refused, "");
    EXPECT_EQ(readAll(fs::path(folders[0]) / "MyAlgorithm.py"), kBounce);
    EXPECT_NE(students[0].hand_in.find("onlinetext.html"), std::string::npos) << students[0].hand_in;
    EXPECT_EQ(students[1].name, "José Núñez");
    EXPECT_EQ(students[1].folder, "Jos_N_ez-1187");
    EXPECT_NE(students[1].hand_in.find("graded MyAlgorithm.py (from MyAlgorithm (1).py)"), std::string::npos) << students[1].hand_in;
    EXPECT_EQ(fs::path(folders[1]).filename(), "Jos_N_ez-1187");
    EXPECT_EQ(fs::path(folders[1]).parent_path(), out / "hand-ins");
    EXPECT_EQ(students[2].name, "Bob Empty");
    EXPECT_EQ(students[2].refused, "nothing handed in");

    saveStudents(out.string(), students, "aula vacuum");
    const auto loaded = loadStudents(out.string());
    ASSERT_EQ(loaded.size(), 3u);
    const std::vector<StudentGrade> grades = {gradeOf("Ada_Lovelace-1021", 7.25), gradeOf("Bob_Empty-1200", 0, "nothing handed in"),
                                              gradeOf("Jos_N_ez-1187", 0, "did not compile: MyAlgorithm.py:3: SyntaxError in /home/teacher/x")};
    const std::string csv = lmsGradesCsv("moodle", grades, loaded, "aula vacuum");
    EXPECT_EQ(csv,
              "Identifier,Full name,Grade,Maximum Grade,Feedback comments\n"
              "Participant 1021,Ada Lovelace,7.25,10.00,\"median 7.25 of 1 run (min 7.25, max 7.25)\"\n"
              "Participant 1200,Bob Empty,0.00,10.00,0: nothing handed in\n"
              "Participant 1187,José Núñez,0.00,10.00,0: did not compile: MyAlgorithm.py:3: SyntaxError in x\n");
  }
  fs::remove_all(dir);
}

TEST(LmsExport, ACanvasExportIsReadWithItsLateAndRenamedFiles) {
  const fs::path dir = scratch();
  const fs::path root = dir / "submissions";
  writeFile(root / "lovelaceada_4410_90001_MyAlgorithm.py", "old");
  writeFile(root / "lovelaceada_4410_90007_MyAlgorithm-1.py", kBounce);  // Canvas's renamed resubmission
  writeFile(root / "lovelaceada_4410_90008_helpers-1.py", "H = 1\n");
  writeFile(root / "nunezjose_LATE_4522_91000_cleaner.cpp", "int x;");
  writeFile(root / "nunezjose_LATE_4522_91001_notes.txt", "n");
  writeFile(root / "smithbob_4600_92000_MyAlgorithm.py", "a");
  writeFile(root / "smithbob_4600_92001_MyAlgorithm.py", kBounce);  // the same name twice: the later attachment
  EXPECT_EQ(exportLayout(root.string()), "canvas");
  std::vector<std::string> folders;
  EXPECT_THROW(readHandIns({root.string()}, "moodle", (dir / "out").string(), HandInLimits{}, folders), aula::config::ConfigError);
  const auto students = readHandIns({root.string()}, "canvas", (dir / "out").string(), HandInLimits{}, folders);
  ASSERT_EQ(students.size(), 3u);
  EXPECT_EQ(students[0].name, "lovelaceada");
  EXPECT_EQ(students[0].lms_id, "4410");
  EXPECT_EQ(readAll(fs::path(folders[0]) / "MyAlgorithm.py"), kBounce);
  EXPECT_EQ(readAll(fs::path(folders[0]) / "helpers.py"), "H = 1\n");
  EXPECT_NE(students[0].hand_in.find("graded MyAlgorithm.py (from MyAlgorithm-1.py), helpers.py (from helpers-1.py)"),
            std::string::npos)
      << students[0].hand_in;
  EXPECT_TRUE(students[1].late);
  EXPECT_EQ(students[1].lms_id, "4522");
  EXPECT_EQ(readAll(fs::path(folders[1]) / "MyAlgorithm.cpp"), "int x;");
  EXPECT_EQ(students[1].hand_in.rfind("late; ", 0), 0u) << students[1].hand_in;
  EXPECT_EQ(readAll(fs::path(folders[2]) / "MyAlgorithm.py"), kBounce);
  std::map<std::string, Student> by_folder;
  for (const Student& s : students) by_folder[s.folder] = s;
  const std::string csv = lmsGradesCsv("canvas", {gradeOf("lovelaceada-4410", 8.5), gradeOf("nunezjose-4522", 3)},
                                       by_folder, "Vacuum (123)");
  EXPECT_EQ(csv, "Student,ID,SIS User ID,Section,Vacuum (123)\nlovelaceada,4410,,,8.50\nnunezjose,4522,,,3.00\n");
  // A name that starts as a spreadsheet formula stays text.
  by_folder["lovelaceada-4410"].name = "=HYPERLINK(\"http://x\")";
  EXPECT_NE(lmsGradesCsv("canvas", {gradeOf("lovelaceada-4410", 8.5)}, by_folder, "V").find("\n\"'=HYPERLINK(\"\"http://x\"\")\",4410,"),
            std::string::npos);
  fs::remove_all(dir);
}

// Moodle's feedback zip: each participant's run pages under the folder the download named.
TEST(LmsExport, MoodleFeedbackFilesGoUnderTheParticipantsFolders) {
  const fs::path dir = scratch();
  const fs::path out = dir / "out";
  std::vector<std::string> folders;
  const auto students = readHandIns({moodleExport(dir / "moodle").string()}, "auto", out.string(), HandInLimits{}, folders);
  saveStudents(out.string(), students, "aula vacuum");
  writeFile(out / "runs" / "Ada_Lovelace-1021" / "vacuum-seed1.html", "<html>ada</html>");
  writeFile(out / "runs" / "Jos_N_ez-1187" / "vacuum-seed1.html", "<html>jose</html>");
  writeLmsFiles(out.string(), {gradeOf("Ada_Lovelace-1021", 7), gradeOf("Jos_N_ez-1187", 5)});
  EXPECT_NE(readAll(out / "lms-grades.csv").find("Participant 1187,José Núñez,5.00"), std::string::npos);
  uint64_t bytes = 0, files = 0;
  ASSERT_EQ(unzipSafely((out / "lms-feedback.zip").string(), (dir / "back").string(), UnzipLimits{1 << 20, 100, 4}, bytes, files), "");
  EXPECT_EQ(readAll(dir / "back" / "Ada Lovelace_1021_assignsubmission_file_" / "vacuum-seed1.html"), "<html>ada</html>");
  EXPECT_EQ(readAll(dir / "back" / "José Núñez_1187_assignsubmission_file_" / "vacuum-seed1.html"), "<html>jose</html>");
  fs::remove_all(dir);
}

// Every way of not running is the same 0 with its reason, before any run: a SyntaxError (its run
// scored 0.02, the robot's footprint), a file with neither class MyAlgorithm nor a loop, a class
// without execute. A RoboticsAcademy program (a loop, no class) and Aula's shape run.
TEST(HandIn, APythonFileThatCannotRunIsRefusedWithItsReason) {
  const fs::path dir = scratch();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {std::string("class MyAlgorithm:\n    def execute(self, api):\n        if x = 3:\n            pass\n"),
       "did not compile: MyAlgorithm.py:3: SyntaxError: "},
      {"x = 1\nprint(x)\n", "not an algorithm: MyAlgorithm.py defines no class MyAlgorithm"},
      {"class MyAlgorithm:\n    def __init__(self, seed):\n        pass\n", "not an algorithm: MyAlgorithm.py's class MyAlgorithm has no execute"},
      {"import HAL\nwhile True:\n    HAL.setV(0.2)\n", ""},
      {"import HAL\nfor i in range(100000):\n    HAL.setV(0.2)\n", ""},
      {"class Base:\n    def execute(self, api):\n        pass\n\nclass MyAlgorithm(Base):\n    pass\n", ""},
      {kBounce, ""}};
  for (size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(cases[i].first);
    const fs::path student = dir / ("s" + std::to_string(i));
    writeFile(student / "MyAlgorithm.py", cases[i].first);
    GradeRequest request;
    request.exercise = "vacuum";
    request.submissions = {student.string()};
    request.out_dir = (dir / "out").string();
    const auto subs = compileSubmissions(request, "/nonexistent");
    ASSERT_EQ(subs.size(), 1u);
    EXPECT_EQ(subs[0].language, "Python");
    if (cases[i].second.empty()) {
      EXPECT_EQ(subs[0].compile_error, "");
      EXPECT_FALSE(subs[0].plugin.empty());
    } else {
      EXPECT_EQ(subs[0].compile_error.rfind(cases[i].second, 0), 0u) << subs[0].compile_error;
      EXPECT_EQ(subs[0].plugin, "");
      EXPECT_EQ(subs[0].compile_error.find(dir.string()), std::string::npos) << "no teacher's path";
    }
  }
  fs::remove_all(dir);
}

// The feedback zip goes to the LMS: its entries carry a valid date (1980-01-01, not day 0, which
// unzip shows as "1980-01-00" and strict readers refuse), and the same grade writes the same bytes.
TEST(HandIn, AWrittenZipHasAValidDateAndTheSameBytesTwice) {
  const fs::path dir = scratch();
  const std::vector<ZipItem> items = {{"Ada Lovelace_12_assignsubmission_file_/vacuum-seed1.html", "<p>10</p>"}};
  writeZip((dir / "a.zip").string(), items);
  writeZip((dir / "b.zip").string(), items);
  const std::string bytes = readAll(dir / "a.zip");
  ASSERT_GT(bytes.size(), 14u);
  // The local header's date (offset 12, little-endian): day 1-31 in bits 0-4, month 1-12 in 5-8.
  const unsigned date = static_cast<unsigned char>(bytes[12]) | (static_cast<unsigned char>(bytes[13]) << 8);
  EXPECT_GE(date & 31u, 1u);
  EXPECT_GE((date >> 5) & 15u, 1u);
  EXPECT_LE((date >> 5) & 15u, 12u);
  EXPECT_EQ(bytes, readAll(dir / "b.zip"));
  fs::remove_all(dir);
}
