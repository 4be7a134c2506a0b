#include <aula/config/config.hpp>
#include <aula/process/guarded_main.hpp>
#include <aula/world/world_spec.hpp>

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

using aula::process::guardedMain;

namespace {

// The exit code and what went to stderr of one guardedMain call.
struct Outcome {
  int exit_code;
  std::string stderr_text;
};

Outcome guarded(const std::function<int()>& body, const std::string& hint = "") {
  testing::internal::CaptureStderr();
  const int code = guardedMain("prog", body, hint);
  return {code, testing::internal::GetCapturedStderr()};
}

}  // namespace

TEST(GuardedMain, ReturnsTheBodysExitCode) {
  EXPECT_EQ(guarded([] { return 0; }).exit_code, 0);
  const Outcome o = guarded([] { return 3; });
  EXPECT_EQ(o.exit_code, 3);
  EXPECT_EQ(o.stderr_text, "");
}

TEST(GuardedMain, HelpShownEndsWithZeroAndNoMessage) {
  const Outcome o = guarded([]() -> int { throw aula::process::HelpShown(); });
  EXPECT_EQ(o.exit_code, 0);
  EXPECT_EQ(o.stderr_text, "");
}

TEST(GuardedMain, ConfigAndWorldErrorsExitWithTwo) {
  const Outcome config = guarded([]() -> int { throw aula::config::ConfigError("a.cfg:3: bad key"); });
  EXPECT_EQ(config.exit_code, 2);
  EXPECT_EQ(config.stderr_text, "prog: a.cfg:3: bad key\n");
  const Outcome world = guarded([]() -> int { throw aula::world::WorldError("w.world: no robot"); });
  EXPECT_EQ(world.exit_code, 2);
  EXPECT_EQ(world.stderr_text, "prog: w.world: no robot\n");
}

TEST(GuardedMain, ConfigErrorHintFollowsTheMessageOnly) {
  const std::string usage = "usage: prog WORLD\n";
  EXPECT_EQ(guarded([]() -> int { throw aula::config::ConfigError("bad"); }, usage).stderr_text,
            "prog: bad\nusage: prog WORLD\n");
  EXPECT_EQ(guarded([]() -> int { throw aula::world::WorldError("bad"); }, usage).stderr_text, "prog: bad\n");
}

TEST(GuardedMain, AnyOtherExceptionExitsWithOne) {
  const Outcome o = guarded([]() -> int { throw std::runtime_error("udpm: no route"); });
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_EQ(o.stderr_text, "prog: udpm: no route\n");
}
