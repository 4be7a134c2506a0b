#pragma once
// Parts of the class report (report_html.cpp): its histograms and the cells of long reasons.
// Private to tools/grade/src.

#include <string>
#include <utility>
#include <vector>

namespace aula::grade {

// Marks in ten bins of one mark, as an SVG bar chart labelled `what`, with dashed `lines` at marks.
std::string histogramSvg(const std::vector<double>& marks, const std::string& what,
                         const std::vector<std::pair<double, std::string>>& lines = {});
// A reason in the students' table: as it is when short, else its beginning, the whole on demand
// (a traceback is no 20-line cell).
std::string whyCell(const std::string& text);

}  // namespace aula::grade
