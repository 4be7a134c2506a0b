// The shipped settings tables and .cfg files agree: every key a shipped .cfg sets is declared
// by one of the exercise's processes, in range, and each program has a table.
#include <aula/config/config.hpp>
#include <aula/settings/tables.hpp>

#include <gtest/gtest.h>

TEST(SettingsTables, EveryShippedConfigIsValidForEveryProcessOfItsExercise) {
  for (const auto& ex : aula::settings::exercises()) {
    const auto file = aula::config::Config::fromFile(std::string(AULA_SOURCE_DIR) + "/" + ex.config_file);
    for (const auto* table : ex.tables()) {
      std::vector<const aula::config::SettingsTable*> siblings;
      for (const auto* other : ex.tables()) {
        if (other != table) siblings.push_back(other);
      }
      EXPECT_NO_THROW(table->resolve(file, siblings)) << ex.config_file << " for " << table->owner();
    }
  }
  const auto simulator = aula::config::Config::fromFile(std::string(AULA_SOURCE_DIR) + "/config/simulator.cfg");
  EXPECT_NO_THROW(aula::settings::simulator().resolve(simulator));
}

TEST(SettingsTables, ProgramsFindTheirTablesAndExercises) {
  EXPECT_EQ(aula::settings::tableOf("vacuum-cleaner-referee").owner(), "vacuum-cleaner-referee");
  EXPECT_EQ(aula::settings::exerciseOfProgram("autopark")->name, "autopark");
  EXPECT_EQ(aula::settings::exerciseNamed("nope"), nullptr);
  EXPECT_THROW(aula::settings::tableOf("nope"), std::logic_error);
  // Channel names are not settings: the world's robot plugins name them.
  for (const auto& ex : aula::settings::exercises()) {
    for (const auto* table : ex.tables()) {
      for (const auto& spec : table->specs()) {
        EXPECT_EQ(spec.key.find("Pose3D"), std::string::npos) << spec.key;
      }
    }
  }
}
