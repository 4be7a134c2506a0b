#pragma once
// "Run my algorithm" / "Stop my algorithm": green while the algorithm runs, red while stopped.

#include <QPushButton>

namespace aula::gui {

class RunToggle : public QPushButton {
  Q_OBJECT
 public:
  explicit RunToggle(QWidget* parent = nullptr);
  void setRunning(bool running);  // shows the state without emitting
  bool running() const { return running_; }

 signals:
  void runningChanged(bool running);  // the user clicked

 private:
  bool running_ = false;
};

}  // namespace aula::gui
