#pragma once
// The vacuum referee window: coverage percentage (label and bar), the house map with the
// cleaned area, a 900 s sim-time countdown with an analogue clock, and the mark at the end.

#include "coverage_referee_node.hpp"

#include <aula/gui/gauge.hpp>
#include <aula/gui/mark_label.hpp>
#include <aula/gui/map_view.hpp>

#include <QLabel>
#include <QProgressBar>
#include <QTimer>
#include <QWidget>

namespace aula::vacuum {

class CoverageRefereeWindow : public QWidget {
  Q_OBJECT
 public:
  explicit CoverageRefereeWindow(CoverageRefereeNode& node);
  void showMark();

 private:
  void refresh();
  CoverageRefereeNode& node_;
  gui::MapView* map_ = nullptr;
  int shown_episode_ = 0;  // a hot reload clears the painted area
  QLabel* percent_ = nullptr;
  QProgressBar* bar_ = nullptr;
  QLabel* countdown_ = nullptr;
  gui::Gauge* clock_ = nullptr;
  gui::MarkLabel* mark_ = nullptr;
  QTimer timer_;
};

}  // namespace aula::vacuum
