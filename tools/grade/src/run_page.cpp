#include "aula/grade/run_page.hpp"

#include "player_assets.hpp"

#include <aula/config/paths.hpp>

#include <aula/config/config.hpp>
#include <aula/grade/grade_plan.hpp>

#include <QByteArray>

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



}  // namespace

std::string dataUri(const std::string& mime, const std::string& bytes) {
  return "data:" + mime + ";base64," + QByteArray(bytes.data(), static_cast<int>(bytes.size())).toBase64().toStdString();
}

std::string noNetworkPolicy() {
  return "<meta http-equiv='Content-Security-Policy' content=\"default-src 'none'; script-src 'unsafe-inline'; "
         "style-src 'unsafe-inline'; img-src data:\">";
}

RunFiles runFilesOf(const nlohmann::json& result) {
  RunFiles run;
  run.report = result;
  run.title = result.value("student", std::string("?")) + ", " + fs::path(result.value("world", std::string("?"))).stem().string() +
              " seed " + std::to_string(result.value("seed", 0LL));
  if (!result.contains("log") || !result["log"].is_string()) return run;
  fs::path stem = result["log"].get<std::string>();
  stem.replace_extension();
  run.trace_json = readBytes(stem.string() + ".trace.json");
  run.picture_png = readBytes(stem.string() + ".png");
  return run;
}

// The player's style and script, player.css and player.js beside this file, compiled in
// (tools/grade/CMakeLists.txt): everything the player draws comes from the trace (the map,
// run-length encoded; the poses, delta-encoded mm and mrad at period_s; the exercise's state; the events).
std::string playerStyle() { return kPlayerStyleCss; }
std::string playerScript() { return kPlayerScriptJs; }

std::string runDataBlock(const std::string& id, const RunFiles& run) {
  if (run.trace_json.empty()) return "";
  // The report as it is, the trace as the referee wrote it: one JSON object, deflated.
  const std::string payload = "{\"report\": " + run.report.dump() + ", \"trace\": " + run.trace_json + "}";
  QByteArray packed = qCompress(QByteArray(payload.data(), static_cast<int>(payload.size())), 9);
  packed.remove(0, 4);  // qCompress's length prefix: the rest is a zlib stream ("deflate" to a browser)
  return "<script type='application/octet-stream' id='" + escapeHtml(id) + "'>" + packed.toBase64().toStdString() +
         "</script>\n";
}

std::string runPageHtml(const RunFiles& run) {
  const nlohmann::json& r = run.report;
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang='en'><head><meta charset='utf-8'>" << noNetworkPolicy() << "<title>Aula run: "
       << escapeHtml(run.title) << "</title><style>body { font-family: sans-serif; margin: 20px; }" << kPlayerStyleCss
       << "</style></head><body>\n<h1>" << escapeHtml(run.title) << ": " << escapeHtml(r.value("exercise", std::string("?")))
       << ", mark " << std::fixed;
  html.precision(2);
  html << r.value("mark", 0.0) << " / 10</h1>\n";
  if (r.contains("failure")) html << "<p class='missed'>" << escapeHtml(r["failure"].get<std::string>()) << "</p>\n";
  if (run.trace_json.empty()) {
    html << "<p>This run has no trace (the referee was not asked for one): its still picture only.</p>\n";
  } else {
    html << "<div id='player'>Opening the run...</div>\n" << runDataBlock("run", run);
  }
  if (!run.picture_png.empty()) {
    html << "<h2>The referee's picture at the end</h2>\n<img alt='the referee&#39;s picture of the run' src='"
         << dataUri("image/png", run.picture_png) << "'>\n";
  }
  html << "<script>" << kPlayerScriptJs << "</script>\n";
  if (!run.trace_json.empty()) {
    html << "<script>\nAulaPlayer.openRun('run', document.getElementById('player')).then(p => {\n"
            "  const t = AulaPlayer.hashTime();\n  if (t !== null) p.seek(t);\n});\n</script>\n";
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
  config::writeFileAtomically(html_path, runPageHtml(run), "the run's page");
}

}  // namespace aula::grade
