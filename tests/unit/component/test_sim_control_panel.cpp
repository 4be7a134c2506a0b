// The window's pace line (issue 58): what the simulator's clock says of the pace it keeps, and,
// when the machine cannot keep the pace asked, that it cannot and that the run is the same.
#include <aula/component/sim_control_panel.hpp>
#include <aula/lcm/bus.hpp>

#include <gtest/gtest.h>

#include <QApplication>
#include <QLabel>

using aula::component::paceText;

namespace {

aula::sim_clock_t tickAt(double measured, double asked, bool lockstep = true) {
  aula::sim_clock_t tick{};
  tick.real_time_factor = measured;
  tick.target_real_time_factor = asked;
  tick.lockstep = lockstep;
  return tick;
}

}  // namespace

TEST(PaceText, SaysOnlyWhenTheMachineCannotKeepThePaceAsked) {
  EXPECT_EQ(paceText(tickAt(0, 1)), "") << "nothing measured yet";
  EXPECT_EQ(paceText(tickAt(0.97, 1)), "") << "within a tenth is keeping it";
  EXPECT_EQ(paceText(tickAt(41.5, 0)), "") << "as fast as possible";
  EXPECT_EQ(paceText(tickAt(6.2, 10)), "6.2x, not the 10x asked: the machine cannot keep up (the run is the same, slower)");
  EXPECT_EQ(paceText(tickAt(0.62, 1, false)), "0.62x, not the 1x asked: the machine cannot keep up");
  aula::sim_clock_t paused = tickAt(0, 1);
  paused.paused = true;
  EXPECT_EQ(paceText(paused), "");
}

// The panel hears the clock on the bus it is given, as a window's does.
TEST(SimControlPanel, ShowsThePaceOfTheClockItHears) {
  aula::lcmbus::Bus bus("memq://");
  aula::component::SimControlPanel panel(bus);
  const aula::sim_clock_t slow = tickAt(3.0, 10);
  bus.publish(aula::lcmbus::kClockChannel, &slow);
  while (bus.handleTimeout(0) > 0) {
  }
  bool said = false;
  for (const QLabel* label : panel.findChildren<QLabel*>()) said = said || (label->isVisibleTo(&panel) && label->text().startsWith("3x, not the 10x asked"));
  EXPECT_TRUE(said);
  const aula::sim_clock_t kept = tickAt(9.8, 10);
  bus.publish(aula::lcmbus::kClockChannel, &kept);
  while (bus.handleTimeout(0) > 0) {
  }
  for (const QLabel* label : panel.findChildren<QLabel*>()) EXPECT_FALSE(label->text().startsWith("9.8x")) << "nothing said when kept";
}

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");  // also when ctest lists the tests
  QApplication app(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
