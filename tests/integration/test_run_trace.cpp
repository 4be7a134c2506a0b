// The referee's --trace: the run as it graded it, for the grading page's player. A run's three
// processes are started here as `aula run --headless` starts them, the referee with --trace,
// while the launcher's recorder (run_recorder) logs the bus; then `aula regrade`'s function
// grades the log again with a trace. The trace must agree with the report (coverage, bumps,
// contacts, final pose), be byte-identical for the same seed and in the regrade, and a 900 s
// vacuum trace must stay under 300 KB.
#include "test_support.hpp"

#include <aula/supervision/run_recorder.hpp>

#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>
#include <aula/process/child_process.hpp>
#include <aula/settings/tables.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

using namespace std::chrono_literals;
using aula::testing::readFile;

namespace {

const std::string kBin = AULA_BIN_DIR;

struct Traced {
  std::string report, trace;              // the live run's
  std::string regraded_report, regraded_trace;
  nlohmann::json r, t;                    // parsed
};

// One run of `exercise` with `algorithm` and `seed`, as `aula run --headless` would start it,
// recorded; then graded again from the log with a trace.
Traced traceRun(const std::string& exercise_name, const std::string& algorithm, int seed,
                const std::vector<std::string>& sim_settings = {}) {
  const aula::settings::Exercise& ex = aula::settings::requireExercise(exercise_name);
  const std::string dir = aula::testing::privateDir();
  const std::string url = "udpm://239.255.76.67:" + std::to_string(aula::testing::freeUdpPort()) + "?ttl=0&recv_buf_size=4194304";
  const std::string cfg = aula::config::dataPath(ex.config_file);
  const aula::config::Config file = aula::config::Config::fromFile(cfg);
  const std::string world_setting = file.has(ex.section + ".World") ? file.getString(ex.section + ".World")
                                                                     : ex.referee_settings->find(ex.section + ".World")->default_value;
  const std::string world = aula::config::resolveWorldPath(world_setting, cfg);
  const std::string world_key = "--" + ex.section + ".World=" + world;
  Traced out;
  {
    aula::supervision::RunRecorder recorder(dir + "/run.lcmlog", url, aula::supervision::runRecord(ex, world, seed, file));
    std::vector<std::string> sim_args = {kBin + "/aula-sim", world, "--lockstep", "--Simulator.Lockstep.WaitForClients=2",
                                         "--rtf=0", "--Simulator.Seed=" + std::to_string(seed), "--lcm-url=" + url};
    sim_args.insert(sim_args.end(), sim_settings.begin(), sim_settings.end());
    aula::process::ChildProcess sim(sim_args, dir + "/sim.txt", dir + "/sim.txt");
    aula::process::ChildProcess component({kBin + "/" + ex.component, "--config=" + cfg, world_key, "--headless",
                                           "--lcm-url=" + url, "--" + ex.section + ".Algorithm=" + algorithm,
                                           "--" + ex.section + ".Autostart=true"},
                                          dir + "/component.txt", dir + "/component.txt");
    aula::process::ChildProcess referee({kBin + "/" + ex.referee, "--config=" + cfg, world_key, "--headless",
                                         "--lcm-url=" + url, "--report=" + dir + "/live.json", "--trace=" + dir + "/live.trace.json"},
                                        dir + "/referee.txt", dir + "/referee.txt");
    EXPECT_EQ(referee.wait(200s).value_or(-1), 0) << readFile(dir + "/referee.txt") << readFile(dir + "/sim.txt");
    component.stop();
    sim.stop();
    recorder.stop();
  }
  const int code = aula::supervision::regrade(dir + "/run.lcmlog", dir + "/again.json", kBin, dir + "/again.trace.json");
  EXPECT_EQ(code, 0);
  out.report = readFile(dir + "/live.json");
  out.trace = readFile(dir + "/live.trace.json");
  out.regraded_report = readFile(dir + "/again.json");
  out.regraded_trace = readFile(dir + "/again.trace.json");
  out.r = nlohmann::json::parse(out.report);
  out.t = nlohmann::json::parse(out.trace);
  return out;
}

long count(const nlohmann::json& trace, const std::string& kind) {
  long n = 0;
  for (const auto& e : trace["events"]) n += e["kind"] == kind ? 1 : 0;
  return n;
}

// The sum of a delta-encoded column: its last value.
long long lastOf(const nlohmann::json& deltas) {
  long long v = 0;
  for (const auto& d : deltas) v += d.get<long long>();
  return v;
}

void expectFinalPoseAgrees(const Traced& g) {
  ASSERT_TRUE(g.r.contains("final_pose")) << g.report;
  const auto& pose = g.t["final"]["pose"];
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(pose[i].get<double>(), g.r["final_pose"][i].get<double>(), 1e-6) << i;
  // The last sample is the pose at its time, in mm.
  const auto& s = g.t["samples"];
  EXPECT_NEAR(lastOf(s["x_mm"]) / 1000.0, g.r["final_pose"][0].get<double>(), 0.05) << "the last sample is near the end";
  EXPECT_NEAR(lastOf(s["y_mm"]) / 1000.0, g.r["final_pose"][1].get<double>(), 0.05);
}

void expectBreakdownSumsToTheMark(const Traced& g) {
  double sum = 0;  // the rows read top to bottom: a term adds, a rule's factor scales the total so far
  for (const auto& term : g.t["breakdown"]) {
    if (term.contains("factor")) {
      sum *= term["factor"].get<double>();
      continue;
    }
    sum += term["points"].get<double>();
    EXPECT_LE(term["points"].get<double>(), term["of"].get<double>() + 1e-9) << term.dump();
  }
  EXPECT_NEAR(sum, g.r["mark"].get<double>(), 1e-4) << g.trace.substr(0, 2000);
  EXPECT_EQ(g.t["mark"], g.r["mark"]);
}

}  // namespace

