#pragma once
// The vacuum cleaner window: the house map with the robot and the area it has cleaned (its
// real 0.33 m disc footprint, from the true pose: shown to the student, never given to the
// algorithm), the "Run my algorithm" toggle, the teleoperator and Stop, and the cleaned
// percentage since Run (the referee's CoverageGrid on the same map) with its plot.

#include <aula/component/algorithm_panel.hpp>
#include <aula/component/referee_status_label.hpp>
#include <aula/component/sim_control_panel.hpp>
#include <aula/gui/map_view.hpp>
#include <aula/gui/run_toggle.hpp>
#include <aula/gui/teleoperator.hpp>
#include <aula/scoring/coverage_grid.hpp>
#include <aula/vacuum/vacuum_component.hpp>

#include <QLabel>
#include <QMainWindow>
#include <QTimer>

#include <deque>
#include <memory>
#include <opencv2/core.hpp>

namespace aula::vacuum {

class CoveragePlot;

class VacuumWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit VacuumWindow(VacuumComponent& component);
  // Grabs the window to png_path once sim time reaches sim_us, then quits.
  void screenshotAfter(const QString& png_path, int64_t sim_us);

 private:
  void refresh();
  void onTick(int64_t utime);

  VacuumComponent& component_;
  gui::MapView* map_ = nullptr;
  gui::RunToggle* run_ = nullptr;
  QLabel* status_ = nullptr;
  component::RefereeStatusLabel* referee_ = nullptr;
  bool end_said_ = false;  // the window's own count, said once in the log at the referee's end
  component::AlgorithmPanel* algorithm_ = nullptr;
  int shown_generation_ = 0;  // a new episode (hot reload) clears the cleaned area
  QTimer timer_;
  CoveragePlot* plot_ = nullptr;
  int64_t last_pose_utime_ = -1;
  cv::Mat map_image_;
  geometry::MapTransform transform_;
  std::unique_ptr<CoverageGrid> coverage_;  // from the first Run
  int64_t run_start_utime_ = -1, last_sample_utime_ = -1;
  // A replay's poses before the referee says when the episode started (at most kPosesBeforeStart).
  struct PoseSeen {
    int64_t utime;
    double x_m, y_m;
  };
  std::deque<PoseSeen> poses_before_start_;
};

}  // namespace aula::vacuum
