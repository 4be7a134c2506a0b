#pragma once
// The grading scale a referee grades with, for its report: the preset its rubric setting selects
// and the effective value of every setting that preset governs (libs/settings declares them):
//   "rubric": {"preset": "default", "Vacuum.Referee.HalfMarkCoverage": 35.0, ...,
//              "overridden": ["Vacuum.Referee.FullMarkCoverage"]}
// "overridden" lists the keys a .cfg or the command line set over the preset (absent when none).

#include <aula/config/settings.hpp>
#include <aula/referee/report.hpp>

#include <string>

namespace aula::referee {

Report rubricReport(const config::Config& effective, const config::SettingsTable& table, const std::string& preset_key);

}  // namespace aula::referee
