#include "aula/grade/calibration.hpp"

#include <aula/grade/grade_plan.hpp>

#include <fstream>

// The calibration's anchor runs: whether each may set the scale (calibration.cpp runs them).
namespace aula::grade {
using config::ConfigError;

namespace {

// What makes an anchor run unfit to set the scale, or "" when it may: a scale of one point is the
// anchor's, and a failed anchor would set it from a failure (a reactive parker that never parks
// sets FullMarkTime to the timeout; a cleaner wedged in a corner for the last minutes sets the 10
// at what it covered before).
std::string anchorFault(const nlohmann::ordered_json& result, const CalibrationSpec& spec) {
  const bool read = !result.is_discarded();
  if (!spec.success.empty() && !(read && result.value(spec.success, false))) {
    return "did not succeed (its report's " + spec.success + " is not true)";
  }
  if (!spec.failure.empty() && read && result.value(spec.failure, false)) {
    return "ended " + spec.failure + " (its report's " + spec.failure + " is true)";
  }
  if (!read || !(result.value("mark", 0.0) > 0)) return "earned no mark";
  return "";
}

}  // namespace

std::string anchorNote(const nlohmann::ordered_json& result, const CalibrationSpec& spec) {
  std::string note;
  for (const std::string& field : {spec.success, spec.failure}) {
    if (!field.empty()) note += (note.empty() ? "" : ", ") + std::string(result.value(field, false) ? "" : "not ") + field;
  }
  return note.empty() ? "" : " (" + note + ")";
}

void requireAnchorSucceeded(const Manifest& manifest, const CalibrationSpec& spec, const std::string& anchor) {
  for (const PlannedRun& run : manifest.runs) {
    if (run.student != "anchor") continue;
    std::ifstream in(run.result_path);
    const std::string fault = anchorFault(nlohmann::ordered_json::parse(in, nullptr, false), spec);
    if (fault.empty()) continue;
    const std::string other = spec.other_anchor.empty() || spec.other_anchor == anchor
                                  ? ""
                                  : "; try another anchor, e.g. --anchor=" + spec.other_anchor;
    throw ConfigError("aula calibrate: the anchor (" + anchor + ") " + fault + " on " + run.world_name + " with seed " +
                      std::to_string(run.seed) + ": it cannot set the scale, and no rubric was written" + other +
                      "; see " + run.log_path);
  }
}

}  // namespace aula::grade
