#include <aula/referee/run_outcome.hpp>

#include <gtest/gtest.h>

using aula::referee::Report;
using aula::referee::RunOutcome;

TEST(RunOutcome, AFaultEndsTheRunAndIsAnnouncedOnce) {
  RunOutcome outcome;
  int announced = 0;
  EXPECT_FALSE(outcome.onEpisode("libmy.so", "", 0, 0));
  outcome.announceOnce(outcome.ended(), [&] { ++announced; });
  EXPECT_EQ(announced, 0);
  outcome.onEpisode("libmy.so", "execute() threw std::runtime_error: boom", 2, 0);
  outcome.onEpisode("libmy.so", "a later fault does not replace the first", 2, 0);
  EXPECT_TRUE(outcome.ended());
  outcome.announceOnce(outcome.ended(), [&] { ++announced; });
  outcome.announceOnce(outcome.ended(), [&] { ++announced; });
  EXPECT_EQ(announced, 1);
  EXPECT_EQ(outcome.fault(), "execute() threw std::runtime_error: boom");
}

TEST(RunOutcome, AReloadStartsANewEpisodeWithoutTheOldFault) {
  RunOutcome outcome;
  int announced = 0;
  outcome.onEpisode("libmy.so", "execute() threw std::runtime_error: boom", 3, 0);
  outcome.announceOnce(outcome.ended(), [&] { ++announced; });
  EXPECT_TRUE(outcome.onEpisode("libmy.so", "", 0, 1));  // the student fixed it and reloaded
  EXPECT_FALSE(outcome.onEpisode("libmy.so", "", 0, 1));  // the same episode again
  EXPECT_FALSE(outcome.ended());
  EXPECT_EQ(outcome.generation(), 1);
  outcome.announceOnce(true, [&] { ++announced; });  // the new episode's end is announced too
  EXPECT_EQ(announced, 2);
  Report report;
  outcome.addTo(report);
  const std::string json = report.toJson();
  EXPECT_NE(json.find("\"reloads\": 1"), std::string::npos) << json;
  EXPECT_EQ(json.find("algorithm_error"), std::string::npos) << json;
  EXPECT_EQ(json.find("non_finite_commands"), std::string::npos) << json;
}

TEST(RunOutcome, AnAbortOutlivesAReload) {
  RunOutcome outcome;
  outcome.abort("component crashed (SIGSEGV)");
  outcome.onEpisode("libmy.so", "", 0, 1);
  EXPECT_TRUE(outcome.ended());
  EXPECT_EQ(outcome.aborted(), "component crashed (SIGSEGV)");
}

TEST(RunOutcome, EpisodeStatusSaysHowTheEpisodeEnded) {
  aula::referee::RunOutcome outcome;
  auto waiting = outcome.episodeStatus(false, 12.0, 600.0, false, "Arrived");
  EXPECT_FALSE(waiting.started);
  EXPECT_DOUBLE_EQ(waiting.elapsed_s, 0.0);  // the clock has not started: nothing elapsed
  EXPECT_DOUBLE_EQ(waiting.time_left_s, 600.0);
  EXPECT_FALSE(waiting.finished);
  EXPECT_EQ(waiting.ending, "");
  auto arrived = outcome.episodeStatus(true, 42.5, 600.0, true, "Arrived");
  EXPECT_DOUBLE_EQ(arrived.time_left_s, 557.5);
  EXPECT_TRUE(arrived.finished);
  EXPECT_EQ(arrived.ending, "Arrived");
  outcome.abort("execute() did not return within 2 s");
  auto stopped = outcome.episodeStatus(true, 50.0, 600.0, false, "Arrived");
  EXPECT_TRUE(stopped.finished);
  EXPECT_EQ(stopped.ending, "Stopped");
}

// What the algorithm said last (a reference that gives up says why and where: issue 44) is in
// the report as it said it; a student's bytes that are not UTF-8 never break the report's JSON.
TEST(RunOutcome, TheAlgorithmsLastWordIsInTheReportAsValidJson) {
  RunOutcome outcome;
  outcome.onEpisode("reactive", "", 0, 0, "searching");
  outcome.onEpisode("reactive", "", 0, 0, "stalled: 240 s in SEARCH, stopped at x 3.10 y 2.50");
  outcome.algorithmFailed("execute() threw: bad \xff\xfe bytes \"quoted\"");
  Report report;
  outcome.addTo(report);
  const std::string json = report.toJson();
  EXPECT_NE(json.find("\"algorithm_status\": \"stalled: 240 s in SEARCH, stopped at x 3.10 y 2.50\""), std::string::npos) << json;
  EXPECT_NE(json.find("bad \xEF\xBF\xBD\xEF\xBF\xBD bytes \\\"quoted\\\""), std::string::npos) << json;
  EXPECT_NE(outcome.summary().find("the algorithm said: stalled: 240 s"), std::string::npos) << outcome.summary();
  EXPECT_EQ(aula::referee::validUtf8("caf\xC3\xA9 \xF0\x9F\x93\x81 \xC3"), "caf\xC3\xA9 \xF0\x9F\x93\x81 \xEF\xBF\xBD");
}

// A windowed run the student teleoperated, stopped or reloaded is not its seed's graded run: the
// report says why, with every reason the component gave, through a reload (issue 58).
TEST(RunOutcome, AWindowedRunThatIsNotItsSeedsGradedRunSaysWhy) {
  RunOutcome outcome;
  Report plain;
  outcome.onEpisode("reference", "", 0, 0);
  outcome.addTo(plain);
  EXPECT_EQ(plain.toJson().find("not_the_seeds_run"), std::string::npos) << "a run as its seed's says nothing";
  outcome.onEpisode("reference", "", 0, 0, "", "teleoperated before Run");
  outcome.onEpisode("reference", "", 0, 1, "", "teleoperated before Run; reloaded during the run");
  outcome.onEpisode("reference", "", 0, 1, "", "");  // an older message, or one from before: the reasons stay
  Report report;
  outcome.addTo(report);
  EXPECT_NE(report.toJson().find("\"not_the_seeds_run\": \"teleoperated before Run; reloaded during the run\""), std::string::npos)
      << report.toJson();
  EXPECT_NE(outcome.summary().find("not its seed's graded run: teleoperated before Run; reloaded during the run"), std::string::npos)
      << outcome.summary();
}
