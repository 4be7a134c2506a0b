#pragma once
// The TeleTaxi window: the city map (double-click picks the destination), Generate Path, GO!,
// Stop, the taxi and its path, labels, and the teleoperator. Refreshed every 50 ms of wall time;
// the algorithm runs on sim time in TaxiComponent.

#include <aula/gui/map_view.hpp>
#include <aula/gui/teleoperator.hpp>
#include <aula/teletaxi/taxi_component.hpp>

#include <QLabel>
#include <aula/component/algorithm_panel.hpp>
#include <aula/component/referee_status_label.hpp>
#include <aula/component/sim_control_panel.hpp>
#include <QMainWindow>
#include <QTimer>

namespace aula::teletaxi {

class TaxiWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit TaxiWindow(TaxiComponent& component);
  // Grabs the window to `png_path` once the taxi is on the map (with autostart: once the referee
  // ended the episode), then quits the application.
  bool screenshotWhenReady(const QString& png_path);

 private:
  void refresh();
  void showGridField();
  void updatePathOverlay();
  bool reloadAlgorithm();  // hot reload: the path is gone and the taxi is back at its start

  TaxiComponent& component_;
  gui::MapView* map_ = nullptr;
  gui::Teleoperator* teleop_ = nullptr;
  QLabel* destination_label_ = nullptr;
  QLabel* position_label_ = nullptr;
  QLabel* velocity_label_ = nullptr;
  QLabel* status_label_ = nullptr;
  component::RefereeStatusLabel* referee_ = nullptr;
  int end_shown_generation_ = -1;  // the episode whose end the status line says
  component::AlgorithmPanel* algorithm_ = nullptr;
  QLabel* grid_window_ = nullptr;
  QTimer timer_;
  bool path_shown_ = false;
};

}  // namespace aula::teletaxi
