#include "report_parts.hpp"

#include <aula/grade/run_page.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace aula::grade {

// Marks in ten bins of one mark, as an SVG bar chart labelled `what`, with dashed `lines` at marks.
std::string histogramSvg(const std::vector<double>& marks, const std::string& what,
                         const std::vector<std::pair<double, std::string>>& lines) {
  std::array<int, 10> bins{};
  for (double mark : marks) bins[static_cast<size_t>(std::clamp(static_cast<int>(mark), 0, 9))]++;
  int top = 1;
  for (int n : bins) top = std::max(top, n);
  const int w = 440, h = 180, bar = 40, base = 150;
  std::ostringstream svg;
  // A viewBox: narrower than its width (a phone), it scales whole, bin labels and all.
  svg << "<svg width='" << w << "' height='" << h << "' viewBox='0 0 " << w << " " << h
      << "' role='img' aria-label='marks histogram'>";
  for (int i = 0; i < 10; ++i) {
    const int bar_h = static_cast<int>(std::lround(120.0 * bins[i] / top));
    const int x = 20 + i * bar;
    svg << "<rect x='" << x << "' y='" << base - bar_h << "' width='" << bar - 6 << "' height='" << bar_h
        << "' fill='#3b7dd8'/>";
    if (bins[i] > 0) svg << "<text x='" << x + 17 << "' y='" << base - bar_h - 4 << "' text-anchor='middle'>" << bins[i] << "</text>";
    svg << "<text x='" << x + 17 << "' y='" << base + 16 << "' text-anchor='middle'>" << i << "-" << i + 1 << "</text>";
  }
  for (size_t i = 0; i < lines.size(); ++i) {
    const double x = 17 + lines[i].first * bar;
    svg << "<line x1='" << x << "' y1='" << 4 + 14 * i << "' x2='" << x << "' y2='" << base << "' stroke='#d84315' stroke-dasharray='4 3'/>"
        << "<text x='" << x << "' y='" << 12 + 14 * i << "' text-anchor='" << (lines[i].first >= 10 ? "end" : "middle")
        << "' font-size='11' fill='#d84315'>" << escapeHtml(lines[i].second) << "</text>";
  }
  svg << "<line x1='16' y1='" << base << "' x2='" << w - 16 << "' y2='" << base << "' stroke='#333'/>"
      << "<text x='" << w / 2 << "' y='" << h - 2 << "' text-anchor='middle'>" << escapeHtml(what) << "</text></svg>";
  return svg.str();
}


// A reason in the students' table: as it is when short, else its beginning, the whole on demand
// (a traceback is no 20-line cell).
std::string whyCell(const std::string& text) {
  constexpr size_t kShownBytes = 140;
  if (text.size() <= kShownBytes + 20) return escapeHtml(text);
  size_t cut = kShownBytes;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
  return "<details><summary>" + escapeHtml(text.substr(0, cut)) + "</summary>" + escapeHtml(text.substr(cut)) + "</details>";
}

}  // namespace aula::grade
