// The referee's status to the component's window: the referee's StatusSender and the
// component's RefereeStatusListener on one in-process bus, and the window's line.
#include <aula/lcm/bus.hpp>
#include <aula/component/referee_status.hpp>
#include <aula/referee/status_sender.hpp>

#include <gtest/gtest.h>

#include <vector>

using aula::component::RefereeStatusListener;
using aula::component::refereeStatusLine;
using aula::referee::EpisodeStatus;
using aula::referee::StatusSender;

namespace {

void drain(aula::lcmbus::Bus& bus) {
  while (bus.handleTimeout(0) > 0) {
  }
}

EpisodeStatus running(int generation, double elapsed_s, double left_s) {
  EpisodeStatus s;
  s.generation = generation;
  s.started = true;
  s.elapsed_s = elapsed_s;
  s.time_left_s = left_s;
  s.summary = "coverage 12.30 %";
  return s;
}

}  // namespace

TEST(StatusSender, SendsOncePerSimSecondAndAtEveryChange) {
  aula::lcmbus::Bus bus("memq://");
  int generation = 0;
  RefereeStatusListener listener(bus, "VACUUM_REFEREE", "test", [&] { return generation; });
  StatusSender sender(bus, "VACUUM_REFEREE", "vacuum");
  sender.tick(0, running(0, 0, 900));
  drain(bus);
  ASSERT_TRUE(listener.latest());
  EXPECT_EQ(listener.latest()->exercise, "vacuum");
  sender.tick(500'000, running(0, 0.5, 899.5));  // not a second later, nothing changed: not sent
  drain(bus);
  EXPECT_DOUBLE_EQ(listener.latest()->time_left_s, 900);
  sender.tick(1'000'000, running(0, 1, 899));
  drain(bus);
  EXPECT_DOUBLE_EQ(listener.latest()->time_left_s, 899);
  EpisodeStatus end = running(0, 900, -0.2);  // a referee's overshoot never shows as negative
  end.finished = true;
  end.ending = "Time's up";
  sender.tick(1'100'000, end);  // a change: sent at once
  drain(bus);
  EXPECT_TRUE(listener.latest()->finished);
  EXPECT_DOUBLE_EQ(listener.latest()->time_left_s, 0);
}

TEST(RefereeStatusListener, IgnoresOtherEpisodesAndAnnouncesTheEndOnce) {
  aula::lcmbus::Bus bus("memq://");
  int generation = 1;
  RefereeStatusListener listener(bus, "TELETAXI_REFEREE", "test", [&] { return generation; });
  std::vector<std::string> endings;
  listener.setOnFinished([&](const aula::referee_status_t& s) { endings.push_back(s.ending); });
  StatusSender sender(bus, "TELETAXI_REFEREE", "teletaxi");
  EpisodeStatus old_episode = running(0, 10, 590);
  old_episode.finished = true;
  old_episode.ending = "Time's up";
  sender.send(1, old_episode);  // about the episode before a reload
  drain(bus);
  EXPECT_FALSE(listener.latest());
  EXPECT_TRUE(endings.empty());
  EpisodeStatus arrived = running(1, 42, 558);
  arrived.finished = true;
  arrived.ending = "Arrived";
  sender.send(2, arrived);
  sender.send(3, arrived);
  drain(bus);
  ASSERT_EQ(endings.size(), 1u);
  EXPECT_EQ(endings[0], "Arrived");
  generation = 2;  // the student reloads: the old word is not about this episode
  EXPECT_FALSE(listener.latest());
}

TEST(RefereeStatusLine, SaysWhatTheRefereeSays) {
  EXPECT_EQ(refereeStatusLine(std::nullopt, "Run"), "no word from the referee yet");
  aula::referee_status_t s{};
  s.started = false;
  EXPECT_EQ(refereeStatusLine(s, "GO!"), "the referee's clock starts at GO!");
  s.started = true;
  s.time_left_s = 872.9;
  s.summary = "coverage 3.10 %";
  EXPECT_EQ(refereeStatusLine(s, "Run"), "time left 14:32 - coverage 3.10 %");
  s.summary = "";
  s.time_left_s = 0.4;
  EXPECT_EQ(refereeStatusLine(s, "Run"), "time left 0:00");
  s.finished = true;
  s.ending = "Time's up";
  s.summary = "coverage 67.30 %, mark 10.00 / 10";
  EXPECT_EQ(refereeStatusLine(s, "Run"), "Time's up: coverage 67.30 %, mark 10.00 / 10");
}

TEST(StatusSender, TheEndIsSaidOnceAsItWasAtTheEnd) {
  aula::lcmbus::Bus bus("memq://");
  int generation = 0;
  RefereeStatusListener listener(bus, "VACUUM_REFEREE", "test", [&] { return generation; });
  StatusSender sender(bus, "VACUUM_REFEREE", "vacuum");
  EpisodeStatus end = running(0, 12, 888);
  end.finished = true;
  end.ending = "Stopped";
  sender.tick(12'000'000, end);
  end.elapsed_s = 15;  // the referee's clock ran on after a fault: the windows keep the end
  sender.tick(15'000'000, end);
  drain(bus);
  EXPECT_DOUBLE_EQ(listener.latest()->elapsed_s, 12);
  generation = 1;  // a reload: the new episode is sent again
  sender.tick(16'000'000, running(1, 0, 900));
  drain(bus);
  ASSERT_TRUE(listener.latest());
  EXPECT_FALSE(listener.latest()->finished);
}
