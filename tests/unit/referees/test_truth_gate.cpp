// What a referee grades in a graded run: only the simulator's signed truth, each message once.
// Forgeries, replays and contradicting episodes are counted by channel; lost messages are gaps.
#include <aula/referee/run_outcome.hpp>
#include <aula/referee/truth_gate.hpp>

#include <aula/bumper_t.hpp>
#include <aula/pose3d_t.hpp>

#include <gtest/gtest.h>

using aula::referee::Report;
using aula::referee::TruthGate;

namespace {

aula::pose3d_t pose(int64_t seq, double x) {
  aula::pose3d_t msg{};
  msg.utime = seq * 20000;
  msg.x = x;
  msg.auth_seq = seq;
  return msg;
}

aula::episode_t episode(int generation, int64_t started_utime, bool goal_set = false, double goal_x = 0) {
  aula::episode_t msg{};
  msg.exercise = "teletaxi";
  msg.algorithm = "student";
  msg.generation = generation;
  msg.started_utime = started_utime;
  msg.goal_set = goal_set;
  msg.goal_x = goal_x;
  return msg;
}

}  // namespace

TEST(TruthGate, AGradedRunGradesOnlyWhatTheSimulatorSignedOnce) {
  const aula::auth::Key key = aula::auth::randomKey();
  TruthGate gate(key);
  aula::pose3d_t real = pose(1, 1.0);
  aula::auth::sign(aula::auth::Signer(key), "ROOMBA_POSE", real);
  EXPECT_TRUE(gate.accept("ROOMBA_POSE", real));
  EXPECT_FALSE(gate.accept("ROOMBA_POSE", pose(2, 9.0))) << "unsigned";
  aula::pose3d_t other_key = pose(2, 9.0);
  aula::auth::sign(aula::auth::Signer(aula::auth::randomKey()), "ROOMBA_POSE", other_key);
  EXPECT_FALSE(gate.accept("ROOMBA_POSE", other_key)) << "signed by someone else";
  EXPECT_FALSE(gate.accept("ROOMBA_POSE", real)) << "a replay of a real message";
  aula::pose3d_t next = pose(2, 1.1);
  aula::auth::sign(aula::auth::Signer(key), "ROOMBA_POSE", next);
  EXPECT_TRUE(gate.accept("ROOMBA_POSE", next));
  EXPECT_EQ(gate.tampering(), (std::map<std::string, long long>{{"ROOMBA_POSE", 3}}));
  EXPECT_TRUE(gate.gaps().empty()) << "forgeries are not lost messages";
}

TEST(TruthGate, GapsInTheSequenceAreLostMessagesWithOrWithoutAKey) {
  TruthGate gate;
  EXPECT_TRUE(gate.accept("ROOMBA_POSE", pose(5, 0)));  // the first one seen sets the count going
  EXPECT_TRUE(gate.accept("ROOMBA_POSE", pose(6, 0)));
  EXPECT_TRUE(gate.accept("ROOMBA_POSE", pose(9, 0)));
  aula::bumper_t bump{};
  bump.auth_seq = 1;
  EXPECT_TRUE(gate.accept("ROOMBA_BUMPER", bump));
  EXPECT_TRUE(gate.accept("ROOMBA_POSE", pose(3, 0))) << "no key: everything is graded, as before";
  EXPECT_EQ(gate.gaps(), (std::map<std::string, long long>{{"ROOMBA_POSE", 2}}));
  EXPECT_FALSE(gate.tampered());
}

TEST(TruthGate, TheSimulatorsRefusedControlsComeWithItsSignedClock) {
  const aula::auth::Key key = aula::auth::randomKey();
  TruthGate gate(key);
  aula::sim_clock_t forged{};
  forged.auth_seq = 1;
  forged.rejected_controls = 0;
  EXPECT_FALSE(gate.acceptTick("SIM_CLOCK", forged));
  aula::sim_clock_t tick{};
  tick.auth_seq = 1;
  tick.rejected_controls = 3;
  aula::auth::sign(aula::auth::Signer(key), "SIM_CLOCK", tick);
  EXPECT_TRUE(gate.acceptTick("SIM_CLOCK", tick));
  EXPECT_EQ(gate.tampering(), (std::map<std::string, long long>{{"SIM_CLOCK", 1}, {"SIM_CONTROL", 3}}));
}

TEST(TruthGate, InAGradedRunAnEpisodeThatContradictsTheFirstIsNotFollowed) {
  TruthGate gate(aula::auth::randomKey());
  EXPECT_FALSE(gate.contradictsEpisode("TELETAXI_EPISODE", episode(0, -1)));
  EXPECT_FALSE(gate.contradictsEpisode("TELETAXI_EPISODE", episode(0, 0, true, 120)));  // GO! with its goal
  EXPECT_FALSE(gate.contradictsEpisode("TELETAXI_EPISODE", episode(0, 0, true, 120)));  // re-sent each second
  EXPECT_TRUE(gate.contradictsEpisode("TELETAXI_EPISODE", episode(1, -1))) << "a reload in a graded run";
  EXPECT_TRUE(gate.contradictsEpisode("TELETAXI_EPISODE", episode(0, 500000000))) << "another start";
  EXPECT_TRUE(gate.contradictsEpisode("TELETAXI_EPISODE", episode(0, 0, true, 0))) << "another goal";
  EXPECT_EQ(gate.tampering().at("TELETAXI_EPISODE"), 3);

  TruthGate windows;  // no key: a reload is a new episode, GO! may pick another goal
  EXPECT_FALSE(windows.contradictsEpisode("TELETAXI_EPISODE", episode(0, 0, true, 120)));
  EXPECT_FALSE(windows.contradictsEpisode("TELETAXI_EPISODE", episode(1, 9, true, 0)));
}

TEST(TruthGate, TheReportSaysTamperingOnlyWhenThereWasSome) {
  aula::referee::RunOutcome clean;
  Report plain;
  clean.addTo(plain);
  EXPECT_EQ(plain.raw("tampering"), "");
  EXPECT_EQ(plain.raw("truth_gaps"), "");

  aula::referee::RunOutcome attacked;
  attacked.truth() = TruthGate(aula::auth::randomKey());
  attacked.truth().accept("ROOMBA_POSE", pose(1, 5.0));
  attacked.truth().accept("ROOMBA_POSE", pose(2, 5.0));
  Report flagged;
  attacked.addTo(flagged);
  EXPECT_EQ(flagged.raw("tampering"), "{\"ROOMBA_POSE\": 2}");
  EXPECT_NE(attacked.summary().find("TAMPERING: 2 forged or refused messages on ROOMBA_POSE"), std::string::npos);
}
