#pragma once
// A process's main window (a component's, a referee's): closing it ends the process, whatever
// other windows are open (TeleTaxi's "Grid Field"). Qt by itself quits only when the last
// top-level window closes, so the run went on behind a window the student had closed.

class QWidget;

namespace aula::app {

// Once `window` has accepted a close (the window manager's close button, Ctrl+W), the
// application quits (exit code 0). A close the window refuses ends nothing.
void quitWhenClosed(QWidget& window);

}  // namespace aula::app