TEST(RunTrace, VacuumTraceAgreesWithTheReportAndTheRegrade) {
  const Traced g = traceRun("vacuum", "reference", 3);
  EXPECT_EQ(g.report, g.regraded_report);
  EXPECT_EQ(g.trace, g.regraded_trace) << "aula regrade writes the live run's trace, byte for byte";
  // Its layers are most of it (450 laser scans of every other beam, the belief's maps): about 300 KB.
  EXPECT_LE(g.trace.size(), 400u * 1024u) << "a 900 s vacuum trace within its budget";
  EXPECT_EQ(g.t["sim_time_s"], 900.0);
  EXPECT_EQ(g.t["samples"]["count"], 9001) << "10 Hz from 0 to 900 s, both ends";
  EXPECT_EQ(g.t["state"]["coverage_percent"], g.r["coverage_percent"]);
  EXPECT_NEAR(lastOf(g.t["state"]["coverage_cp"]) / 100.0, g.r["coverage_percent"].get<double>(), 0.006);
  EXPECT_EQ(count(g.t, "bump"), g.r["bumps"].get<long>());
  double stuck_s = 0;
  for (const auto& e : g.t["events"]) stuck_s += e["kind"] == "stuck" ? e["duration_s"].get<double>() : 0.0;
  EXPECT_NEAR(stuck_s, g.r["stuck_s"].get<double>(), 1e-6);
  EXPECT_EQ(count(g.t, "end"), 1);
  // The cleaned cells cover about the floor the referee counted (a cell is cleaned at half).
  const double cell_m2 = std::pow(g.t["state"]["cell_px"].get<int>() * g.t["map"]["resolution_m"].get<double>(), 2);
  EXPECT_NEAR(g.t["state"]["cells_cleaned"].get<double>() * cell_m2, g.r["cleaned_area_m2"].get<double>(),
              0.05 * g.r["cleaned_area_m2"].get<double>());
  expectFinalPoseAgrees(g);
  expectBreakdownSumsToTheMark(g);
  // The same seed again: the same bytes.
  const Traced again = traceRun("vacuum", "reference", 3);
  EXPECT_EQ(again.trace, g.trace) << "the same seed gives a byte-identical trace";
}

TEST(RunTrace, TeleTaxiTraceAgreesWithTheReportAndTheRegrade) {
  const Traced g = traceRun("teletaxi", "reference", 4);
  EXPECT_EQ(g.report, g.regraded_report);
  EXPECT_EQ(g.trace, g.regraded_trace);
  EXPECT_EQ(g.r["reached"], true) << g.report;
  EXPECT_EQ(count(g.t, "arrival"), 1);
  EXPECT_EQ(count(g.t, "bump"), g.r["bumps"].get<long>());
  EXPECT_EQ(g.t["state"]["destination_m"], g.r["destination_m"]);
  // From GO! to the arrival, and on while the referee makes sure the taxi is at rest (1 s and a tick).
  const double arrival_samples = 10 * g.r["driving_time_s"].get<double>() + 1;
  EXPECT_GE(g.t["samples"]["count"].get<double>(), arrival_samples - 1);
  EXPECT_LE(g.t["samples"]["count"].get<double>(), arrival_samples + 15);
  for (const auto& e : g.t["events"]) {
    if (e["kind"] == "arrival") {
      EXPECT_EQ(e["t_s"], g.r["driving_time_s"]);
    }
  }
  expectFinalPoseAgrees(g);
  expectBreakdownSumsToTheMark(g);
}

TEST(RunTrace, AutoparkTraceAgreesWithTheReportAndTheRegrade) {
  // Started nearer the curb, the reactive car touches something once on its way in.
  const Traced g = traceRun("autopark", "reactive", 5, {"--Simulator.StartPose.car=-7,-1.5,0"});
  EXPECT_GE(g.r["collisions"].get<long>(), 1) << g.report;
  EXPECT_EQ(g.report, g.regraded_report);
  EXPECT_EQ(g.trace, g.regraded_trace);
  EXPECT_EQ(count(g.t, "contact"), g.r["collisions"].get<long>());
  EXPECT_EQ(count(g.t, g.r["parked"].get<bool>() ? "parked" : "end"), 1);
  double contact_s = 0;
  for (const auto& e : g.t["events"]) contact_s += e["kind"] == "contact" ? e["duration_s"].get<double>() : 0.0;
  EXPECT_NEAR(contact_s, g.r["contact_time_s"].get<double>(), 1e-6);
  const auto& gaps = g.t["state"]["gaps_m"];
  EXPECT_EQ(gaps[0], g.r["front_gap_m"]);
  EXPECT_EQ(gaps[1], g.r["rear_gap_m"]);
  EXPECT_EQ(gaps[2], g.r["curb_gap_m"]);
  expectFinalPoseAgrees(g);
  expectBreakdownSumsToTheMark(g);
}
