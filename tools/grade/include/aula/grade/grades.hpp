#pragma once
// The class's grades from the runs' results: per student the median mark over all worlds and
// seeds, min, max, the median per world, the median of each raw measure the referee's report
// names in "measures" (coverage %, gaps, time), the failed runs and why. Deterministic: the same
// results give byte-identical files, whichever engine ran them.

#include <aula/grade/similarity.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace aula::grade {

struct StudentGrade {
  std::string student;
  std::string name, lms_id, hand_in;  // as OUT/students.json says (lms_export.hpp); name "" : the student's folder
  std::string language;  // "C++", "Python", or "" when there was nothing to run
  double median = 0, min = 0, max = 0;
  std::vector<std::pair<std::string, double>> world_medians;  // by world name
  // By measure ("coverage_percent"), in the order the reports name them; NaN when no run has it.
  std::vector<std::pair<std::string, double>> measure_medians;
  int runs = 0, runs_failed = 0;
  int runs_tampered = 0;  // runs whose referee counted forged messages (tamperingOf)
  // Runs tried again for the machine's reason (grade_runner.hpp), and runs that never completed
  // (the machine's reason on every try): those are left out of the marks, named in `incomplete`.
  int runs_retried = 0, runs_incomplete = 0;
  std::string failures;    // "reason (x2); other reason"
  std::string retries;     // why runs were tried again: "reason (x2); other reason"
  std::string incomplete;  // the runs left out: "vacuum seed 3; ..."
};

// A CSV field: as it is, or quoted (its quotes doubled, its line breaks as spaces) when it holds a
// comma, a quote or a line break.
std::string csvField(const std::string& text);
// Reads DIR/runs/*/*.json (the students'), or DIR/<folder>/*/*.json (`folder` "known": the runs
// of the algorithms the class is compared with).
std::vector<nlohmann::json> readResults(const std::string& out_dir, const std::string& folder = "runs");
std::vector<StudentGrade> gradeStudents(const std::vector<nlohmann::json>& results);
double median(std::vector<double> values);
// A mark or measure as grades.csv and report.html show it: two decimals, "" when no run measured it.
std::string twoDecimals(double value);
// The world a run was graded on, as the class's results name it: the world file's stem, or a
// destination's ("city-plaza" for city.world's destination "plaza").
std::string gradedWorldOf(const nlohmann::json& result);
// grades.csv: student (the name), lms_id, median, min, max, one median per world, one per measure,
// runs, runs_failed, runs_tampered, runs_retried, runs_incomplete, failures, retries, incomplete,
// language, hand_in, aula_version (docs/grading.md's list is generated from it).
std::string gradesCsv(const std::vector<StudentGrade>& grades);
// Writes DIR/grades.csv and DIR/report.html; returns the grades.
// `similarity`: compare the class's submissions too (similarity.csv and report.html's section);
// the submissions' folders are those of `submissions` (empty: none, no comparison), a pair
// flagged by `rules`; each is compared with the known algorithms' runs in DIR/known too (the
// exercise's built-ins, and the teacher's solutions of `known`, whose code is compared as well).
std::vector<StudentGrade> collect(const std::string& out_dir, const std::vector<std::string>& submissions = {},
                                  const std::string& exercise = "", const SimilarityRules& rules = {},
                                  const std::vector<std::string>& known = {});

}  // namespace aula::grade
