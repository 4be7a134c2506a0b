#include "aula/gui/run_toggle.hpp"

namespace aula::gui {

RunToggle::RunToggle(QWidget* parent) : QPushButton(parent) {
  setMinimumHeight(40);
  setToolTip("Runs or stops your algorithm (F5)");
  setRunning(false);
  connect(this, &QPushButton::clicked, this, [this] {
    setRunning(!running_);
    emit runningChanged(running_);
  });
}

void RunToggle::setRunning(bool running) {
  running_ = running;
  setText(running ? "Stop my algorithm (F5)" : "Run my algorithm (F5)");
  setShortcut(QKeySequence(Qt::Key_F5));  // after setText, which sets the text's mnemonic (none) as the shortcut
  setStyleSheet(running ? "background-color: #3c3; font-weight: bold;"
                        : "background-color: #d33; color: white; font-weight: bold;");
}

}  // namespace aula::gui
