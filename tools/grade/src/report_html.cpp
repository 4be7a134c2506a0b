#include "aula/grade/report_html.hpp"

#include <aula/grade/grade_runner.hpp>

#include <QByteArray>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace aula::grade {
namespace fs = std::filesystem;

namespace {

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string number(double value) {
  if (!std::isfinite(value)) return "";  // no run measured it
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

// "coverage_percent 63.21, ..." for one run: the raw measures its report names.
std::string measuresOf(const nlohmann::json& result) {
  std::string out;
  if (!result.contains("measures") || !result["measures"].is_array()) return out;
  for (const auto& name : result["measures"]) {
    if (!name.is_string() || !result.contains(name.get<std::string>())) continue;
    const auto& value = result[name.get<std::string>()];
    if (!value.is_number()) continue;
    out += (out.empty() ? "" : ", ") + name.get<std::string>() + " " + number(value.get<double>());
  }
  return out;
}

// The rubric presets the reports were graded with ("default"; "default, original" if mixed).
std::string presetsOf(const std::vector<nlohmann::json>& results) {
  std::set<std::string> presets;
  for (const auto& r : results) {
    if (r.contains("rubric") && r["rubric"].is_object()) presets.insert(r["rubric"].value("preset", "?"));
  }
  std::string out;
  for (const std::string& p : presets) out += (out.empty() ? "" : ", ") + p;
  return out;
}

// The referee's picture of a run, inlined; "" when there is none.
std::string pictureUri(const nlohmann::json& result) {
  if (!result.contains("log")) return "";
  fs::path png = result["log"].get<std::string>();
  png.replace_extension(".png");
  std::ifstream in(png, std::ios::binary);
  if (!in) return "";
  std::stringstream bytes;
  bytes << in.rdbuf();
  const std::string data = bytes.str();
  return "data:image/png;base64," +
         QByteArray(data.data(), static_cast<int>(data.size())).toBase64().toStdString();
}

// The class's median marks in ten bins of one mark, as an SVG bar chart.
std::string histogramSvg(const std::vector<StudentGrade>& grades) {
  std::array<int, 10> bins{};
  for (const auto& g : grades) bins[static_cast<size_t>(std::clamp(static_cast<int>(g.median), 0, 9))]++;
  int top = 1;
  for (int n : bins) top = std::max(top, n);
  const int w = 440, h = 180, bar = 40, base = 150;
  std::ostringstream svg;
  svg << "<svg width='" << w << "' height='" << h << "' role='img' aria-label='marks histogram'>";
  for (int i = 0; i < 10; ++i) {
    const int bar_h = static_cast<int>(std::lround(120.0 * bins[i] / top));
    const int x = 20 + i * bar;
    svg << "<rect x='" << x << "' y='" << base - bar_h << "' width='" << bar - 6 << "' height='" << bar_h
        << "' fill='#3b7dd8'/>";
    if (bins[i] > 0) svg << "<text x='" << x + 17 << "' y='" << base - bar_h - 4 << "' text-anchor='middle'>" << bins[i] << "</text>";
    svg << "<text x='" << x + 17 << "' y='" << base + 16 << "' text-anchor='middle'>" << i << "-" << i + 1 << "</text>";
  }
  svg << "<line x1='16' y1='" << base << "' x2='" << w - 16 << "' y2='" << base << "' stroke='#333'/>"
      << "<text x='" << w / 2 << "' y='" << h - 2 << "' text-anchor='middle'>median mark</text></svg>";
  return svg.str();
}

constexpr const char* kStyle = R"(
body { font-family: sans-serif; margin: 24px; color: #222; }
table { border-collapse: collapse; margin: 12px 0; }
th, td { border: 1px solid #ccc; padding: 4px 8px; text-align: right; }
th { background: #eef2f8; cursor: pointer; user-select: none; }
th:after { content: ' \2195'; color: #999; }
td.name, td.why { text-align: left; }
td.why { color: #b71c1c; max-width: 520px; }
.runs { display: flex; flex-wrap: wrap; gap: 10px; }
.run { border: 1px solid #ccc; padding: 6px; width: 320px; font-size: 13px; }
.run img { width: 100%; image-rendering: auto; }
.run .failed { color: #b71c1c; }
h2 { border-bottom: 1px solid #ddd; padding-bottom: 4px; }
)";

// Click a header to sort by it (numbers as numbers); again to reverse.
constexpr const char* kSortScript = R"(
document.querySelectorAll('table.sortable th').forEach((th, column) => {
  th.addEventListener('click', () => {
    const body = th.closest('table').tBodies[0];
    const rows = Array.from(body.rows);
    const up = th.dataset.order !== 'up';
    th.dataset.order = up ? 'up' : 'down';
    const key = r => { const t = r.cells[column].innerText; const n = parseFloat(t); return isNaN(n) ? t : n; };
    rows.sort((a, b) => { const x = key(a), y = key(b); return (x < y ? -1 : x > y ? 1 : 0) * (up ? 1 : -1); });
    rows.forEach(r => body.appendChild(r));
  });
});
)";

}  // namespace

std::string reportHtml(const std::vector<StudentGrade>& grades, const std::vector<nlohmann::json>& results) {
  std::string exercise;  // from any referee's report (a run that never started has none)
  for (const auto& r : results) {
    if (exercise.empty()) exercise = r.value("exercise", "");
  }
  int failed = 0;
  int tampered = 0;
  for (const auto& r : results) {
    failed += failureOf(r).empty() ? 0 : 1;
    tampered += tamperingOf(r).empty() ? 0 : 1;
  }
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang='en'><head><meta charset='utf-8'><title>Aula grades: " << escape(exercise)
       << "</title><style>" << kStyle << "</style></head><body>\n"
       << "<h1>Aula grades: " << escape(exercise) << "</h1>\n<p>" << grades.size() << " students, " << results.size()
       << " runs, " << failed << " failed"
       << (tampered > 0 ? ", " + std::to_string(tampered) + " with tampering (forged messages the referee refused)" : "")
       << ". The mark of a student is the median over every world and seed"
       << (presetsOf(results).empty() ? std::string() : "; the referee's rubric: " + escape(presetsOf(results)))
       << ". Beside it, the median of each raw measure.</p>\n"
       << histogramSvg(grades) << "\n<table class='sortable'><thead><tr><th>student</th><th>median</th><th>min</th><th>max</th>";
  if (!grades.empty()) {
    for (const auto& [world, value] : grades.front().world_medians) html << "<th>" << escape(world) << "</th>";
    for (const auto& [measure, value] : grades.front().measure_medians) html << "<th>" << escape(measure) << "</th>";
  }
  html << "<th>runs</th><th>failed</th><th>tampered</th><th>why</th></tr></thead><tbody>\n";
  for (const auto& g : grades) {
    html << "<tr><td class='name'><a href='#" << escape(g.student) << "'>" << escape(g.student) << "</a></td><td>"
         << number(g.median) << "</td><td>" << number(g.min) << "</td><td>" << number(g.max) << "</td>";
    for (const auto& [world, value] : g.world_medians) html << "<td>" << number(value) << "</td>";
    for (const auto& [measure, value] : g.measure_medians) html << "<td>" << number(value) << "</td>";
    html << "<td>" << g.runs << "</td><td>" << g.runs_failed << "</td><td" << (g.runs_tampered > 0 ? " class='failed'" : "")
         << ">" << g.runs_tampered << "</td><td class='why'>" << escape(g.failures)
         << "</td></tr>\n";
  }
  html << "</tbody></table>\n";
  std::map<std::string, std::vector<const nlohmann::json*>> by_student;
  for (const auto& r : results) by_student[r.value("student", "?")].push_back(&r);
  for (const auto& [student, runs] : by_student) {
    html << "<h2 id='" << escape(student) << "'>" << escape(student) << "</h2>\n<div class='runs'>\n";
    for (const nlohmann::json* r : runs) {
      const std::string failure = failureOf(*r);
      html << "<div class='run'><b>" << escape(fs::path(r->value("world", "?")).stem().string()) << ", seed "
           << r->value("seed", 0LL) << ": " << number(r->value("mark", 0.0)) << "</b>";
      const std::string measures = measuresOf(*r);
      if (!measures.empty()) html << "<div>" << escape(measures) << "</div>";
      if (!failure.empty()) html << "<div class='failed'>" << escape(failure) << "</div>";
      const std::string tampering = tamperingOf(*r);
      if (!tampering.empty()) html << "<div class='failed'>" << escape(tampering) << "</div>";
      const std::string picture = pictureUri(*r);
      if (!picture.empty()) html << "<img alt='the referee&apos;s picture of the run' src='" << picture << "'>";
      html << "</div>\n";
    }
    html << "</div>\n";
  }
  html << "<script>" << kSortScript << "</script>\n</body></html>\n";
  return html.str();
}

}  // namespace aula::grade
