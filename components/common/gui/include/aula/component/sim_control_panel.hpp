#pragma once
// The simulator's pace from the component's window: a real-time factor (1x, 5x, 20x, as fast as
// possible), pause/resume, and one step while paused; Ctrl+] and Ctrl+[ pick the next faster or
// slower speed from anywhere in the window. Sent on SIM_CONTROL; a headless run never
// has this window, so grading runs are never slowed by it. Under them, while the machine cannot
// keep the pace asked (the clock's measure), that it cannot.

#include <aula/lcm/bus.hpp>
#include <aula/sim_clock_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QWidget>

#include <string>

namespace aula::component {

// The pace line for `tick`: "6.2x, not the 10x asked: the machine cannot keep up (the run is the
// same, slower)" (in lockstep); "" while it keeps the pace, paused, or before a measure.
std::string paceText(const aula::sim_clock_t& tick);

class SimControlPanel : public QWidget {
 public:
  explicit SimControlPanel(lcmbus::Bus& bus, QWidget* parent = nullptr);
  ~SimControlPanel() override;
  SimControlPanel(const SimControlPanel&) = delete;
  SimControlPanel& operator=(const SimControlPanel&) = delete;

 private:
  void send(int8_t command, double real_time_factor = 0);
  void onClock(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t* tick);

  lcmbus::Bus& bus_;
  QComboBox* speed_;
  QPushButton* pause_;
  QPushButton* step_;
  QLabel* pace_;
  std::string pace_text_;  // what pace_ says
  lcm::Subscription* clock_ = nullptr;
  bool paused_ = false;
};

}  // namespace aula::component
