#pragma once
// `aula grade EXERCISE EXPORT`: a class as its LMS hands it out (docs/grading.md, "From your LMS
// and back"), and the grades as the LMS takes them back.
//
// - Moodle's "Download all submissions": a folder per participant, "Full Name_PARTICIPANTID_
//   assignsubmission_file_" (and "_onlinetext_"; Moodle 4.1 and later drop the last '_'), the files
//   inside as uploaded; or, downloaded without folders, the same prefix on each file's name.
// - Canvas's "Download Submissions": flat files "sortablename_[LATE_]USERID_ATTACHMENTID_filename".
// - Anything else given is a plain folder per student, named after it (as before).
// An export is the zip as downloaded or the folder it unpacks to. Each student's hand-in is then
// staged (hand_in.hpp) into OUT/hand-ins/<folder>, the folder the grade builds from.
//
// Back: OUT/lms-grades.csv in the LMS's own import format (Moodle's offline grading worksheet,
// Canvas's gradebook import), and for Moodle OUT/lms-feedback.zip: each participant's run pages
// in the folder the download named, as Moodle's "Upload multiple feedback files in a zip" reads it.

#include <aula/grade/grades.hpp>
#include <aula/grade/hand_in.hpp>

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

namespace aula::grade {

// Who handed in what, as an export names it (OUT/students.json keeps it for --collect).
struct Student {
  std::string folder;      // OUT/runs/<folder>, OUT/hand-ins/<folder>: plain ASCII, unique ("Ada_Lovelace-12")
  std::string name;        // as the LMS writes it ("Ada Lovelace"; Canvas: its sortable name, "lovelaceada")
  std::string lms;         // "moodle", "canvas", or "" for a plain folder
  std::string lms_id;      // Moodle's participant id, Canvas's user id; "" for a plain folder
  std::vector<std::string> lms_folders;  // Moodle: the export's folder names of the participant (feedback goes under the first)
  bool late = false;       // Canvas said LATE
  std::string hand_in;     // what was found and graded, or why nothing is (StagedHandIn::summary)
  std::string refused;     // why nothing of it is graded ("" when something is)
};

// The layout of an export's folder (the class at its top, or in its one folder): "moodle",
// "canvas", or "" for neither (a plain student's folder).
std::string exportLayout(const std::string& folder);

// What `aula grade` was given, as the students to grade: each path an export (by its layout, or
// every one of them when `lms` is "moodle" or "canvas") or a plain student folder. Each export
// student's hand-in is staged into OUT/hand-ins/<folder> (its files as found in
// OUT/hand-ins-as-found/<folder>; an export zip is unpacked into OUT/lms-export first); a plain
// folder without MyAlgorithm.cpp or .py of its own is staged the same way. Throws
// config::ConfigError (exit 2) for a path that is not what `lms` says, or an export that does not
// read. `folders`: each student's folder to build from, in the order of `students`.
std::vector<Student> readHandIns(const std::vector<std::string>& given, const std::string& lms, const std::string& out_dir,
                                 const HandInLimits& limits, std::vector<std::string>& folders);

// OUT/students.json: written by the grade, read by collect (names, ids, what was handed in, and
// the LMS's assignment column, --lms-assignment).
void saveStudents(const std::string& out_dir, const std::vector<Student>& students, const std::string& assignment);
// By folder; no file: none. `assignment`, when given, gets the saved assignment column.
std::map<std::string, Student> loadStudents(const std::string& out_dir, std::string* assignment = nullptr);

// The mark's one-line reason, for the LMS's feedback column: what the student may read.
std::string markReason(const StudentGrade& grade);

// OUT/lms-grades.csv in the LMS's import format, a row per student of `students` that has an
// LMS id (Moodle's worksheet: Identifier "Participant N", Full name, Grade, Maximum Grade,
// Feedback comments; Canvas's: Student, ID, SIS User ID, Section, `assignment`).
std::string lmsGradesCsv(const std::string& lms, const std::vector<StudentGrade>& grades,
                         const std::map<std::string, Student>& students, const std::string& assignment);

// Writes OUT/lms-grades.csv (and, for Moodle, OUT/lms-feedback.zip of each participant's run
// pages) when the class came from an LMS; nothing otherwise.
void writeLmsFiles(const std::string& out_dir, const std::vector<StudentGrade>& grades);

}  // namespace aula::grade
