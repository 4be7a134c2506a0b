// The launcher's one layout of a run's windows (aula/desktop/window_layout.hpp): side by side on
// a 1920x1080 screen for every exercise (with the 3D view too), on the screen on a smaller one,
// and the settings that carry each window's size and place.
#include <aula/desktop/window_layout.hpp>
#include <aula/settings/tables.hpp>

#include <gtest/gtest.h>

namespace aula::desktop {
namespace {

const Rect kFullHd{0, 0, 1920, 1080};

std::vector<Rect> framesOf(const std::vector<Point>& corners, const std::vector<Size>& windows) {
  std::vector<Rect> frames;
  for (size_t i = 0; i < corners.size(); ++i) {
    frames.push_back({corners[i].x_px, corners[i].y_px, windows[i].width_px + kFrameAllowance.width_px,
                      windows[i].height_px + kFrameAllowance.height_px});
  }
  return frames;
}

long long totalOverlap(const std::vector<Rect>& frames) {
  long long area = 0;
  for (size_t i = 0; i < frames.size(); ++i) {
    for (size_t j = i + 1; j < frames.size(); ++j) area += frames[i].overlapArea(frames[j]);
  }
  return area;
}

// What `aula run EXERCISE` lays out: the component's windows, the referee's, then the 3D view.
std::vector<Size> runWindows(const settings::Exercise& ex, bool view_3d) {
  std::vector<Size> sizes;
  std::vector<const config::SettingsTable*> tables = ex.tables();
  if (view_3d) tables.push_back(&settings::simulator());
  for (const auto* table : tables) {
    const config::Config defaults = table->resolve(config::Config());
    for (const std::string& window : windowsOf(*table)) sizes.push_back(placementOf(defaults, window).size);
  }
  return sizes;
}

TEST(WindowLayout, SideBySideTopFirstThenLeft) {
  const std::vector<Size> windows = {{880, 690}, {720, 690}, {544, 306}};
  const auto corners = layOut(kFullHd, windows);
  ASSERT_EQ(corners.size(), 3u);
  EXPECT_EQ(corners[0].x_px, 0);
  EXPECT_EQ(corners[0].y_px, 0);
  EXPECT_EQ(corners[1].x_px, 880 + kFrameAllowance.width_px);  // beside the first
  EXPECT_EQ(corners[1].y_px, 0);
  EXPECT_EQ(corners[2].x_px, 0);  // no room beside them: under the first
  EXPECT_EQ(corners[2].y_px, 690 + kFrameAllowance.height_px);
  EXPECT_EQ(totalOverlap(framesOf(corners, windows)), 0);
}

TEST(WindowLayout, EveryExercisesWindowsFitOnAFullHdScreenWithAndWithoutThe3dView) {
  for (const settings::Exercise& ex : settings::exercises()) {
    if (ex.referee_settings == nullptr) continue;
    for (const bool view_3d : {false, true}) {
      const std::vector<Size> windows = runWindows(ex, view_3d);
      ASSERT_GE(windows.size(), 2u) << ex.name;
      const auto frames = framesOf(layOut(kFullHd, windows), windows);
      EXPECT_EQ(totalOverlap(frames), 0) << ex.name << (view_3d ? " with --3d" : "");
      for (const Rect& frame : frames) EXPECT_TRUE(kFullHd.contains(frame)) << ex.name;
    }
  }
}

TEST(WindowLayout, OnASmallScreenEveryWindowStaysOnItAndOverlapsAsLittleAsItCan) {
  const Rect laptop{0, 0, 1366, 768};
  const std::vector<Size> windows = {{880, 690}, {720, 690}, {544, 306}};
  const auto frames = framesOf(layOut(laptop, windows), windows);
  for (const Rect& frame : frames) EXPECT_TRUE(laptop.contains(frame));
  // The referee cannot be beside the component (1620 px): it goes to the bottom right corner,
  // over as little of the component as it can (254 x 692 px).
  EXPECT_EQ(frames[1].right(), laptop.right());
  EXPECT_EQ(frames[1].bottom(), laptop.bottom());
  EXPECT_EQ(frames[0].overlapArea(frames[1]), static_cast<long long>(890 + 730 - 1366) * (730 - (768 - 730)));
}

TEST(WindowLayout, TheWorkAreaLeavesThePanelsFree) {
  const Rect below_a_top_bar{0, 32, 1920, 1048};
  const auto corners = layOut(below_a_top_bar, {{880, 690}, {720, 690}});
  EXPECT_EQ(corners[0].y_px, 32);
  EXPECT_EQ(corners[1].y_px, 32);
}

TEST(WindowLayout, AWindowLargerThanTheScreenGoesToItsCorner) {
  const auto corners = layOut({0, 0, 800, 600}, {{1200, 900}});
  EXPECT_EQ(corners[0].x_px, 0);
  EXPECT_EQ(corners[0].y_px, 0);
}

TEST(WindowSettings, EachProgramDeclaresItsWindowsAndTheirPlaces) {
  EXPECT_EQ(windowsOf(settings::tableOf("vacuum-cleaner")), std::vector<std::string>{"Vacuum.Window"});
  EXPECT_EQ(windowsOf(settings::tableOf("vacuum-cleaner-referee")), std::vector<std::string>{"Vacuum.RefereeWindow"});
  EXPECT_EQ(windowsOf(settings::tableOf("teletaxi")), (std::vector<std::string>{"TeleTaxi.Window", "TeleTaxi.GridWindow"}));
  EXPECT_EQ(windowsOf(settings::simulator()), std::vector<std::string>{"Simulator.Window"});

  config::Config cfg;
  cfg.set("Vacuum.Window.Position", "890, 0", "command line");
  const config::Config effective = settings::tableOf("vacuum-cleaner").resolve(cfg);
  const Placement placed = placementOf(effective, "Vacuum.Window");
  ASSERT_TRUE(placed.frame_corner.has_value());
  EXPECT_EQ(placed.frame_corner->x_px, 890);
  EXPECT_GT(placed.size.width_px, 0);
  // The default: where the window manager puts it.
  EXPECT_FALSE(placementOf(settings::tableOf("vacuum-cleaner").resolve(config::Config()), "Vacuum.Window").frame_corner);
  EXPECT_EQ(positionArgument("Vacuum.Window", {890, 0}), "--Vacuum.Window.Position=890, 0");
}

TEST(WindowSettings, ARunsLayoutPlacesEachProcessesWindowsAndKeepsAPositionTheSettingsGive) {
  const auto& component = settings::tableOf("teletaxi");
  const auto& referee = settings::tableOf("teletaxi-referee");
  config::Config given;
  given.set("TeleTaxi.RefereeWindow.Position", "100, 100", "command line");
  const RunLayout layout = layOutRun(kFullHd, {{&component, component.resolve(config::Config())}, {&referee, referee.resolve(given)}},
                                     {{760, 170}});
  ASSERT_EQ(layout.arguments.size(), 2u);
  EXPECT_EQ(layout.arguments[0],
            (std::vector<std::string>{"--TeleTaxi.Window.Position=0, 0", "--TeleTaxi.GridWindow.Position=1010, 0"}));
  EXPECT_TRUE(layout.arguments[1].empty());  // the command line's place is kept
  ASSERT_EQ(layout.extras.size(), 1u);  // the player, too wide beside the grid: under it
  EXPECT_EQ(layout.extras[0].x_px, 1010);
  EXPECT_EQ(layout.extras[0].y_px, 420 + kFrameAllowance.height_px);
}

}  // namespace
}  // namespace aula::desktop
