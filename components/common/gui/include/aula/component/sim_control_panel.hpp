#pragma once
// The simulator's pace from the component's window: a real-time factor (1x, 5x, 20x, as fast as
// possible), pause/resume, and one step while paused; Ctrl+] and Ctrl+[ pick the next faster or
// slower speed from anywhere in the window. Sent on SIM_CONTROL; a headless run never
// has this window, so grading runs are never slowed by it.

#include <aula/lcm/bus.hpp>
#include <lcm/lcm-cpp.hpp>

#include <QComboBox>
#include <QPushButton>
#include <QWidget>

namespace aula::component {

class SimControlPanel : public QWidget {
 public:
  explicit SimControlPanel(lcmbus::Bus& bus, QWidget* parent = nullptr);

 private:
  void send(int8_t command, double real_time_factor = 0);

  lcmbus::Bus& bus_;
  QComboBox* speed_;
  QPushButton* pause_;
  QPushButton* step_;
  bool paused_ = false;
};

}  // namespace aula::component
