// The run's player in a real browser: headless Chromium loads a run's page (and the class
// page) made from real runs' reports, traces and pictures (`aula run --trace`), on the runs where
// a page is hardest to get right: an Autopark car that did not park, one with contacts, a vacuum
// whose algorithm sends NaN commands, a C++ crash, a Python exception, a vacuum on a rescaled
// rubric (what a calibration sets), and TeleTaxi. For each page:
//   - no console message (no error, no blocked request: the page's policy forbids any network
//     request, and Chromium logs each it blocks) and no resource loaded;
//   - the breakdown's total (its rows, top to bottom) is the report's mark;
//   - every diagnostic of the result (run_page.hpp's runDiagnostics) and every event is text in it;
//   - a probe script added to a copy of the page plays it through every event: the mark panel
//     stays where it was; the event list keeps the current event in view; Space, the arrows, N and
//     P do what the keys line says; at 400 px wide nothing scrolls sideways;
//   - after seeking to a recorded event's time the robot is where the trace says.
#include "test_support.hpp"

#include <aula/supervision/run_recorder.hpp>

#include <aula/grade/grades.hpp>
#include <aula/grade/report_html.hpp>
#include <aula/grade/run_page.hpp>
#include <aula/process/child_process.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

using namespace std::chrono_literals;
using aula::testing::readFile;
namespace fs = std::filesystem;

namespace {

const std::string kBin = AULA_BIN_DIR;

struct GradedRun {
  std::string dir, stem;  // the run's files: stem.json (the result), .trace.json, .png, .log
  nlohmann::json result, trace;
};

// `aula run` of one exercise with its report, picture and trace; `ok`: it exits 0 (a fault does not).
GradedRun makeRun(const std::string& student, const std::vector<std::string>& run_args, bool ok = true) {
  GradedRun run;
  run.dir = aula::testing::privateDir();
  const std::string world = run_args.front() == "teletaxi" ? "cityLarge" : run_args.front();
  run.stem = run.dir + "/runs/" + student + "/" + world + "-seed1";
  fs::create_directories(fs::path(run.stem).parent_path());
  std::vector<std::string> args = {kBin + "/aula", "run"};
  args.insert(args.end(), run_args.begin(), run_args.end());
  args.insert(args.end(), {"--headless", "--seed=1", "--report=" + run.stem + ".report.json", "--picture=" + run.stem + ".png",
                           "--trace=" + run.stem + ".trace.json", "--lcm-url=" + aula::testing::privateLcmUrl()});
  const auto out = aula::testing::runToEnd(args, 200s);
  if (ok) {
    EXPECT_EQ(out.code.value_or(-1), 0) << out.output;
  }
  run.result = nlohmann::json::parse(readFile(run.stem + ".report.json"));
  run.result["student"] = student;
  run.result["log"] = run.stem + ".log";
  // As aula grade's result says why a run failed (grade_runner's resultOf).
  for (const char* why : {"algorithm_error", "aborted"}) {
    if (!run.result.contains("failure") && run.result.contains(why)) run.result["failure"] = run.result[why];
  }
  std::ofstream(run.stem + ".json") << run.result.dump(2) << "\n";
  run.trace = nlohmann::json::parse(readFile(run.stem + ".trace.json"));
  return run;
}

// A time in the URL: enough digits to land on the event's time.
std::string urlTime(double t_s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", t_s);
  return text;
}

struct Page {
  std::string dom, console;  // the DOM after the budget, Chromium's log
};

// Headless Chromium, a fresh profile, nothing in the background: the DOM once `url` settled.
// `frames`: the page's frames are readable from it (--allow-file-access-from-files: file:// pages
// are otherwise each their own origin), so a probe can read the player in report.html's frame.
Page loadInChromium(const std::string& url, int width_px = 1280, bool frames = false) {
  const std::string profile = aula::testing::privateDir();
  const auto out = aula::testing::runToEnd(
      {"/usr/bin/chromium", "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
       "--disable-component-update", "--disable-sync", "--no-first-run", "--user-data-dir=" + profile,
       "--enable-logging=stderr", "--v=0", "--window-size=" + std::to_string(width_px) + ",900", "--hide-scrollbars",
       frames ? "--allow-file-access-from-files" : "--disable-extensions", "--virtual-time-budget=10000", "--dump-dom", url},
      90s);
  EXPECT_EQ(out.code.value_or(-1), 0) << out.output.substr(0, 3000);
  Page page;
  // runToEnd puts stderr first, then stdout (the DOM).
  const auto html = out.output.find("<html");
  page.dom = html == std::string::npos ? "" : out.output.substr(html);
  page.console = out.output.substr(0, html == std::string::npos ? out.output.size() : html);
  fs::remove_all(profile);
  return page;
}

// The player's status element's data-* attribute `name` (data-robot-x-mm...).
std::string attribute(const std::string& dom, const std::string& name) {
  std::smatch m;
  if (!std::regex_search(dom, m, std::regex("data-" + name + "=\"([^\"]*)\""))) return "";
  return m[1];
}

// Every console line Chromium logged for the page: errors, warnings, blocked requests.
std::vector<std::string> consoleLines(const std::string& log) {
  std::vector<std::string> lines;
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);) {
    if (line.find(":CONSOLE") != std::string::npos) lines.push_back(line);
  }
  return lines;
}

