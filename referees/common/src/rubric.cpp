#include "aula/referee/rubric.hpp"

#include <stdexcept>

namespace aula::referee {

Report rubricReport(const config::Config& effective, const config::SettingsTable& table, const std::string& preset_key) {
  const config::SettingSpec* selector = table.find(preset_key);
  if (selector == nullptr || selector->presets.empty()) {
    throw std::logic_error(table.owner() + ": '" + preset_key + "' is not a preset setting");
  }
  const std::string preset = effective.getString(preset_key);
  Report out;
  out.set("preset", preset);
  std::vector<std::string> overridden;
  for (const std::string& key : selector->governs) {
    switch (table.find(key)->type) {
      case config::SettingType::Int:
      case config::SettingType::Double: out.set(key, effective.getDouble(key)); break;
      case config::SettingType::DoubleList: out.set(key, effective.getDoubleList(key)); break;
      case config::SettingType::Bool: out.set(key, effective.getBool(key)); break;
      case config::SettingType::String:
      case config::SettingType::Choice: out.set(key, effective.getString(key)); break;
    }
    // A .cfg or the command line set another value than the preset's (a regrade repeats them all).
    if (!table.isPresetValue(key, preset, effective.getString(key))) overridden.push_back(key);
  }
  if (!overridden.empty()) out.set("overridden", overridden);
  // The world's calibration file the launcher applied (its keys are among the overridden).
  const std::string calibration_key = preset_key.substr(0, preset_key.rfind('.')) + ".Calibration";
  if (table.declares(calibration_key) && !effective.getString(calibration_key).empty()) {
    out.set("calibration", effective.getString(calibration_key));
  }
  return out;
}

}  // namespace aula::referee
