#pragma once
// What `aula grade` and `aula grade-task` do (their declarations are tools/aula/commands/):
//   a class: every submission compiled, every run planned, run locally or as a Slurm array, collected;
//   --collect DIR: grades.csv and report.html from the results in DIR (after a Slurm job);
//   grade-task MANIFEST INDEX: one run of a manifest (what each Slurm array task runs).

#include <aula/grade/grade_plan.hpp>

#include <string>

namespace aula::grade {

// `bin_dir`: where this Aula's programs are (the runs' `aula`, the plugins' CMake package).
int gradeClass(const GradeRequest& request, const std::string& bin_dir);
int collectGrades(const std::string& out_dir);
int gradeTask(const std::string& manifest_path, const std::string& index);

}  // namespace aula::grade
