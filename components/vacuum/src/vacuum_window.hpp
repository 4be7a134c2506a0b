#pragma once
// The vacuum cleaner window: the house map with the robot and the area it has cleaned (its
// real 0.33 m disc footprint, from the true pose: shown to the student, never given to the
// algorithm), the "Run my algorithm" toggle, the teleoperator and Stop, and the cleaned
// percentage since Run (the referee's CoverageGrid on the same map) with its plot. In magenta,
// what the algorithm says it believes (api.belief: its own map and pose, in its own frame, put
// on the world where the truth was when it first said it), beside the truth.

#include <aula/component/side_panel.hpp>
#include <aula/gui/map_view.hpp>
#include <aula/gui/teleoperator.hpp>
#include <aula/scoring/coverage_grid.hpp>
#include <aula/vacuum/vacuum_component.hpp>

#include <QMainWindow>
#include <QTimer>

#include <deque>
#include <memory>
#include <opencv2/core.hpp>

namespace aula::vacuum {

// The referee's own coverage measure (libs/scoring), by its name here.
using scoring::CoverageGrid;

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
  void followBelief();
  void drawBelief(QPainter& painter) const;

  VacuumComponent& component_;
  gui::MapView* map_ = nullptr;
  bool end_said_ = false;  // the window's own count, said once in the log at the referee's end
  component::SidePanel* side_ = nullptr;  // Run, speed, algorithm, referee, status
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
  // The algorithm's belief as shown: its frame's offset onto the world, its pose, its map.
  struct BeliefShown {
    bool placed = false, has_pose = false;
    double dx_m = 0, dy_m = 0, x_m = 0, y_m = 0, yaw_rad = 0;
    int64_t map_version = 0;
    QImage map;  // occupied cells opaque, free ones faint, top row the map's highest y
    QRectF map_world;  // x, y of its lower-left corner in the world, width, height in metres
  };
  BeliefShown belief_;
};

}  // namespace aula::vacuum