std::vector<long long> undelta(const nlohmann::json& deltas) {
  std::vector<long long> out;
  long long v = 0;
  for (const auto& d : deltas) out.push_back(v += d.get<long long>());
  return out;
}

// Where the trace puts the robot at `t_s` (linear between its samples, then towards the last
// pose graded, its "final", as the player draws it).
std::pair<double, double> tracedPosition(const nlohmann::json& trace, double t_s) {
  const auto xs = undelta(trace["samples"]["x_mm"]), ys = undelta(trace["samples"]["y_mm"]);
  const double period = trace["samples"]["period_s"].get<double>();
  const double last = (xs.size() - 1) * period;
  const nlohmann::json& fin = trace["final"];
  if (t_s > last && fin["traced"].get<bool>() && fin["t_s"].get<double>() > last + 1e-9) {
    const double b = std::min(1.0, (t_s - last) / (fin["t_s"].get<double>() - last));
    return {xs.back() + b * (1000 * fin["pose"][0].get<double>() - xs.back()), ys.back() + b * (1000 * fin["pose"][1].get<double>() - ys.back())};
  }
  const double f = std::clamp(t_s / period, 0.0, static_cast<double>(xs.size() - 1));
  const size_t i = static_cast<size_t>(std::floor(f)), j = std::min(i + 1, xs.size() - 1);
  const double a = f - i;
  return {xs[i] + a * (xs[j] - xs[i]), ys[i] + a * (ys[j] - ys[i])};
}

const nlohmann::json& eventOf(const nlohmann::json& trace, const std::vector<std::string>& kinds) {
  for (const std::string& kind : kinds) {
    for (const auto& e : trace["events"]) {
      if (e["kind"] == kind && e.contains("x_mm")) return e;
    }
  }
  ADD_FAILURE() << "no placed event of the kinds asked for in the trace";
  static const nlohmann::json none = {{"t_s", 0.0}, {"x_mm", 0}, {"y_mm", 0}};
  return none;
}

