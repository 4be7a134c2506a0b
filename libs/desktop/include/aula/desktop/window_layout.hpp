#pragma once
// One layout of a run's windows, decided by the launcher (`aula run`, `aula replay`), which knows
// which windows the run opens and the screen's size; each process is then told where its windows
// go through its settings.
//
// A window is declared by its process as two settings (aula/settings tables, `windowKeys`):
// `<Prefix>.Size` (its fixed size in px) and `<Prefix>.Position` (where its frame's top-left
// corner goes; -1, -1: where the window manager puts it), e.g. Vacuum.RefereeWindow.*.
//
// The layout puts each window, in order, at the topmost and then leftmost place where its frame
// fits on the work area without overlapping those before it. The frame is the window's size plus
// room for the window manager's title bar and borders (kFrameAllowance). A window that fits
// nowhere (a small screen) goes where it overlaps the others least, still on the screen.

#include <aula/config/config.hpp>
#include <aula/config/settings.hpp>

#include <optional>
#include <string>
#include <vector>

namespace aula::desktop {

struct Size {
  int width_px = 0;
  int height_px = 0;
};

struct Point {
  int x_px = 0;
  int y_px = 0;
};

struct Rect {
  int x_px = 0;
  int y_px = 0;
  int width_px = 0;
  int height_px = 0;

  int right() const { return x_px + width_px; }
  int bottom() const { return y_px + height_px; }
  // The area two rectangles share, in px² (0 when they only touch).
  long long overlapArea(const Rect& other) const;
  bool contains(const Rect& other) const;
};

// What a window manager adds around a window: openbox 2 x 25 px, GNOME's title bar about 37 px.
constexpr Size kFrameAllowance{10, 40};

// The top-left corner of each window's frame, in the order of `windows` (their own sizes).
std::vector<Point> layOut(const Rect& work_area, const std::vector<Size>& windows);

// The windows a process declares: the prefixes of its `<Prefix>.Size` / `<Prefix>.Position`
// pairs, in declaration order ("Vacuum.Window").
std::vector<std::string> windowsOf(const config::SettingsTable& table);
// A window as its process's effective settings say: its size, and its frame's top-left corner
// (nullopt: where the window manager puts it).
struct Placement {
  Size size;
  std::optional<Point> frame_corner;
};
Placement placementOf(const config::Config& settings, const std::string& prefix);
// The setting that puts the window there: "--Vacuum.Window.Position=0, 0".
std::string positionArgument(const std::string& prefix, const Point& frame_corner);

// A process whose windows a run lays out: its table and its effective settings.
struct WindowedProcess {
  const config::SettingsTable* table = nullptr;
  config::Config settings;
};
// A run's windows laid out at once: each process's windows in the order given, then `extras`
// (windows that are no process's settings: the replay's player).
struct RunLayout {
  std::vector<std::vector<std::string>> arguments;  // per process: positionArgument of each of its windows
  std::vector<Point> extras;                        // the extras' frame corners
};
// A window whose position its settings already give (the .cfg, the command line) keeps it and
// gets no argument.
RunLayout layOutRun(const Rect& work_area, const std::vector<WindowedProcess>& processes, const std::vector<Size>& extras);

}  // namespace aula::desktop
