// Shared widgets, drawn offscreen (QT_QPA_PLATFORM=offscreen).
#include <aula/gui/map_view.hpp>
#include <aula/gui/run_toggle.hpp>
#include <aula/gui/teleoperator.hpp>

#include <gtest/gtest.h>

#include <QApplication>

#include <cmath>

namespace {
aula::geometry::MapTransform cityTransform() {
  aula::geometry::MapTransform t;
  t.resolution_m = 1.25;
  t.origin_x_m = -250;
  t.origin_y_m = 250;
  t.width_px = t.height_px = 400;
  return t;
}
QImage blankMap() {
  QImage map(400, 400, QImage::Format_Grayscale8);
  map.fill(255);
  return map;
}
}  // namespace

TEST(MapView, WorldAndWidgetCoordinatesRoundTrip) {
  aula::gui::MapView view(blankMap(), cityTransform());
  for (QSize size : {QSize(400, 400), QSize(800, 600), QSize(300, 700)}) {
    view.resize(size);
    for (double x : {-200.0, 0.0, 123.4}) {
      for (double y : {-100.0, 0.0, 245.0}) {
        const QPointF w = view.widgetToWorld(view.worldToWidget(x, y));
        EXPECT_NEAR(w.x(), x, 1e-9);
        EXPECT_NEAR(w.y(), y, 1e-9);
      }
    }
  }
  view.resize(400, 400);
  EXPECT_LT(view.worldToWidget(0, 100).y(), view.worldToWidget(0, 0).y()) << "north is up";
}

TEST(MapView, TheRobotGlyphPointsAlongItsYaw) {
  aula::gui::MapView view(blankMap(), cityTransform());
  view.resize(400, 400);
  view.setRobot(0, 0, M_PI / 2, 40, 20);  // facing north: the nose is above the centre
  const QImage image = view.grab().toImage();
  const QPointF c = view.worldToWidget(0, 0);
  const QColor above = image.pixelColor(static_cast<int>(c.x()), static_cast<int>(c.y() - 12));
  const QColor below = image.pixelColor(static_cast<int>(c.x()), static_cast<int>(c.y() + 14));
  EXPECT_GT(above.blue(), above.red() + 100) << "the glyph should cover the point ahead";
  EXPECT_GT(below.blue(), 100);  // the base is wide too
  const QColor far_ahead = image.pixelColor(static_cast<int>(c.x()), static_cast<int>(c.y() - 30));
  EXPECT_EQ(far_ahead, QColor(255, 255, 255));
}

TEST(Teleoperator, StopSendsZeros) {
  aula::gui::Teleoperator teleop(20.0, 2.0);
  double v = -1, w = -1;
  QObject::connect(&teleop, &aula::gui::Teleoperator::velocityChanged, [&](double a, double b) {
    v = a;
    w = b;
  });
  teleop.stop();
  EXPECT_EQ(v, 0.0);
  EXPECT_EQ(w, 0.0);
}

TEST(RunToggle, GreenWhenRunningRedWhenStopped) {
  aula::gui::RunToggle toggle;
  bool seen = false;
  QObject::connect(&toggle, &aula::gui::RunToggle::runningChanged, [&](bool on) { seen = on; });
  EXPECT_FALSE(toggle.running());
  EXPECT_NE(toggle.styleSheet().indexOf("#d33"), -1);
  toggle.click();
  EXPECT_TRUE(seen);
  EXPECT_TRUE(toggle.running());
  EXPECT_NE(toggle.styleSheet().indexOf("#3c3"), -1);
  EXPECT_EQ(toggle.text(), "Stop my algorithm (F5)");
  EXPECT_EQ(toggle.shortcut(), QKeySequence(Qt::Key_F5));
}

TEST(TeleoperatorPad, KeysNudgeTheKnobByAQuarterWithinThePad) {
  aula::gui::TeleoperatorPad pad;
  double forward = 0, left = 0;
  QObject::connect(&pad, &aula::gui::TeleoperatorPad::moved, [&](double f, double l) {
    forward = f;
    left = l;
  });
  pad.nudge(0.25, 0);
  pad.nudge(0.25, 0.25);
  EXPECT_DOUBLE_EQ(forward, 0.5);
  EXPECT_DOUBLE_EQ(left, 0.25);
  for (int i = 0; i < 10; ++i) pad.nudge(-0.25, -0.25);
  EXPECT_DOUBLE_EQ(forward, -1.0);
  EXPECT_DOUBLE_EQ(left, -1.0);
}

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
