#include "aula/grade/run_page.hpp"

#include "player_assets.hpp"

#include <aula/config/paths.hpp>

#include <aula/config/config.hpp>
#include <aula/grade/grade_plan.hpp>

#include <QByteArray>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace aula::grade {
namespace fs = std::filesystem;

namespace {

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace

std::string escapeHtml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

bool endsAPath(char c) {
  return std::isspace(static_cast<unsigned char>(c)) || std::string("'\"()<>,:;=[]{}\\`").find(c) != std::string::npos;
}

// "3 on CH, 1 on CH2" from {"CH": 3, "CH2": 1} (a count, or any value as JSON).
std::string countsText(const nlohmann::json& counts, const std::string& joiner) {
  std::string out;
  if (!counts.is_object()) return counts.dump();
  for (const auto& [name, count] : counts.items()) {
    out += (out.empty() ? "" : ", ") + (count.is_number() ? count.dump() : std::string("?")) + joiner + name;
  }
  return out;
}

}  // namespace

std::string withoutPaths(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    if (text[i] != '/' || (i > 0 && !endsAPath(text[i - 1]))) {
      out += text[i++];
      continue;
    }
    size_t end = i;
    while (end < text.size() && !endsAPath(text[end])) ++end;
    const size_t last = text.rfind('/', end - 1);
    out += last > i ? text.substr(last + 1, end - last - 1) : text.substr(i, end - i);  // "/x/y" -> "y"; "/x" stays
    i = end;
  }
  return out;
}

std::vector<Diagnostic> runDiagnostics(const nlohmann::json& r) {
  std::vector<Diagnostic> out;
  auto text = [&](const char* key) { return r.contains(key) && r[key].is_string() ? r[key].get<std::string>() : std::string(); };
  const std::string failure = text("failure");
  if (!failure.empty()) out.push_back({"failed", "the run failed: " + failure});
  const std::string fault = text("algorithm_error");
  if (!fault.empty() && fault != failure) out.push_back({"failed", "the algorithm failed: " + fault});
  const std::string aborted = text("aborted");
  if (!aborted.empty() && aborted != failure) out.push_back({"failed", "the run was aborted: " + aborted});
  if (r.contains("non_finite_commands") && r["non_finite_commands"].is_number() && r["non_finite_commands"].get<double>() > 0) {
    out.push_back({"non-finite commands", r["non_finite_commands"].dump() +
                                              " motor commands were not finite numbers (NaN or infinite): each was refused and 0 sent"});
  }
  if (r.contains("tampering")) {
    out.push_back({"tampering", "forged or refused messages (not graded; the run is flagged): " + countsText(r["tampering"], " on ")});
  }
  if (r.contains("escape_attempts")) {
    out.push_back({"escape", "tried to get out of the run (it went nowhere; the run is flagged): " +
                                 countsText(r["escape_attempts"], " x ")});
  }
  if (r.contains("truth_gaps")) {
    out.push_back({"lost messages", "messages the referee did not receive (it graded without them): " + countsText(r["truth_gaps"], " on ")});
  }
  if (r.contains("reloads") && r["reloads"].is_number() && r["reloads"].get<double>() > 0) {
    out.push_back({"reloaded", "the algorithm was reloaded " + r["reloads"].dump() + " time(s): the last episode was graded"});
  }
  const std::string other_run = text("not_the_seeds_run");
  if (!other_run.empty()) out.push_back({"not the graded run", "this run is not its seed's graded run (a headless run of it): " + other_run});
  if (r.value("finished", true) == false && failure.empty() && fault.empty() && aborted.empty()) {
    out.push_back({"ended early", "the run ended before the end of its episode"});
  }
  return out;
}

std::string diagnosticsHtml(const std::vector<Diagnostic>& diagnostics) {
  if (diagnostics.empty()) return "";
  std::string html = "<ul class='diagnostics'>";
  for (const Diagnostic& d : diagnostics) html += "<li>" + escapeHtml(d.text) + "</li>";
  return html + "</ul>";
}

