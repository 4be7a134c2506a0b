#pragma once
// TeleTaxi's referee window: the sim-time clock (from GO! to arrival), straight-line and
// travelled distance, speedometer (km/h), heading dial, "Show me my mark" and the mark.

#include "taxi_referee_node.hpp"

#include <aula/gui/gauge.hpp>
#include <aula/gui/mark_label.hpp>

#include <QLabel>
#include <QTimer>
#include <QWidget>

namespace aula::teletaxi {

class TaxiRefereeWindow : public QWidget {
  Q_OBJECT
 public:
  explicit TaxiRefereeWindow(TaxiRefereeNode& node);
  void showMark();

 private:
  void refresh();
  TaxiRefereeNode& node_;
  QLabel* clock_ = nullptr;
  QLabel* distances_ = nullptr;
  gui::MarkLabel* mark_ = nullptr;
  gui::Gauge* speed_ = nullptr;
  gui::Gauge* heading_ = nullptr;
  QTimer timer_;
};

}  // namespace aula::teletaxi
