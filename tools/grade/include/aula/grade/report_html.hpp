#pragma once
// report.html: one page (no network) for a teacher: the class's marks as a histogram, a sortable
// table of students with each one's flags (run_page.hpp's runDiagnostics), and for each run its
// mark, its diagnostics, its player (the trace inlined, decoded when opened), a link to its own
// page and the referee's picture, both files beside report.html (runs/<student>/<world>-seed<k>
// .html, .png; the picture loaded lazily): the pictures are not inlined, so a class of 450 runs
// stays a few MB. Deterministic: the same results give the same bytes.

#include <aula/grade/grades.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace aula::grade {

// `more`: further sections (similar work), placed after the overview.
std::string reportHtml(const std::vector<StudentGrade>& grades, const std::vector<nlohmann::json>& results,
                       const std::string& more = "");

}  // namespace aula::grade
