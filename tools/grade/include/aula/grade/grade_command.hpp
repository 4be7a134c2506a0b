#pragma once
// The `aula grade` family, behind the launcher:
//   aula grade EXERCISE SUBMISSION... [--worlds=W1,W2] [--seeds=1-5] [--jobs=N] [--out=DIR]
//              [--engine=local|slurm] [--wall-limit=SECONDS] [--Key=value ...]
//   aula grade --collect DIR          grades.csv from the results in DIR (after a Slurm job)
//   aula grade-task MANIFEST INDEX    one run of a manifest (what each Slurm array task runs)

#include <aula/config/config.hpp>

#include <string>

namespace aula::grade {

extern const char* const kGradeUsage;

// `bin_dir`: where this Aula's programs are (the runs' `aula`, the plugins' CMake package).
int gradeCommand(const config::CommandLine& cl, const std::string& bin_dir);

}  // namespace aula::grade