// Added to a copy of a page: once a player is built (the first one in the page, or in the page's
// frame: report.html shows a run's own page in one), it copies the player's status (data-t-s...)
// into <div id='mirror'> of the page, then plays the run through every event (seeking just before
// and after each) and records where the mark panel was, whether the event list kept the current
// event in view, what the keys did, how wide the page (and the frame) are, and where a new #t=
// took the player; all into <body data-probe='JSON'>.
const char* kProbe = R"JS(
(() => {
  const out = {};
  const rect = e => {
    const w = e.ownerDocument.defaultView, r = e.getBoundingClientRect();
    return [r.left + w.scrollX, r.top + w.scrollY, r.width, r.height].map(Math.round).join(',');
  };
  function probe(p) {
    const doc = p.root.ownerDocument;
    const key = (k, shift) => doc.dispatchEvent(new KeyboardEvent('keydown', {key: k, shiftKey: !!shift, bubbles: true}));
    const panel = p.root.querySelector('.mark-panel');
    const rects = new Set();
    let followed = true;
    const look = () => {
      rects.add(rect(panel));
      const now = p.eventBox.querySelector('tr.now');
      if (now) {
        const b = p.eventBox.getBoundingClientRect(), r = now.getBoundingClientRect();
        followed = followed && r.top >= b.top - 1 && r.bottom <= b.bottom + 1;
      }
    };
    p.seek(0); look();
    for (const e of p.events) { p.seek(e.t_s - 0.05); look(); p.seek(e.t_s + 0.05); look(); }
    p.seek(p.end); look();
    out.panel = [...rects];
    out.followed = followed;
    const wide = d => [d.documentElement.scrollWidth, d.documentElement.clientWidth];
    out.width = wide(document);
    out.frameWidth = wide(doc);
    p.seek(0);
    key(' '); out.spacePlays = p.playing; key(' '); out.spacePauses = !p.playing;
    out.playingAfterPause = p.status.dataset.playing;
    const base = p.end / 2;
    p.seek(base); key('ArrowRight'); out.right = p.time - base;
    p.seek(base); key('ArrowLeft'); out.left = p.time - base;
    p.seek(base); key('ArrowRight', true); out.shiftRight = p.time - base;
    // Once the time slider was touched, the arrows still step 1 s (Shift 10 s), not the slider's 1 %.
    const slide = (k, shift) => p.slider.dispatchEvent(new KeyboardEvent('keydown', {key: k, shiftKey: !!shift, bubbles: true}));
    p.slider.focus();
    p.seek(base); slide('ArrowRight'); out.sliderRight = p.time - base;
    p.seek(base); slide('ArrowLeft', true); out.sliderShiftLeft = p.time - base;
    p.slider.blur();
    p.seek(0); key('n'); out.n = p.time; key('n'); out.n2 = p.time; key('p'); out.p = p.time;
    out.end = p.end;
    // Every layer the run has, switched on, drawn mid-run: what its switches and notes say.
    out.layerSwitches = [...p.root.querySelectorAll('.layers input')].map(b => b.className);
    p.showLayers(['laser', 'belief', 'plan', 'console']);
    p.seek(p.end / 2);
    out.layerNote = p.layerNote.textContent;
    out.consoleNow = p.root.querySelectorAll('.console-box .line.now').length;
    out.consoleShown = !!p.consolePart && !p.consolePart.hidden;
    p.showLayers([]);
    out.consoleHidden = !p.consolePart || p.consolePart.hidden;
    p.seek(0);
  }
  const playerIn = d => { const c = d && d.querySelector('.player'); return c && c.player; };
  const wait = () => {
    const frame = document.querySelector('iframe');
    let p = playerIn(document);
    try { p = p || playerIn(frame && frame.contentDocument); } catch (e) { out.frameError = String(e); }
    if (!p) { setTimeout(wait, 20); return; }
    const mirror = document.createElement('div');
    mirror.id = 'mirror';
    Object.assign(mirror.dataset, p.status.dataset);
    document.body.appendChild(mirror);
    try { probe(p); } catch (e) { out.error = String(e); }
    // A new #t= on the open page moves the player there.
    const asked = Math.round(p.end * 0.25 * 1000) / 1000;
    const rest = location.hash.replace(/&?t=[0-9.]+/, '');
    location.hash = (rest && rest !== '#' ? rest + '&' : '#') + 't=' + asked;
    setTimeout(() => { out.hashAsked = asked; out.hashTime = p.time; document.body.dataset.probe = JSON.stringify(out); }, 300);
  };
  wait();
})();
)JS";

// `page` with the probe before its </body>, as `probed`.
void writeProbed(const std::string& page, const std::string& probed) {
  std::string html = readFile(page);
  const auto end = html.rfind("</body>");
  ASSERT_NE(end, std::string::npos);
  html.insert(end, std::string("<script>") + kProbe + "</script>\n");
  std::ofstream(probed) << html;
}

nlohmann::json probeOf(const std::string& dom) {
  std::smatch m;
  if (!std::regex_search(dom, m, std::regex("data-probe=\"([^\"]*)\""))) return nullptr;
  std::string text = m[1];
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"&quot;", "\""}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}}) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
  }
  return nlohmann::json::parse(text);
}

// Text as Chromium's DOM dump writes it in a text node: & < > escaped, quotes as they are.
std::string asDomText(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : std::string(1, c);
  return out;
}

// The distinct event times after `t_s`, in order.
std::vector<double> eventTimesAfter(const nlohmann::json& trace, double t_s) {
  std::vector<double> times;
  for (const auto& e : trace["events"]) times.push_back(e["t_s"].get<double>());
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end(), [](double a, double b) { return std::abs(a - b) < 1e-6; }), times.end());
  times.erase(times.begin(), std::find_if(times.begin(), times.end(), [&](double t) { return t > t_s + 1e-6; }));
  return times;
}

