// Similarity over a class: every pair's code score and behaviour distance, similarity.csv and
// report.html's section.
#include "aula/grade/similarity.hpp"

#include <aula/grade/grades.hpp>
#include <aula/grade/run_page.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace aula::grade {
namespace fs = std::filesystem;

namespace {

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Each student's runs' paths, by "world seed".
using Paths = std::map<std::string, std::map<std::string, Path>>;

Paths pathsOf(const std::vector<nlohmann::json>& results) {
  Paths paths;
  for (const auto& r : results) {
    if (!r.contains("log") || !r["log"].is_string()) continue;
    fs::path stem = r["log"].get<std::string>();
    stem.replace_extension();
    const std::string text = traceOfRun(stem.string());  // the trace file, or the page's copy
    if (text.empty()) continue;
    const nlohmann::json parsed = nlohmann::json::parse(text, nullptr, false);
    if (parsed.is_discarded()) continue;
    const std::string run = gradedWorldOf(r) + " seed " +
                            std::to_string(r.value("seed", 0LL));
    paths[r.value("student", std::string("?"))][run] = pathOfTrace(parsed);
  }
  return paths;
}

// The median mean distance over the runs both students made that both moved in; runs named in `runs`.
double behaviourDistance(const std::map<std::string, Path>& a, const std::map<std::string, Path>& b, double moved_m,
                         std::vector<std::string>& runs) {
  std::vector<double> distances;
  for (const auto& [run, path] : a) {
    const auto other = b.find(run);
    if (other == b.end() || pathLength(path) < moved_m || pathLength(other->second) < moved_m) continue;
    const double d = meanDistance(path, other->second);
    if (std::isnan(d)) continue;
    distances.push_back(d);
    runs.push_back(run);
  }
  if (distances.empty()) return -1;
  std::sort(distances.begin(), distances.end());
  const size_t n = distances.size();
  return n % 2 == 1 ? distances[n / 2] : 0.5 * (distances[n / 2 - 1] + distances[n / 2]);
}

// "student/file" of a submission's file `index`.
std::string fileOf(const Submitted& s, int index) {
  const std::string name = index >= 0 && static_cast<size_t>(index) < s.sources.size()
                               ? fs::path(s.sources[static_cast<size_t>(index)]).filename().string()
                               : "?";
  return s.student + "/" + name;
}

std::string evidenceOf(const CodeMatch& code, const Submitted& a, const Submitted& b, const std::vector<std::string>& runs) {
  std::ostringstream out;
  for (size_t i = 0; i < code.ranges.size() && i < 6; ++i) {
    const MatchedLines& r = code.ranges[i];
    out << (i ? "; " : "") << fileOf(a, r.a_file) << ":" << r.a_first << "-" << r.a_last << " ~ " << fileOf(b, r.b_file) << ":"
        << r.b_first << "-" << r.b_last;
  }
  if (!runs.empty()) {
    out << (code.ranges.empty() ? "" : "; ") << "runs compared:";
    for (const std::string& run : runs) out << " " << run << ";";
  }
  std::string text = out.str();
  if (!text.empty() && text.back() == ';') text.pop_back();
  return text;
}

// A submission's language: 'p' all Python, 'c' all C++, 'm' both (compared in the common form).
char languageOf(const Submitted& s) {
  size_t python = 0;
  for (const std::string& source : s.sources) python += fs::path(source).extension() == ".py" ? 1 : 0;
  return python == 0 ? 'c' : python == s.sources.size() ? 'p' : 'm';
}

std::string number(double value, int decimals) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(decimals);
  out << value;
  return out.str();
}

}  // namespace

Path pathOfTrace(const nlohmann::json& trace) {
  Path path;
  if (!trace.contains("samples")) return path;
  const auto& samples = trace["samples"];
  path.period_s = samples.value("period_s", 0.1);
  double x_mm = 0, y_mm = 0;  // delta-encoded: the first absolute, then each step
  const auto& xs = samples.at("x_mm");
  const auto& ys = samples.at("y_mm");
  for (size_t i = 0; i < xs.size() && i < ys.size(); ++i) {
    x_mm += xs[i].get<double>();
    y_mm += ys[i].get<double>();
    path.x_m.push_back(x_mm / 1000.0);
    path.y_m.push_back(y_mm / 1000.0);
  }
  return path;
}

double meanDistance(const Path& a, const Path& b) {
  const size_t n = std::min(a.x_m.size(), b.x_m.size());
  if (n == 0 || std::abs(a.period_s - b.period_s) > 1e-9) return std::nan("");
  double sum = 0;
  for (size_t i = 0; i < n; ++i) sum += std::hypot(a.x_m[i] - b.x_m[i], a.y_m[i] - b.y_m[i]);
  return sum / static_cast<double>(n);
}

double pathLength(const Path& path) {
  double length = 0;
  for (size_t i = 1; i < path.x_m.size(); ++i) {
    length += std::hypot(path.x_m[i] - path.x_m[i - 1], path.y_m[i] - path.y_m[i - 1]);
  }
  return length;
}

