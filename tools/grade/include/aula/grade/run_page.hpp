#pragma once
// A run's player in the browser: from the referee's report, its trace (--trace, aula/referee/
// run_trace.hpp) and its picture, one self-contained HTML page (scripts, style and data inline,
// no network: a Content-Security-Policy forbids any request) with a <canvas> over the run's map
// (the robot's footprint and heading, its trail, the exercise's state building up), play/pause,
// speed 1x-100x, a time slider, the referee's events on a timeline (a click jumps there) and the
// mark's breakdown (each rubric term: its measure, points and points missed).
//
// The data of a run travels compressed (zlib's deflate, base64) in two <script type="application/
// octet-stream"> blocks (the report; the trace), decoded when the page opens. report.html shows a run's page in a frame,
// made when the run is opened, so a class page of 450 runs loads as fast as one without players. `page.html#t=SECONDS` opens the player paused at that
// sim time. The player writes what it shows into its status element's data-* attributes
// (data-t-s, data-robot-x-mm, data-robot-y-mm, data-robot-yaw-mrad, data-breakdown-sum,
// data-errors): what the browser tests read back.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace aula::grade {

// One thing a run's result says went wrong or was refused, besides its mark: `kind` for the class
// table ("failed", "non-finite commands", "tampering", "escape", "lost messages", "reloaded",
// "ended early"), `text` for people. Every page shows each one as text; report.html flags the run.
struct Diagnostic {
  std::string kind, text;
};
std::vector<Diagnostic> runDiagnostics(const nlohmann::json& result);
// The diagnostics as an HTML list (class 'diagnostics'), "" when there is none.
std::string diagnosticsHtml(const std::vector<Diagnostic>& diagnostics);
// `text` with each absolute path cut to its file name ("/home/t/out/runs/alice/x.log" -> "x.log"):
// what a student's page may say of the teacher's machine.
std::string withoutPaths(const std::string& text);

struct RunFiles {
  std::string title;        // "alice, vacuum seed 3"
  nlohmann::json report;    // the run's result (the referee's report and who ran it)
  std::string trace_json;   // "" when the run has no trace: the page shows the still picture only
  std::string picture_png;  // the referee's picture, "" when there is none
  std::string picture_name;  // its file's name beside the page ("vacuum-seed1.png"), "" when not there
};

// A run's files beside its result: its trace (traceOfRun) and <stem>.png, where <stem> is the
// result's "log" without its extension (runs/<student>/<world>-seed<k>).
RunFiles runFilesOf(const nlohmann::json& result);

// One copy of each trace (docs/grading.md, "How big a class is"): the referee writes
// <stem>.trace.json; once the run's page embeds it byte for byte, the grade keeps no other copy,
// and when the student's page had to change it (a text withheld, a path cut) it keeps the
// referee's as <stem>.trace.z (zlib). traceOfRun reads whichever there is, in that order:
// <stem>.trace.json, <stem>.trace.z, the page's trace block; "" when none.
std::string traceOfRun(const std::string& stem);
// The trace block of a run page's HTML (runPageHtml), inflated: the referee's trace as the page
// holds it; "" when the page has none.
std::string traceOfPage(const std::string& html);
// After <stem>.html is written: <stem>.trace.json removed, kept as <stem>.trace.z unless
// `page_has_it` (the page holds the referee's trace byte for byte).
void keepOneTrace(const std::string& stem, bool page_has_it);
// zlib's deflate of `bytes` (a zlib stream: what the browser's DecompressionStream('deflate')
// reads), and back ("" when `zlib` is not such a stream).
std::string deflated(const std::string& bytes);
std::string inflated(const std::string& zlib);
// The referee's PNG `png` with its pixels (the same filtered rows) deflated at zlib's level 9 in
// one IDAT, its other chunks as they were; `png` itself when that is not smaller or it is not a
// PNG this reads. The grade writes each run's picture so before its page inlines it.
std::string smallerPng(const std::string& png);
// The picture `png` in at most 256 colours, as a palette PNG a third of its size: each pixel the
// nearest of the picture's 256 most frequent colours (beyond them are a few hundred pixels of
// anti-aliased edges' blends); `png` itself when that is not smaller or it is not an opaque PNG.
std::string palettePng(const std::string& png);
// The player's script (player.js with the exercises' drawings), deflated and base64, as the
// page's 'aula-player' block holds it for player_loader.js.
std::string packedPlayerScript();
// "%2F" for '/', and so on: a relative link whose names came from the students' folders.
std::string urlPath(const std::string& path);

// The per-run page (`runs/<student>/<world>-seed<k>.html`, `aula run --report-html`), for the
// student: no absolute path of the teacher's machine in it (withoutPaths).
std::string runPageHtml(const RunFiles& run);
// `aula run --report-html=FILE.html`: the page of a single run from the referee's files (the trace
// and the picture may be "" or missing: the page then has no player, or no still picture).
// Throws config::ConfigError naming a report that cannot be read, or a page that cannot be written.
void writeRunPage(const std::string& html_path, const std::string& report_path, const std::string& trace_path,
                  const std::string& picture_path);

// The page's Content-Security-Policy <meta>: inline scripts and styles; images inline (data:) or
// beside the page, and frames beside the page ('self': report.html's still pictures and the runs'
// own pages it shows in a frame; on a file:// page, files only); nothing else.
std::string noNetworkPolicy();
// Text for HTML: & < > " ' escaped.
std::string escapeHtml(const std::string& text);
// `bytes` as a data: URI of `mime`.
std::string dataUri(const std::string& mime, const std::string& bytes);

}  // namespace aula::grade