// The page at 1280 px and at 400 px, probed: every number, diagnostic and event, the layout, the
// keys. `hash`: what opens the run's player in it ("" for a run's own page; report.html's
// "#run=ID": its frame). Returns the DOM at 1280 px (its #mirror: the player's status as it opened).
std::string expectAGoodPage(const GradedRun& run, const std::string& page_path, const std::string& hash = "") {
  const std::string probed = page_path + ".probed.html";
  writeProbed(page_path, probed);
  std::string first_dom;
  for (const int width : {1280, 400}) {
    SCOPED_TRACE("at " + std::to_string(width) + " px: " + page_path);
    const Page page = loadInChromium("file://" + probed + hash, width, !hash.empty());
    if (first_dom.empty()) first_dom = page.dom;
    if (page.dom.empty()) ADD_FAILURE() << page.console;
    EXPECT_TRUE(consoleLines(page.console).empty()) << "a console message (an error, a blocked request):\n" << page.console;
    EXPECT_EQ(attribute(page.dom, "errors"), "0") << attribute(page.dom, "error-text");
    EXPECT_EQ(attribute(page.dom, "resources"), "0") << "the page loads nothing";
    if (attribute(page.dom, "breakdown-sum").empty()) {
      ADD_FAILURE() << "the player was built\n" << page.dom.substr(0, 3000);
      continue;
    }
    EXPECT_NEAR(std::stod(attribute(page.dom, "breakdown-sum")), run.result["mark"].get<double>(), 1e-3);
    EXPECT_EQ(page.dom.find("class=\"missed mismatch\""), std::string::npos) << "the page says its rows do not make the mark";
    for (const auto& d : aula::grade::runDiagnostics(run.result)) {
      EXPECT_NE(page.dom.find(asDomText(aula::grade::withoutPaths(d.text))), std::string::npos) << "diagnostic missing: " << d.text;
    }
    for (const auto& e : run.trace["events"]) {
      if (!hash.empty()) break;  // in the frame: its own page, checked on its own
      EXPECT_NE(page.dom.find(asDomText(aula::grade::withoutPaths(e["text"].get<std::string>()))), std::string::npos) << e.dump();
    }
    const nlohmann::json probe = probeOf(page.dom);
    if (!probe.is_object()) {
      ADD_FAILURE() << "the probe ran";
      continue;
    }
    EXPECT_FALSE(probe.contains("error")) << probe.dump();
    EXPECT_EQ(probe["panel"].size(), 1u) << "the mark panel moved while playing through the events: " << probe["panel"].dump();
    EXPECT_TRUE(probe["followed"].get<bool>()) << "the event list lost the current event";
    EXPECT_LE(probe["width"][0].get<int>(), probe["width"][1].get<int>()) << "the page scrolls sideways: " << probe["width"].dump();
    EXPECT_LE(probe["frameWidth"][0].get<int>(), probe["frameWidth"][1].get<int>()) << "the frame scrolls sideways";
    EXPECT_NEAR(probe["hashTime"].get<double>(), probe["hashAsked"].get<double>(), 1e-6) << "#t= on an open page";
    EXPECT_TRUE(probe["spacePlays"].get<bool>());
    EXPECT_TRUE(probe["spacePauses"].get<bool>());
    const double end = probe["end"].get<double>(), base = end / 2;
    EXPECT_NEAR(probe["right"].get<double>(), std::min(1.0, end - base), 1e-6);
    EXPECT_NEAR(probe["left"].get<double>(), -std::min(1.0, base), 1e-6);
    EXPECT_NEAR(probe["shiftRight"].get<double>(), std::min(10.0, end - base), 1e-6);
    EXPECT_NEAR(probe["sliderRight"].get<double>(), std::min(1.0, end - base), 1e-6) << "the arrows on the slider";
    EXPECT_NEAR(probe["sliderShiftLeft"].get<double>(), -std::min(10.0, base), 1e-6) << "Shift and an arrow on the slider";
    EXPECT_EQ(probe["playingAfterPause"], "no") << "the status says a paused player plays";
    const auto after = eventTimesAfter(run.trace, 0.0);
    if (after.size() >= 2) {
      EXPECT_NEAR(probe["n"].get<double>(), after[0], 1e-6);
      EXPECT_NEAR(probe["n2"].get<double>(), after[1], 1e-6);
      EXPECT_NEAR(probe["p"].get<double>(), after[0], 1e-6);
    }
  }
  // No path of the teacher's machine in a student's page.
  if (hash.empty()) {
    EXPECT_EQ(readFile(page_path).find(run.dir), std::string::npos) << "the page names " << run.dir;
  }
  return first_dom;
}

