// aula calibrate EXERCISE --world=W: the rubric that gives the same mark the same meaning on W
// (the baseline's median at a 5, the anchor's at a 10), written to W.rubric.cfg beside the world,
// which `aula run` and `aula grade` then apply (tools/grade/calibration).
#include "commands.hpp"
#include "run_settings.hpp"

#include <aula/config/paths.hpp>
#include <aula/grade/calibration.hpp>
#include <aula/grade/grade_plan.hpp>
#include <aula/settings/tables.hpp>

#include <filesystem>
#include <iostream>
#include <thread>

namespace aula::commands {
namespace {

std::string commandLine(const cli::Arguments& args, const std::string& world) {
  std::string line = "aula calibrate " + args.positional(0) + " --world=" + std::filesystem::path(world).filename().string() +
                     " --seeds=" + args.text("seeds");
  for (const char* option : {"baseline", "anchor"}) {
    if (args.given(option)) line += std::string(" --") + option + "=" + args.text(option);
  }
  for (const auto& [key, value] : args.settings()) line += " --" + key + "=" + value;
  return line;
}

int calibrateWorld(const cli::Arguments& args) {
  const settings::Exercise& ex = exerciseArgument(args.positional(0), "calibrate");
  if (!args.given("world")) throw config::ConfigError("aula calibrate: --world=FILE is required (the world to calibrate)");
  grade::CalibrationRequest request;
  request.exercise = ex.name;
  request.world = config::resolveWorldPath(args.text("world"), "command line --world");
  request.seeds = grade::parseSeeds(args.text("seeds"), "--seeds");
  request.baseline = args.given("baseline") ? args.text("baseline") : "";
  request.anchor = args.given("anchor") ? args.text("anchor") : "";
  request.jobs = args.given("jobs") ? static_cast<int>(args.integer("jobs"))
                                    : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  request.out_dir = std::filesystem::absolute(args.text("out")).string();
  request.overrides = args.settings();
  const grade::Calibration calibration = grade::calibrate(request, binDir());
  const std::string path = args.given("output") ? args.text("output") : grade::calibrationPathOf(request.world);
  config::writeFileAtomically(path, grade::calibrationText(calibration, commandLine(args, request.world)),
                              "the calibration");
  std::cout << ex.name << " on " << request.world << ": " << calibration.spec.measure << " median ";
  if (!calibration.baseline.algorithm.empty()) {
    std::cout << calibration.baseline.median << " (" << calibration.baseline.algorithm << ", a 5) and ";
  }
  std::cout << calibration.anchor.median << " (" << calibration.anchor.algorithm << ", a 10) over " << request.seeds.size()
            << " seeds\nwrote " << path << "\n";
  return 0;
}

// "autopark (park_time_s), ... or vacuum (coverage_percent)": what each declared exercise calibrates.
std::string calibratedExercises() {
  std::vector<std::string> items;
  for (const auto& ex : settings::exercises()) {
    if (ex.calibration) items.push_back(ex.name + " (its scale of " + ex.calibration->measure + ")");
  }
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) out += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + items[i];
  return out;
}

}  // namespace

cli::Command calibrate() {
  cli::Command c("calibrate", "calibrate an exercise's rubric for a world: the baseline's median a 5, the anchor's a 10 "
                              "(with no baseline, the anchor's measure is worth a 10)");
  c.positionals = {{"EXERCISE", calibratedExercises()}};
  c.takes_settings = true;
  c.options.add(cli::valueOption("world", "FILE", "the world to calibrate (a .world file or a shipped world's name); required"))
      .add(cli::valueOption("seeds", "LIST", "the seeds each algorithm runs: 1-10, 1,4,9 or 2-3,7", "1-10"))
      .add(cli::valueOption("baseline", "ALGORITHM", "the algorithm worth a 5 (default: the exercise's baseline, bounce)"))
      .add(cli::valueOption("anchor", "ALGORITHM",
                            "the algorithm worth a 10 (default: the exercise's reference; e.g. classic, or a plugin PATH.so)"))
      .add(cli::numberOption("jobs", config::SettingType::Int, "", 1, 1024, "runs at once (default: one per CPU)"))
      .add(cli::valueOption("out", "DIR", "the folder of the calibration's runs (reports, pictures; run again to resume)", "calibration"))
      .add(cli::valueOption("output", "FILE.cfg", "where to write the rubric (default: W.rubric.cfg beside the world)"));
  c.details = "aula run and aula grade apply W.rubric.cfg when the rubric preset is default; see docs/grading.md\n";
  c.run = calibrateWorld;
  return c;
}

}  // namespace aula::commands
