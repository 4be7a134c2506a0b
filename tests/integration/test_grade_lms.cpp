// `aula grade vacuum EXPORT`: a Moodle export zip, written here, graded end to end: a Python bounce
// handed in as a renamed copy inside the student's own zip, a SyntaxError, an empty hand-in and a
// hand-in of sparse headers. grades.csv names each student and their participant id; the three
// who did not run get the same 0 with their reasons; lms-grades.csv is Moodle's worksheet with the
// right identifiers, lms-feedback.zip holds each participant's run pages under their folder; and
// nothing a student or Moodle receives names a folder of the teacher's.
#include <aula/grade/zip_archive.hpp>
#include <aula/process/child_process.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

namespace fs = std::filesystem;
using aula::grade::ZipItem;
using aula::testing::privateDir;
using aula::testing::readFile;

namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::string line;
  for (std::istringstream in(text); std::getline(in, line);) out.push_back(line);
  return out;
}

}  // namespace

TEST(GradeFromAnLms, AMoodleExportIsGradedAndItsGradesGoBack) {
  const fs::path dir = privateDir();
  const std::string bounce = readFile(std::string(AULA_TEST_DATA_DIR) + "/python/vacuum_bounce/MyAlgorithm.py");
  // Ada's own zip, as she uploaded it: her first try and her renamed later copy, in a folder.
  aula::grade::writeZip((dir / "ada.zip").string(), {{"lab/MyAlgorithm.py", "class MyAlgorithm:\n    pass\n"},
                                                     {"lab/MyAlgorithm (1).py", bounce}});
  std::vector<ZipItem> items = {
      {"Ada Lovelace_1021_assignsubmission_file_/", "", 040755},
      {"Ada Lovelace_1021_assignsubmission_file_/ada.zip", readFile((dir / "ada.zip").string())},
      {"Grace Hopper_1030_assignsubmission_file_/MyAlgorithm.py", readFile(std::string(AULA_TEST_DATA_DIR) + "/python/syntax_error/MyAlgorithm.py")},
      {"Bob Empty_1044_assignsubmission_file_/", "", 040755}};
  aula::grade::writeZip((dir / "submissions.zip").string(), items);
  // Mallory's sparse headers go in as a folder export's participant: a zip cannot hold a sparse file.
  const fs::path moodle = dir / "export";
  {
    uint64_t bytes = 0, files = 0;
    ASSERT_EQ(aula::grade::unzipSafely((dir / "submissions.zip").string(), moodle.string(), {64u << 20, 100, 4}, bytes, files), "");
    const fs::path mallory = moodle / "Mallory Sparse_1050_assignsubmission_file_";
    fs::create_directories(mallory);
    std::ofstream(mallory / "MyAlgorithm.py") << bounce;
    for (int i = 0; i < 1500; ++i) {
      const int fd = ::open((mallory / ("h" + std::to_string(i) + ".py")).c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ASSERT_GE(fd, 0);
      ASSERT_EQ(::ftruncate(fd, 1 << 20), 0);
      ::close(fd);
    }
  }
  const fs::path out = dir / "lab3";
  const std::string log = (dir / "grade.txt").string();
  aula::process::ChildProcess grade({std::string(AULA_BIN_DIR) + "/aula", "grade", "vacuum", moodle.string(), "--seeds=1", "--jobs=2",
                                     "--out=" + out.string(), "--Vacuum.Referee.Duration=60", "--calibration-seeds=off"},
                                    log, log);
  const auto code = grade.wait(std::chrono::seconds(900));
  ASSERT_TRUE(code.has_value()) << readFile(log);
  ASSERT_EQ(*code, 0) << readFile(log);

  const std::string csv = readFile((out / "grades.csv").string());
  const auto rows = lines(csv);
  ASSERT_EQ(rows.size(), 5u) << csv;
  EXPECT_EQ(rows[0].rfind("student,lms_id,median,", 0), 0u) << rows[0];
  EXPECT_NE(csv.find("Ada Lovelace,1021,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("graded MyAlgorithm.py (from ada.zip/lab/MyAlgorithm (1).py)"), std::string::npos) << csv;
  EXPECT_NE(csv.find("Bob Empty,1044,0.00,0.00,0.00"), std::string::npos) << csv;
  EXPECT_NE(csv.find("Grace Hopper,1030,0.00,0.00,0.00"), std::string::npos) << csv;
  EXPECT_NE(csv.find("Mallory Sparse,1050,0.00,0.00,0.00"), std::string::npos) << csv;

  // The class report names each student as the LMS does, and says what they handed in.
  const std::string report = readFile((out / "report.html").string());
  EXPECT_NE(report.find("<h2 id='Ada_Lovelace-1021'>Ada Lovelace</h2>"), std::string::npos);
  EXPECT_NE(report.find("<p class='hand-in'>handed in 2 files (ada.zip/lab/MyAlgorithm (1).py, ada.zip/lab/MyAlgorithm.py); "
                        "graded MyAlgorithm.py (from ada.zip/lab/MyAlgorithm (1).py)</p>"),
            std::string::npos);

  const std::string worksheet = readFile((out / "lms-grades.csv").string());
  const auto sheet = lines(worksheet);
  ASSERT_EQ(sheet.size(), 5u) << worksheet;
  EXPECT_EQ(sheet[0], "Identifier,Full name,Grade,Maximum Grade,Feedback comments");
  EXPECT_EQ(sheet[1].rfind("Participant 1021,Ada Lovelace,", 0), 0u) << worksheet;
  EXPECT_EQ(sheet[1].find("Participant 1021,Ada Lovelace,0.00"), std::string::npos) << "Ada's bounce ran: " << worksheet;
  EXPECT_EQ(sheet[2], "Participant 1044,Bob Empty,0.00,10.00,0: nothing handed in");
  EXPECT_EQ(sheet[3].rfind("Participant 1030,Grace Hopper,0.00,10.00,0: did not compile: MyAlgorithm.py:7: SyntaxError: ", 0), 0u)
      << worksheet;
  EXPECT_EQ(sheet[4].rfind("Participant 1050,Mallory Sparse,0.00,10.00,\"0: refused: ", 0), 0u) << worksheet;
  EXPECT_NE(sheet[4].find("is a sparse file"), std::string::npos) << worksheet;
  // The sparse hand-in left nothing of its 1.5 GB in the grade's folder.
  EXPECT_FALSE(fs::exists(out / "hand-ins-as-found" / "Mallory_Sparse-1050"));

  // Moodle's feedback zip: Ada's run page under her folder; no teacher's path in anything sent back.
  uint64_t bytes = 0, files = 0;
  ASSERT_EQ(aula::grade::unzipSafely((out / "lms-feedback.zip").string(), (dir / "feedback").string(),
                                     {64u << 20, 100, 4}, bytes, files),
            "");
  const fs::path page = dir / "feedback" / "Ada Lovelace_1021_assignsubmission_file_" / "vacuum-seed1.html";
  ASSERT_TRUE(fs::is_regular_file(page));
  const std::string html = readFile(page.string());
  EXPECT_NE(html.find("Ada Lovelace, vacuum seed 1"), std::string::npos);
  EXPECT_NE(html.find("graded MyAlgorithm.py (from ada.zip/lab/MyAlgorithm (1).py)"), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(dir / "feedback" / "Grace Hopper_1030_assignsubmission_file_" / "vacuum-seed1.html"));
  for (const std::string& sent : {worksheet, html, readFile((dir / "feedback" / "Grace Hopper_1030_assignsubmission_file_" /
                                                             "vacuum-seed1.html").string())}) {
    EXPECT_EQ(sent.find(dir.string()), std::string::npos) << "a teacher's folder in what goes back";
  }
  fs::remove_all(dir);
}

// What the teacher names and is not what --lms says, or is no export, stops the grade before any
// run or calibration: exit 2, naming the path.
TEST(GradeFromAnLms, AnExportThatIsNotWhatLmsSaysIsAUsageError) {
  const fs::path dir = privateDir();
  const std::string aula = std::string(AULA_BIN_DIR) + "/aula";
  const fs::path moodle = dir / "export";
  std::ofstream((fs::create_directories(moodle / "Ada Lovelace_1021_assignsubmission_file_"),
                 moodle / "Ada Lovelace_1021_assignsubmission_file_" / "MyAlgorithm.py"))
      << "class MyAlgorithm:\n    def execute(self, api):\n        pass\n";
  std::ofstream(dir / "notes.txt") << "not a zip";
  auto grade = [&](const std::vector<std::string>& args) {
    std::vector<std::string> argv = {aula, "grade", "vacuum"};
    argv.insert(argv.end(), args.begin(), args.end());
    const std::string log = (dir / "grade.txt").string();
    aula::process::ChildProcess child(argv, log, log);
    const auto code = child.wait(std::chrono::seconds(120));
    return std::make_pair(code.value_or(-1), readFile(log));
  };
  auto [code, text] = grade({moodle.string(), "--lms=canvas", "--out=" + (dir / "out").string()});
  EXPECT_EQ(code, 2) << text;
  EXPECT_NE(text.find("--lms=canvas: " + moodle.string() + " is not a canvas export (it is moodle's)"), std::string::npos) << text;
  EXPECT_FALSE(fs::exists(dir / "out" / "calibrations"));
  std::tie(code, text) = grade({(dir / "notes.txt").string(), "--out=" + (dir / "out").string()});
  EXPECT_EQ(code, 2) << text;
  EXPECT_NE(text.find("not a folder nor an LMS's export zip"), std::string::npos) << text;
  fs::remove_all(dir);
}

// Canvas's download, as its zip: Ada's resubmitted file (Canvas's "-1") and her helper, José's
// late single file of another name. lms-grades.csv is Canvas's gradebook import, its assignment
// column as --lms-assignment names it, a row per user id.
TEST(GradeFromAnLms, ACanvasExportIsGradedIntoItsGradebookColumn) {
  const fs::path dir = privateDir();
  const std::string bounce = readFile(std::string(AULA_TEST_DATA_DIR) + "/python/vacuum_bounce/MyAlgorithm.py");
  aula::grade::writeZip((dir / "submissions.zip").string(),
                        {{"lovelaceada_4410_90001_MyAlgorithm.py", "class MyAlgorithm:\n    pass\n"},
                         {"lovelaceada_4410_90007_MyAlgorithm-1.py", bounce},
                         {"nunezjose_LATE_4522_91000_cleaner.py", bounce}});
  const fs::path out = dir / "lab3";
  const std::string log = (dir / "grade.txt").string();
  aula::process::ChildProcess grade({std::string(AULA_BIN_DIR) + "/aula", "grade", "vacuum", (dir / "submissions.zip").string(),
                                     "--lms=canvas", "--lms-assignment=Lab 3 (4021)", "--seeds=1", "--jobs=2",
                                     "--out=" + out.string(), "--Vacuum.Referee.Duration=60", "--calibration-seeds=off"},
                                    log, log);
  const auto code = grade.wait(std::chrono::seconds(900));
  ASSERT_TRUE(code.has_value()) << readFile(log);
  ASSERT_EQ(*code, 0) << readFile(log);
  const auto sheet = lines(readFile((out / "lms-grades.csv").string()));
  ASSERT_EQ(sheet.size(), 3u);
  EXPECT_EQ(sheet[0], "Student,ID,SIS User ID,Section,Lab 3 (4021)");
  EXPECT_EQ(sheet[1].rfind("lovelaceada,4410,,,", 0), 0u) << sheet[1];
  EXPECT_EQ(sheet[2].rfind("nunezjose,4522,,,", 0), 0u) << sheet[2];
  // The same program, the same seed: the same mark, whichever file name it came in.
  EXPECT_EQ(sheet[1].substr(sheet[1].rfind(',')), sheet[2].substr(sheet[2].rfind(',')));
  EXPECT_NE(sheet[1].substr(sheet[1].rfind(',')), ",0.00");
  EXPECT_FALSE(fs::exists(out / "lms-feedback.zip")) << "Canvas takes no feedback zip";
  const std::string csv = readFile((out / "grades.csv").string());
  EXPECT_NE(csv.find("nunezjose,4522,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("late; handed in 1 file (cleaner.py); graded MyAlgorithm.py (from cleaner.py)"), std::string::npos) << csv;
  fs::remove_all(dir);
}