// `from_files`: the page as `aula run --report-html` makes it (writeRunPage, from the referee's
// files), else as `aula grade` does (from the run's result). Checks the page, then the robot at
// the first event of `kinds`.
void expectPlayerAtEvent(const GradedRun& run, const std::vector<std::string>& kinds, bool from_files = false) {
  const std::string page_path = run.stem + ".html";
  if (from_files) {
    aula::grade::writeRunPage(page_path, run.stem + ".report.json", run.stem + ".trace.json", run.stem + ".png");
  } else {
    std::ofstream(page_path) << aula::grade::runPageHtml(aula::grade::runFilesOf(run.result));
  }
  if (!from_files) expectAGoodPage(run, page_path);
  const nlohmann::json& event = eventOf(run.trace, kinds);
  const double t_s = event["t_s"].get<double>();
  const Page page = loadInChromium("file://" + page_path + "#t=" + urlTime(t_s));
  ASSERT_FALSE(page.dom.empty()) << page.console;
  EXPECT_TRUE(consoleLines(page.console).empty()) << page.console;
  ASSERT_FALSE(attribute(page.dom, "t-s").empty()) << "the player was built\n" << page.dom.substr(0, 3000);
  EXPECT_NEAR(std::stod(attribute(page.dom, "t-s")), t_s, 1e-3);
  const auto [x_mm, y_mm] = tracedPosition(run.trace, t_s);
  EXPECT_NEAR(std::stod(attribute(page.dom, "robot-x-mm")), x_mm, 1.0);
  EXPECT_NEAR(std::stod(attribute(page.dom, "robot-y-mm")), y_mm, 1.0);
  // ... and that is where the referee saw the event, within what the robot drives in a sample.
  EXPECT_NEAR(std::stod(attribute(page.dom, "robot-x-mm")), event["x_mm"].get<double>(), 150.0) << event.dump();
  EXPECT_NEAR(std::stod(attribute(page.dom, "robot-y-mm")), event["y_mm"].get<double>(), 150.0) << event.dump();
  EXPECT_NEAR(std::stod(attribute(page.dom, "breakdown-sum")), run.result["mark"].get<double>(), 1e-3);
  EXPECT_NE(page.dom.find("<canvas"), std::string::npos);
}

// A browser without DecompressionStream: the page says so where the player would be, quietly.
void expectAMessageWithoutDecompression(const std::string& page_path) {
  std::string html = readFile(page_path);
  const auto body = html.find("<body>");
  ASSERT_NE(body, std::string::npos);
  html.insert(body + 6, "<script>window.DecompressionStream = undefined;</script>");
  std::ofstream(page_path + ".old-browser.html") << html;
  const Page page = loadInChromium("file://" + page_path + ".old-browser.html");
  EXPECT_NE(page.dom.find("This browser cannot play the run: it lacks DecompressionStream"), std::string::npos)
      << page.dom.substr(0, 2000);
  EXPECT_TRUE(consoleLines(page.console).empty()) << page.console;
}

bool hasEvent(const nlohmann::json& trace, const std::string& kind) {
  for (const auto& e : trace["events"]) {
    if (e["kind"] == kind) return true;
  }
  return false;
}

}  // namespace

TEST(RunPage, VacuumPlayerInChromium) {
  const GradedRun run = makeRun("alice", {"vacuum", "--algorithm=reference", "--Vacuum.Referee.Duration=300"});
  expectPlayerAtEvent(run, {"bump", "stuck", "mark", "end"});
}

// A rescaled rubric, as a world's calibration sets it (a 5 at 3 %, a 10 at 9 %).
TEST(RunPage, VacuumOnARescaledRubric) {
  const GradedRun run = makeRun("amy", {"vacuum", "--algorithm=reference", "--Vacuum.Referee.Duration=60",
                                        "--Vacuum.Referee.HalfMarkCoverage=3", "--Vacuum.Referee.FullMarkCoverage=9"});
  EXPECT_NE(run.trace["breakdown"][0]["measure"].get<std::string>().find("a 10 at 9 %"), std::string::npos) << run.trace["breakdown"];
  expectPlayerAtEvent(run, {"bump", "stuck", "mark", "end"});
}

