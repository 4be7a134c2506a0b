#pragma once
// The keys every exercise's processes share, for the exercises' own declarations
// (components/<exercise>/exercise.cpp): one way of naming a world, a window, a map and the
// student's motion limits, so that `aula run`, `aula replay` and the windows find them by section.

#include <aula/config/settings.hpp>

#include <string>
#include <vector>

namespace aula::settings {

// A program's table with the keys every Aula process has (Aula.LcmUrl).
config::SettingsTable programTable(const std::string& program);
// SECTION.World, SECTION.Robot and the channels named after the section (VACUUM_EPISODE...).
void worldKeys(config::SettingsTable& t, const std::string& section, const std::string& world, const std::string& robot);
// PREFIX.Size and PREFIX.Position of a window of the process (aula/desktop/window_layout.hpp).
void windowKeys(config::SettingsTable& t, const std::string& prefix, const std::string& size_px, const std::string& what);
// SECTION.Map.Resolution and SECTION.Map.ZBand: the occupancy map the component and referee draw.
void mapKeys(config::SettingsTable& t, const std::string& section, double resolution_m, const std::string& z_band);
// SECTION.Referee.Calibration: the calibration file `aula run` applied (it sets the key by this
// name when the exercise declares a calibration), which the report names.
void calibrationKey(config::SettingsTable& t, const std::string& section);
// SECTION.MaxV, MaxW, Period, Autostart and the Component.* budgets and sandbox limits.
void motionKeys(config::SettingsTable& t, const std::string& section, double max_v, double max_w, double period_s,
                double v_bound_mps, double w_bound_radps);
// The settings that change what any exercise's robot can reach, which its calibration records
// (ExerciseCalibration::context_keys): SECTION.MaxV and MaxW (motionKeys), and the simulator's noise.
std::vector<std::string> reachKeys(const std::string& section);

}  // namespace aula::settings
