#pragma once
// report.html: one self-contained page (pictures inlined as data: URIs, no network) for a
// teacher: the class's marks as a histogram, a sortable table of students, and for each run its
// mark, its failure and the referee's picture of it (runs/<student>/<world>-seed<k>.png when
// the referee drew one). Deterministic: the same results give the same bytes.

#include <aula/grade/grades.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace aula::grade {

// `more`: further sections (similar work), placed after the overview.
std::string reportHtml(const std::vector<StudentGrade>& grades, const std::vector<nlohmann::json>& results,
                       const std::string& more = "");

}  // namespace aula::grade