TEST(RunPage, VacuumNanCommandsAreAnEventAndADiagnostic) {
  const GradedRun run = makeRun("nina", {"vacuum", "--algorithm=" AULA_PLUGIN_NAN_COMMANDS, "--Vacuum.Referee.Duration=20"});
  ASSERT_GT(run.result.value("non_finite_commands", 0), 0) << run.result.dump(2);
  EXPECT_TRUE(hasEvent(run.trace, "non-finite")) << run.trace["events"].dump();
  expectAGoodPage(run, [&] {
    std::ofstream(run.stem + ".html") << aula::grade::runPageHtml(aula::grade::runFilesOf(run.result));
    return run.stem + ".html";
  }());
}

TEST(RunPage, ACppCrashIsInThePage) {
  const GradedRun run = makeRun("carl", {"vacuum", "--algorithm=" AULA_PLUGIN_SEGFAULT, "--Vacuum.Referee.Duration=20"}, false);
  ASSERT_TRUE(run.result.contains("aborted") || run.result.contains("algorithm_error")) << run.result.dump(2);
  std::ofstream(run.stem + ".html") << aula::grade::runPageHtml(aula::grade::runFilesOf(run.result));
  expectAGoodPage(run, run.stem + ".html");
}

TEST(RunPage, APythonExceptionIsInThePage) {
  const GradedRun run = makeRun("pia", {"vacuum", "--algorithm=" AULA_TEST_DATA_DIR "/python/raises/MyAlgorithm.py",
                                        "--Vacuum.Referee.Duration=20"}, false);
  ASSERT_TRUE(run.result.contains("algorithm_error")) << run.result.dump(2);
  EXPECT_TRUE(hasEvent(run.trace, "fault")) << run.trace["events"].dump();
  std::ofstream(run.stem + ".html") << aula::grade::runPageHtml(aula::grade::runFilesOf(run.result));
  expectAGoodPage(run, run.stem + ".html");
  expectAMessageWithoutDecompression(run.stem + ".html");
}

TEST(RunPage, TeleTaxiPlayerInChromium) {
  const GradedRun run = makeRun("bob", {"teletaxi", "--algorithm=reference"});
  expectPlayerAtEvent(run, {"arrival", "bump", "end"});
}

TEST(RunPage, AutoparkPlayerInChromium) {
  const GradedRun run = makeRun("carol", {"autopark", "--algorithm=reactive", "--Simulator.StartPose.car=-7,-1.5,0"});
  ASSERT_GE(run.result["collisions"].get<long>(), 1) << "the seek goes to a contact";
  expectPlayerAtEvent(run, {"contact", "parked", "end"}, true);
  expectPlayerAtEvent(run, {"contact", "parked", "end"});
}

// Not parked: the rubric's rule gives the mark (1.00 x the contacts' factor), whatever the terms;
// the breakdown says so in a row of its own and its total is the mark.
TEST(RunPage, AutoparkNotParked) {
  const GradedRun run = makeRun("dora", {"autopark", "--algorithm=reactive", "--Autopark.Referee.Timeout=12"});
  ASSERT_FALSE(run.result["parked"].get<bool>()) << run.result.dump(2);
  EXPECT_NEAR(run.result["mark"].get<double>(), 1.0 * (1.0 - run.result["contact_cost"].get<double>()), 1e-9);
  expectPlayerAtEvent(run, {"end"});
}

