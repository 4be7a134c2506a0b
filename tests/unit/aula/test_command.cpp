// A command's declaration is its parser and its help: what it declares is typed and defaulted,
// what it does not declare is refused naming the command and the nearest option.
#include <aula/cli/command.hpp>

#include <gtest/gtest.h>

namespace {
using aula::cli::Arguments;
using aula::cli::Command;
using aula::config::ConfigError;
using aula::config::SettingType;

Command example() {
  Command c("run", "start an exercise");
  c.positionals = {{"EXERCISE", "which"}};
  c.takes_settings = true;
  c.options.flag("headless", false, "no windows")
      .add(aula::cli::valueOption("report", "FILE.json", "the report"))
      .add(aula::cli::numberOption("duration", SettingType::Double, "s", 0, 1e6, "episode length", true))
      .add(aula::cli::valueOption("seeds", "LIST", "seeds", "1"))
      .choice("engine", "local", {"local", "slurm"}, "where");
  c.run = [](const Arguments&) { return 0; };
  return c;
}

std::string errorOf(const Command& c, const std::vector<std::string>& args) {
  try {
    c.parse(args);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(Command, TypedValuesDefaultsAndWhatWasGiven) {
  const Arguments a = example().parse({"vacuum", "--headless", "--duration=5", "--report", "out.json", "--Vacuum.X=1"});
  EXPECT_EQ(a.positional(0), "vacuum");
  EXPECT_TRUE(a.flag("headless"));
  EXPECT_DOUBLE_EQ(a.real("duration"), 5.0);
  EXPECT_EQ(a.text("report"), "out.json");
  EXPECT_TRUE(a.given("report"));
  EXPECT_FALSE(a.given("seeds"));
  EXPECT_EQ(a.text("seeds"), "1");  // the declared default
  EXPECT_EQ(a.text("engine"), "local");
  ASSERT_EQ(a.settings().size(), 1u);
  EXPECT_EQ(a.settings()[0].first, "Vacuum.X");
}

TEST(Command, AnUndeclaredOptionNamesTheCommandAndTheNearestOption) {
  const std::string error = errorOf(example(), {"vacuum", "--durration=5"});
  EXPECT_NE(error.find("aula run: unknown option '--durration'"), std::string::npos) << error;
  EXPECT_NE(error.find("did you mean '--duration'?"), std::string::npos) << error;
}

TEST(Command, ValuesAreCheckedAgainstTheirDeclaration) {
  EXPECT_NE(errorOf(example(), {"vacuum", "--duration=0"}).find("aula run: --duration=0: out of range (0, 1000000] s"),
            std::string::npos);
  EXPECT_NE(errorOf(example(), {"vacuum", "--duration=abc"}).find("--duration=abc: not a finite number"), std::string::npos);
  EXPECT_NE(errorOf(example(), {"vacuum", "--engine=cloud"}).find("aula run: --engine=cloud: local or slurm"), std::string::npos);
  EXPECT_NE(errorOf(example(), {"vacuum", "--report"}).find("aula run: command line: --report needs a value"), std::string::npos);
  EXPECT_NE(errorOf(example(), {"vacuum", "-x"}).find("aula run: command line: unknown argument '-x'"), std::string::npos);
}

TEST(Command, PositionalArgumentsAreCounted) {
  EXPECT_NE(errorOf(example(), {}).find("expected EXERCISE, got nothing"), std::string::npos);
  EXPECT_NE(errorOf(example(), {"vacuum", "extra"}).find("expected EXERCISE, got 'vacuum' ..."), std::string::npos);
}

TEST(Command, SettingsOnlyWhereTheCommandTakesThem) {
  Command c = example();
  c.takes_settings = false;
  EXPECT_NE(errorOf(c, {"vacuum", "--Vacuum.X=1"}).find("takes no settings"), std::string::npos);
}

TEST(Command, HelpListsEveryDeclaredOption) {
  const std::string help = example().help();
  for (const char* line : {"usage: aula run EXERCISE [options] [--Section.Key=value ...]", "--headless", "--report=FILE.json",
                           "--duration=SECONDS", "(0, 1000000] s", "--engine=local|slurm", "--seeds=LIST", "(default 1)"}) {
    EXPECT_NE(help.find(line), std::string::npos) << line << "\n" << help;
  }
  EXPECT_EQ(help.find("VALUE"), std::string::npos) << help;
}

// A text option says what its value is (FILE, DIR, LIST); one declared without a placeholder
// would print a generic "--out=VALUE", so its help is refused.
TEST(Command, ATextOptionWithoutAPlaceholderIsRefused) {
  Command c = example();
  c.options.text("out", "grading", "the folder");
  EXPECT_THROW(c.help(), std::logic_error);
}

TEST(CommandTable, DispatchesByNameAndAnswersHelpAndVersion) {
  aula::cli::CommandTable table;
  Command c = example();
  c.run = [](const Arguments& a) { return a.flag("headless") ? 7 : 8; };
  table.add(c);
  const char* headless[] = {"aula", "run", "vacuum", "--headless"};
  EXPECT_EQ(table.dispatch(4, headless, "1.2.3", ""), 7);
  const char* plain[] = {"aula", "run", "vacuum"};
  EXPECT_EQ(table.dispatch(3, plain, "1.2.3", ""), 8);
  const char* version[] = {"aula", "--version"};
  EXPECT_EQ(table.dispatch(2, version, "1.2.3", ""), 0);
  const char* nothing[] = {"aula"};
  EXPECT_EQ(table.dispatch(1, nothing, "1.2.3", ""), 2);
  const char* unknown[] = {"aula", "rnu"};
  EXPECT_EQ(table.dispatch(2, unknown, "1.2.3", ""), 2);
  const char* help[] = {"aula", "run", "--help", "--not-declared"};
  EXPECT_EQ(table.dispatch(4, help, "1.2.3", ""), 0);
}

}  // namespace
