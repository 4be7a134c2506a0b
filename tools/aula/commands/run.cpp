// aula run EXERCISE: the simulator, the component and the referee (like the original's three
// terminals), supervised until the run ends (aula/supervision).
#include "commands.hpp"
#include "run_settings.hpp"

#include <aula/config/paths.hpp>
#include <aula/grade/run_page.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/lcm/udpm_receiver.hpp>
#include <aula/process/cpu_affinity.hpp>
#include <aula/sandbox/sandbox.hpp>
#include <aula/settings/tables.hpp>
#include <aula/supervision/confinement.hpp>
#include <aula/supervision/rules.hpp>
#include <aula/supervision/run_recorder.hpp>
#include <aula/supervision/supervisor.hpp>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>

namespace aula::commands {
namespace {
using cli::Arguments;
using config::Config;
using config::ConfigError;
using settings::Exercise;

// Where the referee writes `output` (report, picture, trace): as given, or beside --report-html,
// which is made of them ("" when neither asks for it).
std::string outputPath(const Arguments& args, const std::string& output) {
  if (args.given(output)) return args.text(output);
  if (!args.given("report-html") || output == "report-html") return "";
  const std::string page = args.text("report-html");
  const std::string stem = page.substr(0, page.rfind('.') == std::string::npos ? page.size() : page.rfind('.'));
  return stem + (output == "report" ? ".report.json" : output == "trace" ? ".trace.json" : ".png");
}

bool noDisplay() {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (display == nullptr || *display == '\0') && (wayland == nullptr || *wayland == '\0');
}

// The simulator's command line: lockstep and as fast as possible when headless.
std::vector<std::string> simulatorLine(const Arguments& args, const RunSettings& run, size_t clients, bool headless,
                                       const std::string& lcm_url) {
  std::vector<std::string> sim = {binDir() + "/aula-sim", run.world};
  if (args.flag("lockstep") || headless) {
    sim.push_back("--lockstep");
    sim.push_back("--Simulator.Lockstep.WaitForClients=" + std::to_string(clients));
  }
  // With windows, in lockstep, the world is held at 0 s until the first Run (or teleoperation):
  // the episode starts where a headless run of the seed starts, and is that run (the component
  // resumes the simulator: ExerciseComponent::releaseTheStart).
  if (!headless && args.flag("lockstep") && clients > 1 && !run.overrides.has("Simulator.StartPaused")) {
    sim.push_back("--Simulator.StartPaused=true");
  }
  // Headless runs go as fast as possible unless --rtf says otherwise; --rtf counts in every mode.
  if (args.given("rtf")) sim.push_back("--rtf=" + args.text("rtf"));
  else if (headless) sim.push_back("--rtf=0");
  if (!lcm_url.empty()) sim.push_back("--lcm-url=" + lcm_url);
  if (args.flag("3d")) sim.push_back("--gui");  // the world in 3D (DART's OpenSceneGraph view)
  return sim;
}

// The three command lines of a run: each process gets the .cfg, the world and only its own keys.
std::vector<std::vector<std::string>> commandLines(const Exercise& ex, const Arguments& args, const RunSettings& run,
                                                   bool headless, const std::string& lcm_url, const std::string& isolation) {
  std::vector<std::vector<std::string>> lines = {
      simulatorLine(args, run, ex.referee_settings == nullptr ? 1 : 2, headless, lcm_url)};
  const std::vector<std::string> programs = {ex.component, ex.referee};
  for (size_t i = 0; i < ex.tables().size(); ++i) {
    std::vector<std::string> line = {binDir() + "/" + programs[i], "--config=" + run.cfg_path,
                                     "--" + ex.section + ".World=" + run.world};
    if (headless) line.push_back("--headless");
    if (!lcm_url.empty()) line.push_back("--lcm-url=" + lcm_url);
    lines.push_back(line);
  }
  for (const std::string& key : run.overrides.keys()) {
    if (key == ex.section + ".World") continue;
    const std::string arg = "--" + key + "=" + run.overrides.getString(key);
    if (settings::simulator().declares(key)) lines[0].push_back(arg);
    for (size_t i = 0; i < ex.tables().size(); ++i) {
      if (ex.tables()[i]->declares(key)) lines[i + 1].push_back(arg);
    }
  }
  if (ex.referee_settings == nullptr && args.given("duration")) lines[1].push_back("--duration=" + args.text("duration"));
  for (const char* output : {"report", "picture", "trace"}) {
    const std::string path = outputPath(args, output);
    if (ex.referee_settings != nullptr && !path.empty()) lines[2].push_back(std::string("--") + output + "=" + path);
  }
  if (ex.referee_settings != nullptr && !isolation.empty()) lines[2].push_back("--isolation=" + isolation);
  if (!headless) {
    const auto places = windowPlaces(run, args.flag("3d"));
    for (size_t i = 0; i < lines.size(); ++i) lines[i].insert(lines[i].end(), places[i].begin(), places[i].end());
  }
  return lines;
}

// The referee's output files: a folder that is not there is refused before anything starts, and
// a report from an earlier run must never pass for this one's, whatever happens next.
// What is at an output's path is replaced only when it is a file: never a link (its target, or
// the link, would be a file the user did not name), a named pipe or a device (/dev/full).
void prepareOutputs(const Arguments& args) {
  for (const char* output : {"report", "picture", "trace", "report-html", "record"}) {
    if (!args.given(output)) continue;
    config::requireWritableFolder(args.text(output), args.spelled(output));
    std::error_code error;
    const auto status = std::filesystem::symlink_status(args.text(output), error);
    if (!error && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
      const char* what = std::filesystem::is_symlink(status)     ? "a symbolic link"
                         : std::filesystem::is_directory(status) ? "a folder"
                         : std::filesystem::is_fifo(status)      ? "a named pipe"
                         : std::filesystem::is_socket(status)    ? "a socket"
                                                                 : "a device or special file";
      throw ConfigError(args.spelled(output) + ": " + args.text(output) + " is " + what +
                        ", not a file: give the path of a new or regular file");
    }
  }
  for (const char* output : {"report", "picture", "trace", "report-html"}) {
    if (!outputPath(args, output).empty()) std::filesystem::remove(outputPath(args, output));
  }
}

// After the run: --report-html, the run's page (player, events, the mark's breakdown) from the
// referee's files.
void writePage(const Arguments& args) {
  if (!args.given("report-html")) return;
  if (!std::filesystem::exists(outputPath(args, "report"))) {
    std::cerr << "aula: no report, so no page (" << args.spelled("report-html") << ")\n";
    return;
  }
  grade::writeRunPage(args.text("report-html"), outputPath(args, "report"), outputPath(args, "trace"),
                      outputPath(args, "picture"));
  std::cout << "the run's page: " << args.text("report-html") << "\n";
}

void checkOptions(const Exercise& ex, const Arguments& args, bool headless) {
  if (args.flag("3d") && headless) throw ConfigError("--3d shows the world in a window: not with --headless (or without a display)");
  if (args.flag("sandbox") && !headless) {
    throw ConfigError("--sandbox runs the student's component headless, in bubblewrap: add --headless");
  }
  if (args.flag("sandbox") && sandbox::bubblewrapPath().empty()) {
    throw ConfigError("--sandbox needs bubblewrap (/usr/bin/bwrap): apt install bubblewrap");
  }
  if (args.given("algorithm") && !args.flag("stale")) {
    const std::string stale = supervision::staleBuild(args.text("algorithm"));
    if (!stale.empty()) throw ConfigError("--algorithm=" + args.text("algorithm") + ": " + stale + "; --stale runs it anyway");
  }
  for (const char* option : {"record", "report", "picture", "trace", "report-html"}) {
    if (args.given(option) && ex.referee_settings == nullptr) {
      throw ConfigError(std::string("--") + option + ": '" + ex.name + "' has no referee");
    }
  }
}

// A headless run is one thread of control handed from process to process (lockstep): its three
// processes share one CPU, as batch tasks (aula/process/cpu_affinity.hpp): --cpu=N, or the one
// the launcher runs on; any (and runs with windows): wherever the kernel puts them.
process::Placement placementOf(const Arguments& args, bool headless) {
  const std::string choice = args.given("cpu") ? args.text("cpu") : headless ? "auto" : "any";
  const std::vector<int> allowed = process::allowedCpus();
  const int current = allowed.empty() ? -1 : process::currentCpu(allowed);
  return {supervision::chooseCpu(choice, allowed, current), headless};
}

// What the sandboxed component may see and use: exactly its own inputs, within the run's limits.
sandbox::Confinement confinementOf(const Exercise& ex, const RunSettings& run, supervision::TemporaryFile& graded_file) {
  const config::Config& component = run.component();
  sandbox::Limits limits;
  limits.memory_bytes = static_cast<uint64_t>(component.getDouble("Component.Sandbox.Memory") * (1 << 20));
  limits.processes = component.getInt("Component.Sandbox.Processes");
  limits.file_bytes = static_cast<uint64_t>(component.getDouble("Component.Sandbox.FileSize") * (1 << 20));
  limits.output_bytes = static_cast<uint64_t>(component.getDouble("Component.Sandbox.Output") * (1 << 20));
  limits.aula_processes = component.getBool("Component.OwnProcess") ? 3 : 2;
  const std::string algorithm = component.getString(ex.section + ".Algorithm");
  const auto files = supervision::componentFiles(binDir() + "/" + ex.component, ex.name, run.cfg_path, run.world, algorithm);
  sandbox::Confinement confinement = supervision::componentConfinement(files, limits);
  // The one algorithm the sandboxed component may run, in a file it cannot change.
  confinement.read_only_at.emplace_back(graded_file.write(algorithm + "\n"), sandbox::kGradedAlgorithmFile);
  return confinement;
}

supervision::Supervision supervisionOf(const Exercise& ex, const Arguments& args, const RunSettings& run, bool headless,
                                       const std::string& lcm_url, const std::string& isolation,
                                       supervision::TemporaryFile& graded_file) {
  supervision::Supervision s;
  s.exercise = ex.name;
  s.component_client = ex.component;
  s.report_path = outputPath(args, "report");
  s.headless = headless;
  s.sandbox = args.flag("sandbox");
  s.placement = placementOf(args, headless);
  s.wall_budget_s = wallBudgetOf(ex, run, args, headless);
  s.lines = commandLines(ex, args, run, headless, lcm_url, isolation);
  if (s.sandbox) s.confinement = confinementOf(ex, run, graded_file);
  if (isolation == "full") {  // its own network: a datagram to any other port went nowhere, and is flagged
    config::CommandLine url;
    if (!lcm_url.empty()) url.options["lcm-url"] = lcm_url;
    s.watched_lcm_port = lcmbus::parseUdpmUrl(lcmbus::resolveUrl(url, run.referee())).port;
  }
  s.has_referee = ex.referee_settings != nullptr;
  // A graded run's key, for the simulator and the referee only (never the component, which runs
  // the student's code), and the recorder that signs the log with it.
  if (headless && s.has_referee) s.key = auth::randomKey();
  if (s.has_referee) {
    s.algorithm = run.component().getString(ex.section + ".Algorithm");
  }
  return s;
}

// --record: the logger listens and the log holds the run's record before the simulator starts.
std::unique_ptr<supervision::RunRecorder> startRecording(const Exercise& ex, const std::string& path,
                                                         const RunSettings& run, const std::string& lcm_url,
                                                         const std::optional<auth::Key>& key) {
  supervision::RunRecorder::checkPath(path);
  const auto record = supervision::runRecord(ex, run.world, run.effective.front().second.getInt64("Simulator.Seed"), run.referee());
  config::CommandLine url;  // the run's --lcm-url wins over the referee's Aula.LcmUrl, as in every process
  if (!lcm_url.empty()) url.options["lcm-url"] = lcm_url;
  return std::make_unique<supervision::RunRecorder>(path, lcmbus::resolveUrl(url, run.referee()), record, key);
}

// A sandboxed run's own network (before this process has any thread): "full" isolation; where
// the system allows no namespace, the host's network and "partial", said once.
std::string isolate() {
  const std::string why_not = sandbox::enterPrivateNetwork();
  if (why_not.empty()) return "full";
  std::cerr << "aula: no private network for this run (" << why_not
            << "): the sandbox shares the host's network; the report says \"isolation\": \"partial\"\n";
  return "partial";
}

int runExercise(const Arguments& args) {
  const Exercise& ex = exerciseArgument(args.positional(0), "run");
  bool headless = args.flag("headless");
  if (!headless && noDisplay()) {
    std::cerr << "aula: no display (DISPLAY is not set): running headless; the mark is printed at the end\n";
    headless = true;
  }
  checkOptions(ex, args, headless);
  const std::string isolation = args.flag("sandbox") ? isolate() : "";
  prepareOutputs(args);
  const std::string cfg = args.given("config") ? args.text("config") : config::dataPath(ex.config_file);
  const RunSettings run = resolveSettings(ex, cfg, overridesOf(ex, args, headless), args.given("calibration") ? args.text("calibration") : "");
  const std::string lcm_url = runBus(args, run);
  std::cerr << "aula: the run's bus is " << lcm_url << " (for LCM's tools: LCM_DEFAULT_URL='" << lcm_url << "')\n";
  supervision::TemporaryFile graded_file;
  const supervision::Supervision supervision = supervisionOf(ex, args, run, headless, lcm_url, isolation, graded_file);
  std::unique_ptr<supervision::RunRecorder> recorder;
  if (args.given("record")) recorder = startRecording(ex, args.text("record"), run, lcm_url, supervision.key);
  const int code = supervision::supervise(supervision);
  if (recorder) recorder->stop();
  writePage(args);
  return code;
}

cli::Command declare() {
  cli::Command c("run", "start an exercise: the simulator, the component (your algorithm) and the referee");
  c.positionals = {{"EXERCISE", settings::exerciseNames(true)}};
  c.takes_settings = true;
  c.options.flag("headless", false, "no windows; lockstep, as fast as possible (or at --rtf); the run ends with the mark")
      .flag("sandbox", false, "run the component (the student's code) in bubblewrap, as `aula grade` does (docs/grading.md)")
      .add(cli::valueOption("world", "FILE", "any SDF world, for all three processes (docs/worlds.md)"))
      .add(cli::valueOption("algorithm", "NAME", "reference, student, a built-in's name, or your plugin PATH.so"))
      .add(cli::numberOption("seed", config::SettingType::Int, "", 0, 9.2e18, "the run's seed (default: Simulator.Seed)"))
      .add(cli::valueOption("report", "FILE.json", "the referee's JSON report, written at the end (atomically)"))
      .add(cli::valueOption("picture", "FILE.png", "the referee's PNG picture of the run, written at the end"))
      .add(cli::valueOption("trace", "FILE.json", "the referee's trace: poses at 10 Hz, the exercise's state, every event and its points"))
      .add(cli::valueOption("report-html", "FILE.html", "the run's own page: a player in the browser, its events and the mark's breakdown"))
      .add(cli::valueOption("record", "FILE.lcmlog", "write the whole run in LCM's log format (`aula regrade` grades it again)"))
      .flag("3d", false, "also show the world in 3D (the simulator's OpenSceneGraph window)")
      .flag("stale", false, "run a plugin even when its sources changed after it was built")
      .flag("lockstep", true, "with windows: the world waits for the component and the referee at every tick and is held at 0 s "
                              "until Run, so the windowed run is the headless (graded) run of its seed; --lockstep=off: it does not wait")
      .add(cli::numberOption("rtf", config::SettingType::Double, "", 0, 1e6,
                             "real-time factor (0: as fast as possible; default 1 with windows, 0 headless)"))
      .add(cli::numberOption("duration", config::SettingType::Double, "s", 0, 1e6,
                             "the episode's length in simulated seconds (the referee's Duration or Timeout)", true))
      .add(cli::numberOption("timeout", config::SettingType::Double, "s", 0, 1e7,
                             "a headless run's wall-clock budget (default: the episode at real time x 1.5 + 60 s + the "
                             "algorithm's Component budgets; waiting for a CPU not counted); past it the run ends, graded "
                             "so far, the machine's reason (exit 75)", true))
      .add(cli::valueOption("lcm-url", "URL", "the run's bus (udpm://GROUP:PORT?ttl=0); port 0: a free one from the OS"))
      .add(cli::valueOption("cpu", "N|auto|any", "the CPU a headless run's processes share (default: auto, the one `aula` starts on)"))
      .add(cli::valueOption("config", "FILE.cfg", "the exercise's .cfg file (default: its own in the data folder)"))
      .add(cli::valueOption("calibration", "FILE", "the world's calibration, with the default rubric (default: WORLD.rubric.cfg beside it)"));
  c.run = runExercise;
  return c;
}

}  // namespace

cli::Command run() { return declare(); }

}  // namespace aula::commands