// The class page: it loads as it is (no player built, no data decoded), then `#run=ID&t=` opens
// one run's player lazily, there.
TEST(RunPage, ClassPageOpensARunLazily) {
  const GradedRun run = makeRun("dave", {"vacuum", "--algorithm=reference", "--Vacuum.Referee.Duration=120"});
  const std::string out_dir = run.dir;
  const std::string referees = readFile(run.stem + ".trace.json");
  aula::grade::collect(out_dir);
  EXPECT_TRUE(fs::exists(run.stem + ".html")) << "collect writes the run's own page";
  // One copy of the trace: the page's, the referee's bytes (read back as they were written).
  EXPECT_FALSE(fs::exists(run.stem + ".trace.json"));
  EXPECT_FALSE(fs::exists(run.stem + ".trace.z")) << "the page holds the referee's trace as it is: no other copy";
  EXPECT_EQ(aula::grade::traceOfPage(readFile(run.stem + ".html")), referees);
  EXPECT_EQ(aula::grade::traceOfRun(run.stem), referees);
  aula::grade::collect(out_dir);  // again (--collect): the pages are made again from their own copies
  EXPECT_EQ(aula::grade::traceOfRun(run.stem), referees);
  EXPECT_FALSE(fs::exists(run.stem + ".trace.z"));
  const std::string report = out_dir + "/report.html";
  {
    const Page page = loadInChromium("file://" + report);
    EXPECT_TRUE(consoleLines(page.console).empty()) << page.console;
    EXPECT_EQ(attribute(page.dom, "t-s"), "") << "no player is built before a run is opened";
    EXPECT_NE(page.dom.find("Flagged runs (0)"), std::string::npos);
  }
  // #run=ID&t=: that run's own page in a frame, its player there; the run's page is probed in the
  // frame, with the class page's style around it.
  const nlohmann::json& event = eventOf(run.trace, {"bump", "stuck", "mark", "end"});
  const double t_s = event["t_s"].get<double>();
  const std::string dom = expectAGoodPage(run, report, "#run=dave/vacuum-seed1&t=" + urlTime(t_s));
  ASSERT_FALSE(attribute(dom, "t-s").empty()) << dom.substr(0, 2000);
  EXPECT_NEAR(std::stod(attribute(dom, "t-s")), t_s, 1e-3);
  const auto [x_mm, y_mm] = tracedPosition(run.trace, t_s);
  EXPECT_NEAR(std::stod(attribute(dom, "robot-x-mm")), x_mm, 1.0);
  EXPECT_NEAR(std::stod(attribute(dom, "robot-y-mm")), y_mm, 1.0);
  EXPECT_NE(dom.find("<iframe class=\"player-frame\""), std::string::npos);
  EXPECT_LT(fs::file_size(report), 200u * 1024u) << "no run's data in the class page: each run's page has it";
}

// The class report read on a phone and on a desk: a long failure (a traceback) is a readable cell
// (at least 150 px wide at 1280 px, its beginning shown and the whole on demand), and the
// histograms keep every bin's label inside them at 400 px.
TEST(RunPage, ClassReportFailuresAndHistogramsAreReadable) {
  const GradedRun run = makeRun("dave", {"vacuum", "--algorithm=reference", "--Vacuum.Referee.Duration=20"});
  nlohmann::json failed = run.result;  // a classmate whose run failed with a long traceback
  failed["student"] = "erin";
  std::string traceback = "MyAlgorithm.py:12: ValueError: boom (traceback, most recent call last:";
  for (int i = 0; i < 12; ++i) traceback += " MyAlgorithm.py:" + std::to_string(20 + i) + " in step_" + std::to_string(i) + ": `x = y[" + std::to_string(i) + "]`;";
  failed["failure"] = traceback + ")";
  failed["log"] = run.dir + "/runs/erin/vacuum-seed1.log";
  fs::create_directories(run.dir + "/runs/erin");
  std::ofstream(run.dir + "/runs/erin/vacuum-seed1.json") << failed.dump(2) << "\n";
  aula::grade::collect(run.dir);
  const std::string report = run.dir + "/report.html", probed = run.dir + "/report.probed.html";
  std::string html = readFile(report);
  ASSERT_NE(html.find("<details><summary>MyAlgorithm.py:12: ValueError: boom"), std::string::npos) << "the beginning shown";
  html.insert(html.rfind("</body>"), R"(<script>
(() => {
  const out = {why: [], labelsInside: true, labels: 0};
  for (const td of document.querySelectorAll('table.students td.why')) if (td.textContent) out.why.push(Math.round(td.getBoundingClientRect().width));
  for (const svg of document.querySelectorAll("svg[aria-label='marks histogram']")) {
    const box = svg.getBoundingClientRect();
    for (const t of svg.querySelectorAll('text')) {
      const r = t.getBoundingClientRect();
      ++out.labels;
      if (r.width <= 0 || r.left < box.left - 1 || r.right > box.right + 1) out.labelsInside = false;
    }
  }
  document.body.dataset.probe = JSON.stringify(out);
})();
</script>
)");
  std::ofstream(probed) << html;
  for (const int width : {1280, 400}) {
    SCOPED_TRACE(width);
    const Page page = loadInChromium("file://" + probed, width);
    const nlohmann::json probe = probeOf(page.dom);
    ASSERT_TRUE(probe.is_object()) << page.dom.substr(0, 2000);
    EXPECT_GT(probe["labels"].get<int>(), 10) << "a histogram with its labels";
    EXPECT_TRUE(probe["labelsInside"].get<bool>()) << "a histogram's labels cut off";
    ASSERT_FALSE(probe["why"].empty());
    if (width == 1280) {
      for (const auto& w : probe["why"]) EXPECT_GE(w.get<int>(), 150) << "a failure squeezed into a narrow column";
    }
  }
}