namespace {

// The page around the player: its margins, the diagnostics, the still at its own size at most.
constexpr const char* kPageStyle =
    "body { font-family: sans-serif; margin: 12px; } h1 { font-size: 1.4em; overflow-wrap: anywhere; } "
    "ul.diagnostics { color: #b71c1c; overflow-wrap: anywhere; } img.still { max-width: 100%; height: auto; }";

}  // namespace

std::string dataUri(const std::string& mime, const std::string& bytes) {
  return "data:" + mime + ";base64," + QByteArray(bytes.data(), static_cast<int>(bytes.size())).toBase64().toStdString();
}

std::string noNetworkPolicy() {
  // 'self' for images and frames: report.html's still pictures and run pages are files beside it.
  return "<meta http-equiv='Content-Security-Policy' content=\"default-src 'none'; script-src 'unsafe-inline'; "
         "style-src 'unsafe-inline'; img-src data: 'self'; frame-src 'self'\">";
}

namespace {

constexpr const char* kTraceBlockOpen = "<script type='application/octet-stream' id='run-trace'>";

}  // namespace

std::string traceOfPage(const std::string& html) {
  const size_t open = html.find(kTraceBlockOpen);
  if (open == std::string::npos) return "";
  const size_t from = open + std::string(kTraceBlockOpen).size();
  const size_t end = html.find("</script>", from);
  if (end == std::string::npos) return "";
  const QByteArray b64 = QByteArray::fromBase64(QByteArray(html.data() + from, static_cast<int>(end - from)));
  return inflated(std::string(b64.constData(), static_cast<size_t>(b64.size())));
}

std::string traceOfRun(const std::string& stem) {
  std::string trace = readBytes(stem + ".trace.json");
  if (!trace.empty()) return trace;
  const std::string compact = readBytes(stem + ".trace.z");
  if (!compact.empty()) return inflated(compact);
  return traceOfPage(readBytes(stem + ".html"));
}

void keepOneTrace(const std::string& stem, bool page_has_it) {
  std::error_code error;
  const std::string json = readBytes(stem + ".trace.json");
  if (json.empty()) {
    if (page_has_it) fs::remove(stem + ".trace.z", error);  // the page's copy is the referee's: one is enough
    return;
  }
  if (page_has_it) {
    fs::remove(stem + ".trace.z", error);
  } else {
    config::writeFileAtomically(stem + ".trace.z", deflated(json), "the run's trace");
  }
  fs::remove(stem + ".trace.json", error);
}

RunFiles runFilesOf(const nlohmann::json& result) {
  RunFiles run;
  run.report = result;
  run.title = result.value("student_name", result.value("student", std::string("?"))) + ", " + fs::path(result.value("world", std::string("?"))).stem().string() +
              " seed " + std::to_string(result.value("seed", 0LL));
  if (!result.contains("log") || !result["log"].is_string()) return run;
  fs::path stem = result["log"].get<std::string>();
  stem.replace_extension();
  run.trace_json = traceOfRun(stem.string());
  run.picture_png = readBytes(stem.string() + ".png");
  if (!run.picture_png.empty()) run.picture_name = stem.filename().string() + ".png";
  return run;
}

namespace {

// The run's data blocks: `id`, the report as it is, and `id`-trace, the trace as the referee
// wrote it (byte for byte when the student's copy needed no change: the grade then keeps no other
// copy, traceOfPage reads it back), each deflated and base64. The page's player (player.js,
// compiled in: tools/grade/CMakeLists.txt) draws everything from them (the map, run-length
// encoded; the poses, delta-encoded mm and mrad at period_s; the exercise's state; the events;
// the breakdown's rows).
std::string runDataBlock(const std::string& id, const RunFiles& run) {
  if (run.trace_json.empty()) return "";
  auto block = [](const std::string& open, const std::string& bytes) {
    return open + QByteArray::fromStdString(deflated(bytes)).toBase64().toStdString() + "</script>\n";
  };
  return block("<script type='application/octet-stream' id='" + escapeHtml(id) + "'>", run.report.dump()) +
         block(id == "run" ? std::string(kTraceBlockOpen)
                           : "<script type='application/octet-stream' id='" + escapeHtml(id + "-trace") + "'>",
               run.trace_json);
}

// In report.html's frame, the page tells it how tall it is (report_html.cpp's message listener).
constexpr const char* kTellTheFrame =
    "if (window.parent !== window && window.ResizeObserver) {\n"
    "  new ResizeObserver(() => parent.postMessage({aulaPageHeight: document.documentElement.scrollHeight}, '*'))"
    ".observe(document.body);\n}\n";

}  // namespace

