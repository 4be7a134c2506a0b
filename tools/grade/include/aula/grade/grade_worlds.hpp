#pragma once
// The worlds a grade runs on, made ready before any run: the held-out worlds it generates
// (generated_worlds.hpp), and a calibration for each world that has none beside it
// (calibration.hpp), so that marks mean the same on every world.

#include <aula/grade/grade_plan.hpp>

#include <string>

namespace aula::grade {

// Writes the generated worlds (adding them to request.worlds), checks that a run can start on
// every world with the grade's settings (as `aula config` resolves them), and calibrates every world without
// a calibration file beside it into request.calibrations: OUT/calibrations/<world>-<key>.rubric.cfg,
// where the key is the SHA-256 of the world's SHA-256, the calibration seeds, the grade's
// settings and Aula's version (a file already there is used again, not rerun). Only with the
// exercise's default rubric, for an exercise that has a calibration, and not for Aula's own
// worlds (share/aula/worlds: the default rubric was made on them). Throws config::ConfigError
// (exit 2: the teacher's to fix, before any student's run) when a world cannot be generated or
// calibrated.
void prepareWorlds(GradeRequest& request, const std::string& bin_dir);

}  // namespace aula::grade