// The trace's layers in the player: each one the run has is a switch, draws without an error and
// says what it shows; what a Python program printed is in the page, line by line, the line of the
// playhead marked. The RoboticsAcademy vacuum prints with time.time() timers; the vacuum's reference
// publishes its belief and has a laser; TeleTaxi's reference plans.
TEST(RunPage, LayersAndWhatTheProgramPrinted) {
  struct Case {
    std::string student;
    std::vector<std::string> args;
    std::vector<std::string> switches;
    std::string note;
  };
  const std::vector<Case> cases = {
      {"rafa", {"vacuum", "--algorithm=" AULA_TEST_DATA_DIR "/python/ra_vacuum/MyAlgorithm.py", "--Vacuum.Referee.Duration=120"},
       {"layer-laser", "layer-console"}, "laser: the scan of"},
      {"rhea", {"vacuum", "--algorithm=reference", "--Vacuum.Referee.Duration=60"}, {"layer-laser", "layer-belief"},
       "magenta: what it believes"},
      {"tito", {"teletaxi", "--algorithm=reference"}, {"layer-plan"}, "its plan of 0.0 s"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.student);
    const GradedRun run = makeRun(c.student, c.args);
    const std::string page = run.stem + ".html";
    std::ofstream(page) << aula::grade::runPageHtml(aula::grade::runFilesOf(run.result));
    const nlohmann::json probe = probeOf(expectAGoodPage(run, page));
    ASSERT_TRUE(probe.is_object());
    EXPECT_EQ(probe["layerSwitches"], nlohmann::json(c.switches)) << probe.dump();
    EXPECT_NE(probe["layerNote"].get<std::string>().find(c.note), std::string::npos) << probe["layerNote"];
    const nlohmann::json& console = run.trace["layers"]["console"];
    if (c.student != "rafa") {
      EXPECT_TRUE(console["lines"].empty()) << "a C++ built-in prints nothing to the trace";
      continue;
    }
    ASSERT_GE(console["lines"].size(), 3u) << console.dump();
    EXPECT_EQ(console["lines"][0]["text"].get<std::string>().rfind("started at ", 0), 0u) << "printed at the import";
    const Page shown = loadInChromium("file://" + page + "#t=60&layers=console");
    for (const auto& line : console["lines"]) {
      EXPECT_NE(shown.dom.find(asDomText(line["text"].get<std::string>())), std::string::npos) << line.dump();
    }
    EXPECT_EQ(probe["consoleNow"], 1) << "the line printed last before the playhead is marked";
    EXPECT_TRUE(probe["consoleShown"].get<bool>());
    EXPECT_TRUE(probe["consoleHidden"].get<bool>()) << "switched off, the printed lines are hidden";
  }
}

// How big a graded run is (issue 58, docs/grading.md "How big a class is"): a full 900 s run of
// the vacuum reference (its lasers and belief traced: the largest vacuum trace), graded, leaves
// its result, report, picture, log and page, and no other copy of its trace; all its files
// together within 128 KB (117 KB on 2026-12-06): the largest vacuum run; a class's runs average
// 102 KB, 46 MB for 450 (bench/class_size.sh).
TEST(RunPage, AGradedFullRunStaysWithinItsBudget) {
  const GradedRun run = makeRun("erin", {"vacuum", "--algorithm=reference", "--Vacuum.Referee.Duration=900"});
  ASSERT_NEAR(run.trace["sim_time_s"].get<double>(), 900.0, 1.0) << "a full-length run";
  aula::grade::collect(run.dir);
  uintmax_t bytes = 0;
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(fs::path(run.stem).parent_path())) {
    if (entry.path().filename().string().rfind(fs::path(run.stem).filename().string() + ".", 0) != 0) continue;
    bytes += entry.file_size();
    files.push_back(entry.path().filename().string() + " " + std::to_string(entry.file_size()));
  }
  std::string listed;
  for (const std::string& f : files) listed += f + "\n";
  EXPECT_FALSE(fs::exists(run.stem + ".trace.json")) << listed;
  EXPECT_FALSE(fs::exists(run.stem + ".trace.z")) << listed;
  EXPECT_TRUE(fs::exists(run.stem + ".html")) << listed;
  EXPECT_LE(bytes, 128u * 1024u) << "a run's files within its budget:\n" << listed;
}
