#pragma once
// A run's result as `aula grade` records it (grade_runner.hpp): the referee's report, who ran on
// what, and why it failed, with the grade's own word on whether that was the machine's reason.
// Private to tools/grade/src.

#include <aula/grade/grade_plan.hpp>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace aula::grade {

// A JSON file, or nothing when it is missing or does not parse.
std::optional<nlohmann::ordered_json> readJson(const std::string& path);
// The last non-empty line of a log.
std::string lastLine(const std::string& log_path);
// The run's result: the referee's report (when there is one) plus who ran, on what, how long,
// and why it failed (`machine_reason`: this grade's verdict, machine_reason.hpp).
nlohmann::ordered_json resultOf(const PlannedRun& run, std::optional<int> exit_code, bool timed_out, double wall_s);

}  // namespace aula::grade
