// The run's player in a real browser: headless Chromium loads a run's page (and the class
// page) made from a real run's report, trace and picture. For one run of each exercise: the
// page loads with no console message (no error, no blocked request: the page's policy forbids
// any network request, and Chromium logs each it blocks) and loads no resource; after seeking
// to a recorded event's time the player's robot is where the trace says; the mark's breakdown
// sums to the report's mark.
//
// The trace comes from `aula regrade`'s function on the run's log (byte-identical to the live
// run's: test_run_trace), since `aula run` does not pass --trace to the referee yet.
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

// `aula run` of one exercise, recorded, with its report and picture; its trace from the log.
GradedRun makeRun(const std::string& student, const std::vector<std::string>& run_args) {
  GradedRun run;
  run.dir = aula::testing::privateDir();
  const std::string world = run_args.front() == "teletaxi" ? "cityLarge" : run_args.front();
  run.stem = run.dir + "/runs/" + student + "/" + world + "-seed1";
  fs::create_directories(fs::path(run.stem).parent_path());
  std::vector<std::string> args = {kBin + "/aula", "run"};
  args.insert(args.end(), run_args.begin(), run_args.end());
  args.insert(args.end(), {"--headless", "--seed=1", "--record=" + run.stem + ".lcmlog", "--report=" + run.stem + ".report.json",
                           "--picture=" + run.stem + ".png", "--lcm-url=" + aula::testing::privateLcmUrl()});
  const auto out = aula::testing::runToEnd(args, 200s);
  EXPECT_EQ(out.code.value_or(-1), 0) << out.output;
  EXPECT_EQ(aula::supervision::regrade(run.stem + ".lcmlog", "", kBin, run.stem + ".trace.json"), 0);
  run.result = nlohmann::json::parse(readFile(run.stem + ".report.json"));
  run.result["student"] = student;
  run.result["log"] = run.stem + ".log";
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
Page loadInChromium(const std::string& url) {
  const std::string profile = aula::testing::privateDir();
  const auto out = aula::testing::runToEnd(
      {"/usr/bin/chromium", "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
       "--disable-component-update", "--disable-sync", "--no-first-run", "--user-data-dir=" + profile,
       "--enable-logging=stderr", "--v=0", "--virtual-time-budget=10000", "--dump-dom", url},
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

// Where the trace puts the robot at `t_s` (linear between its samples, as the player draws it).
std::pair<double, double> tracedPosition(const nlohmann::json& trace, double t_s) {
  const auto xs = undelta(trace["samples"]["x_mm"]), ys = undelta(trace["samples"]["y_mm"]);
  const double period = trace["samples"]["period_s"].get<double>();
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

// `from_files`: the page as `aula run --report-html` makes it (writeRunPage, from the referee's
// files), else as `aula grade` does (from the run's result).
void expectPlayerAtEvent(const GradedRun& run, const std::vector<std::string>& kinds, bool from_files = false) {
  const std::string page_path = run.stem + ".html";
  if (from_files) {
    aula::grade::writeRunPage(page_path, run.stem + ".report.json", run.stem + ".trace.json", run.stem + ".png");
  } else {
    std::ofstream(page_path) << aula::grade::runPageHtml(aula::grade::runFilesOf(run.result));
  }
  const nlohmann::json& event = eventOf(run.trace, kinds);
  const double t_s = event["t_s"].get<double>();
  const Page page = loadInChromium("file://" + page_path + "#t=" + urlTime(t_s));
  ASSERT_FALSE(page.dom.empty()) << page.console;
  EXPECT_TRUE(consoleLines(page.console).empty()) << "a console message (an error, a blocked request):\n" << page.console;
  EXPECT_EQ(attribute(page.dom, "errors"), "0") << attribute(page.dom, "error-text");
  EXPECT_EQ(attribute(page.dom, "resources"), "0") << "the page loads nothing";
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

}  // namespace

TEST(RunPage, VacuumPlayerInChromium) {
  const GradedRun run = makeRun("alice", {"vacuum", "--algorithm=reference", "--Vacuum.Referee.Duration=300"});
  expectPlayerAtEvent(run, {"bump", "stuck", "mark", "end"});
}

TEST(RunPage, TeleTaxiPlayerInChromium) {
  const GradedRun run = makeRun("bob", {"teletaxi", "--algorithm=reference"});
  expectPlayerAtEvent(run, {"arrival", "bump", "end"});
}

TEST(RunPage, AutoparkPlayerInChromium) {
  const GradedRun run = makeRun("carol", {"autopark", "--algorithm=reactive", "--Simulator.StartPose.car=-7,-1.5,0"});
  ASSERT_GE(run.result["collisions"].get<long>(), 1) << "the seek goes to a contact";
  expectPlayerAtEvent(run, {"contact", "parked", "end"}, true);
}

// The class page: it loads as it is (no player built, no data decoded), then `#run=ID&t=` opens
// one run's player lazily, there.
TEST(RunPage, ClassPageOpensARunLazily) {
  const GradedRun run = makeRun("dave", {"vacuum", "--algorithm=reference", "--Vacuum.Referee.Duration=120"});
  const std::string out_dir = run.dir;
  aula::grade::collect(out_dir);
  EXPECT_TRUE(fs::exists(run.stem + ".html")) << "collect writes the run's own page";
  const std::string report = out_dir + "/report.html";
  {
    const Page page = loadInChromium("file://" + report);
    EXPECT_TRUE(consoleLines(page.console).empty()) << page.console;
    EXPECT_EQ(attribute(page.dom, "t-s"), "") << "no player is built before a run is opened";
    EXPECT_NE(page.dom.find("Flagged runs (0)"), std::string::npos);
  }
  const nlohmann::json& event = eventOf(run.trace, {"bump", "stuck", "mark", "end"});
  const double t_s = event["t_s"].get<double>();
  const Page page = loadInChromium("file://" + report + "#run=dave/vacuum-seed1&t=" + urlTime(t_s));
  EXPECT_TRUE(consoleLines(page.console).empty()) << page.console;
  ASSERT_FALSE(attribute(page.dom, "t-s").empty()) << page.dom.substr(0, 2000);
  const auto [x_mm, y_mm] = tracedPosition(run.trace, t_s);
  EXPECT_NEAR(std::stod(attribute(page.dom, "robot-x-mm")), x_mm, 1.0);
  EXPECT_NEAR(std::stod(attribute(page.dom, "robot-y-mm")), y_mm, 1.0);
  EXPECT_NEAR(std::stod(attribute(page.dom, "breakdown-sum")), run.result["mark"].get<double>(), 1e-3);
}
