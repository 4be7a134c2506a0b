#pragma once
// A process's main window (a component's, a referee's): closing it ends the process, whatever
// other windows are open (TeleTaxi's "Grid Field"). Qt by itself quits only when the last
// top-level window closes, so the run went on behind a window the student had closed.
//
// Every window of a run has a fixed size and a place from the launcher's one layout
// (aula/desktop/window_layout.hpp): a window whose size followed its text widened as a mark
// appeared, and windows placed by the window manager opened on top of each other.

#include <aula/config/config.hpp>
#include <aula/desktop/window_layout.hpp>

#include <string>

class QWidget;

namespace aula::app {

// Once `window` has accepted a close (the window manager's close button, Ctrl+W), the
// application quits (exit code 0). A close the window refuses ends nothing.
void quitWhenClosed(QWidget& window);

// Fixes the window's size and moves its frame where `placement` says (before it is shown). A
// size smaller than what the window's content needs is kept, and said once on stderr by `program`.
void placeWindow(QWidget& window, const desktop::Placement& placement, const std::string& program);
// The process's main window: the first window its settings declare (`<Prefix>.Size`).
void placeMainWindow(QWidget& window, const std::string& program, const config::Config& settings);

}  // namespace aula::app
