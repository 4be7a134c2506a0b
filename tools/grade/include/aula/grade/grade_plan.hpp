#pragma once
// `aula grade`: what a teacher asks for (students, worlds, seeds), the submissions compiled as
// plugins, and the manifest: one entry per run with its exact command line. Both engines run
// the same manifest entries (the local pool, or one Slurm array task per entry), so a grade
// never depends on where it ran.

#include <aula/config/config.hpp>
#include <aula/grade/generated_worlds.hpp>
#include <aula/grade/hand_in.hpp>
#include <aula/grade/similarity.hpp>

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace aula::settings { struct Exercise; }

namespace aula::grade {

struct GradeRequest {
  std::string exercise;
  std::vector<std::string> submissions;  // folders: each has MyAlgorithm.cpp (and maybe more .cpp); or LMS exports (lms_export.hpp)
  std::string lms = "auto";              // what the submissions are: auto (an export by its layout), moodle or canvas
  std::string lms_assignment;            // Canvas's assignment column in lms-grades.csv
  HandInLimits hand_in_limits;           // what one student's hand-in may hold
  std::map<std::string, std::string> refused_hand_ins;  // by submission folder: why nothing of it is graded
  std::vector<std::string> worlds;       // absolute paths; empty: the exercise's own world
  std::vector<WorldsToGenerate> generate;  // held-out worlds to write into OUT/worlds and grade on too
  std::vector<long long> seeds;
  // Calibrate each world without a calibration file beside it (the exercise's default rubric,
  // an exercise that has a calibration): the baseline and the anchor over these seeds, cached in
  // OUT/calibrations by the world's SHA-256 and the grade's settings. Empty: no calibration.
  std::vector<long long> calibration_seeds;
  std::map<std::string, std::string> calibrations;  // GradedWorld::key -> its calibration file (the runs' --calibration)
  int jobs = 1;
  std::string out_dir;
  std::string engine = "local";  // local | slurm
  double wall_limit_s = 600;     // per run; the sim-time limit is the referee's own
  bool similarity = false;       // compare the submissions (similarity.csv, report.html's section)
  bool similarity_auto = false;  // --similarity=auto: decided again once an export's students are counted
  // --known=DIR: the teacher's own solutions (one folder each, like a submission), run and compared
  // with every student as the exercise's built-in algorithms are (similarity on), never graded.
  std::vector<std::string> known;
  SimilarityRules similarity_rules;  // what flags a pair
  bool record = false;           // keep each run's LCM log (runs/<student>/<world>-seed<k>.lcmlog)
  bool keep_builds = false;      // keep each build's CMake tree after the runs (dropBuildTrees)
  bool build_sandbox = true;     // each C++ submission built in its sandbox (submission_build.hpp); off: to measure it
  std::vector<std::pair<std::string, std::string>> overrides;  // --Key=value for every run
};

// What `aula grade` was given, as its declared options typed them (tools/aula/commands/grade.cpp).
struct GradeOptions {
  std::string exercise;
  std::vector<std::string> submissions;  // as given
  std::string lms = "auto";
  std::string lms_assignment;            // "" for "aula EXERCISE"
  HandInLimits hand_in_limits;
  std::string worlds;                    // "W1,W2"; "" for the exercise's own
  std::string seeds = "1";
  std::string calibration_seeds = "1-10";  // "" or "off": no calibration
  long long jobs = 0;                    // 0: one per CPU
  std::string out_dir = "grading";
  std::string engine = "local";
  double wall_limit_s = 600;
  bool record = false;
  bool keep_builds = false;
  bool build_sandbox = true;
  std::string similarity = "auto";       // on, off, or auto: on for a class of 3 or more
  std::string known;                     // --known=DIR, "" for none
  SimilarityRules similarity_rules;
  std::vector<std::pair<std::string, std::string>> overrides;
};

// Checks the exercise, the submissions and the worlds; throws config::ConfigError (exit 2) naming
// the option or folder that is wrong.
GradeRequest parseRequest(const GradeOptions& options);
// The exercise's component settings as its own .cfg (in the data folder) and the defaults give them.
config::Config componentSettings(const settings::Exercise& ex);
// The seeds of `option` ("--seeds"): "1-5", "1,4,9", "1-3,7"; each in 0..kMaxSeed, kMaxSeeds at
// most in all; anything else throws ConfigError naming the option.
inline constexpr long long kMaxSeed = 9000000000000000000LL;  // aula run --seed's range
inline constexpr long long kMaxSeeds = 1000;
std::vector<long long> parseSeeds(const std::string& text, const std::string& option);

// A submission compiled (or not) into a plugin, or a student's Python file.
struct Submission {
  std::string student;  // the folder's name
  std::string folder;   // absolute; a built-in's: its installed sources (references/EXERCISE/NAME), or ""
  std::string language = "C++";  // "C++" (MyAlgorithm.cpp) or "Python" (MyAlgorithm.py alone)
  std::string plugin;   // the built .so, or the copy of MyAlgorithm.py ("" when it did not compile)
  std::string plugin_sha256;
  std::string compile_error;  // "did not compile: <the compiler's first error lines>"
  bool build_machine = false;  // the build was stopped at its wall-clock backstop: not the student's
  // A known algorithm, compared with every student and never graded: one of the exercise's
  // built-ins (student "reference 'classic'", plugin "classic": the name aula run takes) or one of
  // the teacher's --known solutions (student "known 'NAME'"). Its runs go to OUT/known/<dir_name>.
  bool known = false;
  std::string dir_name;  // OUT/runs/<student> or OUT/known/<dir_name>
};

// The exercise's built-in algorithms but the student's template, as known algorithms (their
// names from the component's SECTION.Algorithm choices).
std::vector<Submission> builtInAlgorithms(const std::string& exercise);
// `subs`, compiled from --known folders, made known ("known 'NAME'", OUT/known/known-NAME).
void markKnown(std::vector<Submission>& subs);

// Builds every submission as a plugin in OUT/build/<student>, `jobs` at once, each in a sandbox
// of its own (submission_build.hpp: its files checked and copied, its names never in a build
// file). A refused file or a compile error is that student's result and never stops the others. A folder with MyAlgorithm.py and no
// MyAlgorithm.cpp is not compiled: its .py files are copied there (what runs cannot change
// under the batch) and the copy of MyAlgorithm.py is what its runs load.
std::vector<Submission> compileSubmissions(const GradeRequest& request, const std::string& aula_prefix);
// Once every run is done: each build's CMake tree (OUT/build/<student>/build, OUT/known/build/...:
// objects and the plugin, about 1 MB a student) removed; the sources it built from, its project
// and compile.log stay. A resumed grade builds again, as it always does (issue 58: a class's size).
void dropBuildTrees(const std::string& out_dir);

// One run of the batch.
struct PlannedRun {
  int index = 0;
  std::string student, world_name, world_sha256;  // world_name: the file's name ("vacuum.world")
  long long seed = 0;
  std::string plugin, plugin_sha256, compile_error;
  bool build_machine = false;     // Submission::build_machine
  std::string language;  // the submission's: "C++", "Python" or "" (none)
  std::vector<std::string> argv;  // the exact command ("" when the plugin did not compile)
  // What the run was graded under besides its plugin, world and seed: the grade's --Key=value and
  // its --calibration. A result under other settings is not this run's (it is run again).
  std::vector<std::string> settings;
  std::string result_path;        // runs/<student>/<world>-seed<k>.json
  std::string report_path;        // where the referee writes its own report
  std::string log_path;           // the run's output
  double wall_limit_s = 600;
};

struct Manifest {
  std::string exercise, out_dir;
  std::vector<PlannedRun> runs;
  // With similarity on: the class's folders and what flags a pair (`aula grade --collect` compares
  // the class as the grade would have).
  std::vector<std::string> submissions;
  std::vector<std::string> known;  // the --known folders
  std::optional<SimilarityRules> similarity_rules;

  nlohmann::ordered_json toJson() const;
  static Manifest fromJson(const nlohmann::json& json);
  void save(const std::string& path) const;  // atomically
  static Manifest load(const std::string& path);  // throws ConfigError naming the file
};


// A world the grade runs on: a world file, or one of the destinations it declares (TeleTaxi: a
// world with <aula:destination>s is graded over each, unless the grade's settings name one).
struct GradedWorld {
  std::string path, name, sha256;  // name: the file's ("city.world"), "city-plaza.world" for a destination,
                                   // or "house-1a2b3c4d.world" when two different worlds share one file name
  std::string destination;         // "TeleTaxi.Destination=-40,40", or "" for the world's file alone
  std::string key;                 // the path, or "path#destination": request.calibrations' key
};
std::vector<GradedWorld> gradedWorlds(const GradeRequest& request);

// Every submission x world x seed, each on its own LCM port (a known algorithm's runs too, when
// `submissions` holds some: builtInAlgorithms, markKnown).
Manifest planRuns(const GradeRequest& request, const std::vector<Submission>& submissions, const std::string& bin_dir);

}  // namespace aula::grade
