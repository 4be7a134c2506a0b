#pragma once
// The Autopark window: a local map of the street (about 12 px/m: parked cars and curbs in
// black, the ideal parking pose as a green rectangle, the car as a yellow rectangle with black
// wheels, a red trail of recent positions), a laser view with the car in the centre and the
// three scans in three colours at their true mounting poses, the Run toggle, the
// teleoperator and Stop.

#include <aula/autopark/autopark_component.hpp>
#include <aula/scoring/parking_geometry.hpp>
#include <aula/gui/map_view.hpp>

#include <aula/component/side_panel.hpp>
#include <QMainWindow>
#include <QTimer>

#include <deque>

namespace aula::autopark {

// The street's geometry (libs/scoring), by its names here.
using scoring::ParkingScene;
using scoring::sceneNamesOf;

class LaserView : public QWidget {
 public:
  explicit LaserView(const AutoparkComponent& component, QWidget* parent = nullptr);
  QSize sizeHint() const override { return {360, 360}; }

 protected:
  void paintEvent(QPaintEvent*) override;

 private:
  const AutoparkComponent& component_;
};

class AutoparkWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit AutoparkWindow(AutoparkComponent& component);
  void screenshotAfter(const QString& png_path, int64_t sim_us);

 private:
  void refresh();
  void drawCar(QPainter& painter) const;

  AutoparkComponent& component_;
  ParkingScene scene_;
  gui::MapView* map_ = nullptr;
  LaserView* lasers_ = nullptr;
  component::SidePanel* side_ = nullptr;  // Run, speed, algorithm, referee, status
  int shown_generation_ = 0;  // a new episode (hot reload) clears the trail
  QTimer timer_;
  std::deque<QPointF> trail_;  // recent positions (a ring of the last kTrail)
  int64_t last_trail_utime_ = -1;
};

}  // namespace aula::autopark
