#pragma once
// Autopark's referee window: the sim-time clock from Run, the orientation gauge (green within
// +-15 degrees, orange to +-45, red beyond), the three distances, a collision bar, "Show me my
// mark" and the mark by itself at the end.

#include "parking_referee_node.hpp"

#include <aula/gui/gauge.hpp>
#include <aula/gui/mark_label.hpp>

#include <QLabel>
#include <QProgressBar>
#include <QTimer>
#include <QWidget>

namespace aula::autopark {

class ParkingRefereeWindow : public QWidget {
  Q_OBJECT
 public:
  explicit ParkingRefereeWindow(ParkingRefereeNode& node);
  void showMark();

 private:
  void refresh();
  ParkingRefereeNode& node_;
  QLabel* clock_ = nullptr;
  QLabel* distances_ = nullptr;
  gui::MarkLabel* mark_ = nullptr;
  QProgressBar* collisions_ = nullptr;
  gui::Gauge* orientation_ = nullptr;
  QTimer timer_;
};

}  // namespace aula::autopark
