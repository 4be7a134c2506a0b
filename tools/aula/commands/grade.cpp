// aula grade EXERCISE SUBMISSION...: a class graded headless, every submission x world x seed
// (locally or as a Slurm array); aula grade --collect DIR after a Slurm job (tools/grade).
#include "commands.hpp"
#include "run_settings.hpp"

#include <aula/grade/grade_command.hpp>
#include <aula/grade/generated_worlds.hpp>
#include <aula/settings/tables.hpp>

namespace aula::commands {
namespace {

int gradeSubmissions(const cli::Arguments& args) {
  if (args.given("collect")) {
    if (!args.positional().empty()) throw config::ConfigError("aula grade --collect=DIR takes no other argument");
    return grade::collectGrades(args.text("collect"));
  }
  if (args.positional().size() < 2) {
    throw config::ConfigError("aula grade: name the exercise and at least one submission folder (aula grade vacuum alice/ bob/)");
  }
  grade::GradeOptions options;
  options.exercise = args.positional(0);
  options.submissions.assign(args.positional().begin() + 1, args.positional().end());
  options.lms = args.text("lms");
  options.lms_assignment = args.given("lms-assignment") ? args.text("lms-assignment") : "";
  options.hand_in_limits.max_bytes = static_cast<uint64_t>(args.integer("hand-in-size")) << 20;
  options.hand_in_limits.max_files = static_cast<uint64_t>(args.integer("hand-in-files"));
  options.hand_in_limits.max_depth = static_cast<int>(args.integer("hand-in-depth"));
  options.worlds = args.text("worlds");
  options.seeds = args.text("seeds");
  options.calibration_seeds = args.text("calibration-seeds");
  options.jobs = args.given("jobs") ? args.integer("jobs") : 0;
  options.out_dir = args.text("out");
  options.engine = args.text("engine");
  options.wall_limit_s = args.real("wall-limit");
  options.record = args.flag("record");
  options.keep_builds = args.flag("keep-builds");
  options.build_sandbox = args.text("build-sandbox") == "on";
  options.similarity = args.text("similarity");
  options.similarity_rules.code_threshold = args.real("similarity-code");
  options.similarity_rules.code_min_shared = static_cast<size_t>(args.integer("similarity-shared"));
  options.similarity_rules.behaviour_threshold_m = args.real("similarity-path");
  options.known = args.given("known") ? args.text("known") : "";
  options.overrides = args.settings();
  return grade::gradeClass(grade::parseRequest(options), binDir());
}

}  // namespace

cli::Command grade() {
  const grade::SimilarityRules defaults;  // the similarity rules' defaults are declared once, there
  const grade::HandInLimits hand_in;      // and a hand-in's bounds', in hand_in.hpp
  cli::Command c("grade", "grade a class: every submission (a folder with MyAlgorithm.cpp or MyAlgorithm.py, or an LMS's export) x world x seed, headless");
  c.positionals = {{"EXERCISE", settings::exerciseNames(false), false, true},
                   {"SUBMISSION", "a student's folder (the student is named after it), or an LMS's export: its zip or "
                                  "folder (Moodle's or Canvas's \"download all submissions\")", true, true}};
  c.takes_settings = true;
  c.options.add(cli::valueOption("worlds", "W1,W2", "the worlds every submission runs on (default: the exercise's own); "
                                 "generate:KIND:5,seed=7 writes held-out worlds into OUT/worlds (" + grade::generatedWorldKinds() + ")"))
      .add(cli::valueOption("seeds", "LIST", "the seeds: 1-5, 1,4,9 or 2-3,7", "1"))
      .add(cli::valueOption("calibration-seeds", "LIST|off",
                            "the seeds each world without a calibration file is calibrated on (the baseline's and the "
                            "reference's runs, cached in OUT/calibrations); off: none",
                            "1-10"))
      .add(cli::numberOption("jobs", config::SettingType::Int, "", 1, 1024, "runs at once (default: one per CPU)"))
      .add(cli::valueOption("out", "DIR", "the folder of grades.csv, report.html, runs/ and build/ (run again to resume)", "grading"))
      .choice("engine", "local", {"local", "slurm"}, "where the runs go: this machine, or a Slurm array")
      .real("wall-limit", 3600, "s", 1, 1e7, "each run's wall-clock backstop for a starved machine: past it the run is the machine's failure and is run again (the sim-time limit is the referee's)", true)
      .flag("record", false, "keep each run's LCM log (runs/<student>/<world>-seed<k>.lcmlog)")
      .flag("keep-builds", false,
            "keep each C++ build's tree (its objects and plugin, about 1 MB a student) in OUT/build once every run is "
            "done; by default only its sources, project and compile.log stay")
      .choice("build-sandbox", "on", {"on", "off"},
              "compile each C++ submission in a sandbox of its own (docs/grading.md); off only to measure what it "
              "costs (bench/grade_class.sh): a student's build then runs as you")
      .choice("similarity", "auto", {"auto", "on", "off"},
              "compare the submissions' code and their robots' paths (similarity.csv, flagged pairs in report.html); "
              "auto: for a class of 3 or more")
      .real("similarity-code", defaults.code_threshold, "", 0, 1,
            "a pair is flagged on code when this share of the smaller submission's fingerprints is in the other, or more")
      .integer("similarity-shared", static_cast<long long>(defaults.code_min_shared), "fingerprints", 1, 1000000,
               "a pair flagged on code shares this many fingerprints or more too (two short programs share a few by chance)")
      .real("similarity-path", defaults.behaviour_threshold_m, "m", 0, 1000,
            "a pair is flagged on behaviour when their robots' paths (same world and seed, at the same sim times) are "
            "this far apart or less, on average")
      .add(cli::valueOption("known", "DIR",
                            "your own solutions, one folder each (MyAlgorithm.cpp or .py): run and compared with every "
                            "student like the exercise's built-in algorithms, never graded (with similarity on)"))
      .choice("lms", "auto", {"auto", "moodle", "canvas"},
              "what the submissions are: auto tells an LMS's export by its names (else a folder per student); moodle "
              "or canvas: each is that LMS's export (lms-grades.csv goes back in its format)")
      .add(cli::valueOption("lms-assignment", "NAME",
                            "Canvas: the assignment's column in lms-grades.csv, as the gradebook's export names it "
                            "(\"Vacuum (12345)\"; default \"aula EXERCISE\")"))
      .integer("hand-in-size", static_cast<long long>(hand_in.max_bytes >> 20), "MiB", 1, 1 << 20,
               "a student's hand-in may hold this much, its zips unpacked (a file as long as it says it is)")
      .integer("hand-in-files", static_cast<long long>(hand_in.max_files), "files", 1, 10000000,
               "a student's hand-in may hold this many files and folders, its zips' included")
      .integer("hand-in-depth", hand_in.max_depth, "folders", 1, 1000, "a student's hand-in may be this many folders deep")
      .add(cli::valueOption("collect", "DIR", "only collect: grades.csv and report.html from DIR's runs (after a Slurm job)"));
  c.details = "out: DIR/grades.csv (median, min, max per student; failures with reasons), DIR/report.html, DIR/runs/\n"
              "see docs/grading.md\n";
  c.run = gradeSubmissions;
  return c;
}

cli::Command gradeTask() {
  cli::Command c("grade-task", "one run of a grading manifest (what each Slurm array task of `aula grade` runs)");
  c.positionals = {{"MANIFEST", "DIR/manifest.json of `aula grade`"}, {"INDEX", "the run's index in it"}};
  c.run = [](const cli::Arguments& args) { return grade::gradeTask(args.positional(0), args.positional(1)); };
  return c;
}

}  // namespace aula::commands