std::string runPageHtml(const RunFiles& given) {
  // The student's copy: the teacher's paths cut to file names, in the text and in the data.
  RunFiles run = given;
  run.report = nlohmann::json::parse(withoutPaths(given.report.dump()));
  run.report.erase("log");
  run.title = withoutPaths(given.title);
  run.trace_json = withoutPaths(given.trace_json);
  const nlohmann::json& r = run.report;
  const std::string exercise = r.value("exercise", std::string());
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang='en'><head><meta charset='utf-8'>"
       << "<meta name='viewport' content='width=device-width, initial-scale=1'>" << noNetworkPolicy() << "<title>Aula run: "
       << escapeHtml(run.title) << "</title><style>" << kPageStyle << kPlayerStyleCss << "</style></head><body>\n<h1>"
       << escapeHtml(run.title) << (exercise.empty() ? "" : ": " + escapeHtml(exercise)) << ", mark " << std::fixed;
  html.precision(2);
  html << r.value("mark", 0.0) << " / 10</h1>\n";
  // What the student handed in and what of it was graded, when the grade had to look for it.
  if (r.contains("hand_in") && r["hand_in"].is_string()) html << "<p class='hand-in'>" << escapeHtml(r["hand_in"].get<std::string>()) << "</p>\n";
  html << diagnosticsHtml(runDiagnostics(r));
  if (run.trace_json.empty()) {
    html << "<p>" << (r.contains("failure") ? "This run has no replay: it stopped before the referee could trace it (see above)."
                                            : "This run has no trace (the referee was not asked for one).")
         << (run.picture_png.empty() ? "" : " The referee's picture of its end is below.") << "</p>\n";
  } else {
    html << "<div id='player'>Opening the run...</div>\n" << runDataBlock("run", run);
  }
  if (!run.picture_png.empty() && !run.trace_json.empty() && !run.picture_name.empty()) {
    // The player draws the run's end: the picture stays the file beside the page, a link (not a
    // request when the page opens), rather than a third of the page again (issue 58).
    html << "<p><a href='" << escapeHtml(urlPath(run.picture_name)) << "'>The referee's picture at the end</a> (" << escapeHtml(run.picture_name)
         << ", beside this page)</p>\n";
  } else if (!run.picture_png.empty()) {
    html << "<h2>The referee's picture at the end</h2>\n<img class='still' alt='the referee&#39;s picture of the run' src='"
         << dataUri("image/png", run.picture_png) << "'>\n";
  }
  if (!run.trace_json.empty()) {
    html << "<script type='application/octet-stream' id='aula-player'>" << packedPlayerScript() << "</script>\n<script>\n" << kPlayerLoaderJs
         << "aulaLoadPlayer(() => AulaPlayer.followHash(() => AulaPlayer.openRun('run', document.getElementById('player'))));\n"
         << kTellTheFrame << "</script>\n";
  }
  html << "</body></html>\n";
  return html.str();
}

void writeRunPage(const std::string& html_path, const std::string& report_path, const std::string& trace_path,
                  const std::string& picture_path) {
  RunFiles run;
  try {
    run.report = nlohmann::json::parse(readBytes(report_path));
  } catch (const nlohmann::json::exception& e) {
    throw config::ConfigError(report_path + ": not a referee's report (" + e.what() + ")");
  }
  run.title = fs::path(run.report.value("world", std::string("?"))).stem().string() + " seed " +
              std::to_string(run.report.value("seed", 0LL));
  if (!trace_path.empty()) run.trace_json = readBytes(trace_path);
  if (!picture_path.empty()) run.picture_png = readBytes(picture_path);
  // Linked by name when it is beside the page, else inlined.
  if (!run.picture_png.empty() && fs::absolute(picture_path).parent_path() == fs::absolute(html_path).parent_path()) {
    run.picture_name = fs::path(picture_path).filename().string();
  }
  config::writeFileAtomically(html_path, runPageHtml(run), "the run's page");
}

}  // namespace aula::grade