std::vector<PairSimilarity> compareClass(const std::vector<Submitted>& students, const std::vector<nlohmann::json>& results,
                                         const std::vector<Fingerprint>& starter, const SimilarityRules& rules) {
  // Each submission's files as written, and in the common form for a pair across the two languages.
  std::vector<std::vector<Fingerprint>> prints, common;
  std::vector<char> language;
  for (const Submitted& s : students) {
    language.push_back(languageOf(s));
    std::vector<SourceText> files;
    for (const std::string& source : s.sources) files.push_back({readText(source), fs::path(source).extension() == ".py"});
    prints.push_back(codeFingerprints(files));
    common.push_back(codeFingerprints(files, CodeForm::Common));
  }
  const Paths paths = pathsOf(results);
  std::vector<PairSimilarity> pairs;
  for (size_t i = 0; i < students.size(); ++i) {
    for (size_t j = i + 1; j < students.size(); ++j) {
      if (students[i].known && students[j].known) continue;  // two references: not a class's likeness
      PairSimilarity pair;
      pair.a = students[i].student;
      pair.b = students[j].student;
      pair.across_languages = (language[i] != language[j] || language[i] == 'm') && !students[i].sources.empty() &&
                              !students[j].sources.empty();
      const CodeMatch code = pair.across_languages ? compareCode(common[i], common[j], starter) : compareCode(prints[i], prints[j], starter);
      pair.code_score = code.score;
      std::vector<std::string> runs;
      const auto pa = paths.find(pair.a), pb = paths.find(pair.b);
      if (pa != paths.end() && pb != paths.end()) pair.behaviour_m = behaviourDistance(pa->second, pb->second, rules.moved_m, runs);
      pair.runs_compared = static_cast<int>(runs.size());
      pair.flagged = (pair.code_score >= rules.code_threshold && code.shared >= rules.code_min_shared) ||
                     (pair.runs_compared > 0 && pair.behaviour_m <= rules.behaviour_threshold_m);
      pair.evidence = (pair.across_languages && !code.ranges.empty() ? "across C++ and Python: " : "") +
                      evidenceOf(code, students[i], students[j], runs);
      pairs.push_back(pair);
    }
  }
  std::stable_sort(pairs.begin(), pairs.end(), [](const PairSimilarity& x, const PairSimilarity& y) {
    return x.flagged != y.flagged ? x.flagged : x.code_score > y.code_score;
  });
  return pairs;
}

std::string similarityCsv(const std::vector<PairSimilarity>& pairs) {
  std::string csv = "student_a,student_b,flagged,code_score,behaviour_mean_distance_m,runs_compared,evidence\n";
  for (const PairSimilarity& p : pairs) {
    std::string evidence = p.evidence;
    for (size_t at = evidence.find('"'); at != std::string::npos; at = evidence.find('"', at + 2)) evidence.insert(at, "\"");
    csv += csvField(p.a) + "," + csvField(p.b) + "," + (p.flagged ? "yes" : "no") + "," + number(p.code_score, 2) + "," +
           (p.behaviour_m < 0 ? "" : number(p.behaviour_m, 3)) + "," + std::to_string(p.runs_compared) + ",\"" + evidence +
           "\"\n";
  }
  return csv;
}

std::string similarityHtml(const std::vector<PairSimilarity>& pairs, const std::vector<Submitted>& students,
                           const SimilarityRules& rules) {
  std::map<std::string, std::string> source;
  std::set<std::string> known;
  for (const Submitted& s : students) {
    std::string& text = source[s.student];
    if (s.sources.empty()) text = "(a built-in algorithm whose sources are not installed: compared by its robot's path)";
    for (const std::string& file : s.sources) {
      text += (s.sources.size() > 1 ? "// ===== " + fs::path(file).filename().string() + " =====\n" : "") + readText(file);
    }
    if (s.known) known.insert(s.student);
  }
  std::ostringstream html;
  size_t flagged = 0;
  for (const PairSimilarity& p : pairs) flagged += p.flagged ? 1 : 0;
  html << "<h2 id='similarity'>Similar work (" << flagged << " pairs to look at)</h2>\n<p>Pairs whose code shares "
       << "fingerprints that renaming and reordering do not hide, or whose robots drove the same path on the same world "
       << "and seed. For a teacher to look at: no mark changes. All pairs: similarity.csv.</p>\n<p class='rules'>Flagged: "
       << "a code score of " << number(rules.code_threshold, 2) << " or more with " << rules.code_min_shared
       << " shared fingerprints or more (aula grade --similarity-code, --similarity-shared), or paths "
       << number(rules.behaviour_threshold_m, 3) << " m apart or less for robots that moved " << number(rules.moved_m, 1)
       << " m or more (--similarity-path).</p>\n";
  for (const PairSimilarity& p : pairs) {
    if (!p.flagged) continue;
    const std::string who = known.count(p.b) != 0 ? escapeHtml(p.a) + " matches " + escapeHtml(p.b)
                                                    : escapeHtml(p.a) + " ~ " + escapeHtml(p.b);
    html << "<details class='pair'><summary><b>" << who << "</b>: code "
         << number(p.code_score, 2) << (p.across_languages ? " (across C++ and Python)" : "") << (p.behaviour_m < 0 ? "" : ", paths " + number(p.behaviour_m, 3) + " m apart")
         << "</summary><p>" << escapeHtml(p.evidence) << "</p><div class='side-by-side'><pre>" << escapeHtml(source[p.a])
         << "</pre><pre>" << escapeHtml(source[p.b]) << "</pre></div></details>\n";
  }
  return html.str();
}

}  // namespace aula::grade
