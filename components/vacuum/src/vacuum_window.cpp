#include "vacuum_window.hpp"

#include "coverage_plot.hpp"

#include <aula/geometry/map_transform.hpp>
#include <aula/gui/screenshot.hpp>


#include <QApplication>
#include <QHBoxLayout>
#include <QPainter>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace aula::vacuum {

VacuumWindow::VacuumWindow(VacuumComponent& component) : component_(component) {
  setWindowTitle("Vacuum cleaner");
  const geometry::MapTransform& transform = component_.map().transform;
  transform_ = transform;
  map_image_ = component_.map().image;
  const QImage map(map_image_.data, map_image_.cols, map_image_.rows, static_cast<int>(map_image_.step),
                   QImage::Format_Grayscale8);
  auto* central = new QWidget(this);
  auto* layout = new QHBoxLayout(central);
  map_ = new gui::MapView(map.copy(), transform, central);
  map_->setMinimumSize(480, 480);  // the window's size is Vacuum.Window.Size; the map takes what is left
  layout->addWidget(map_, 1);
  auto* teleop = new gui::Teleoperator(component_.maxV(), component_.maxW(), central);
  side_ = new component::SidePanel(component_, *teleop, central);
  side_->status()->setMinimumWidth(260);
  side_->layout()->addWidget(teleop);
  plot_ = new CoveragePlot(component_.runDurationS(), central);
  side_->layout()->addWidget(plot_, 1);
  layout->addWidget(side_);
  setCentralWidget(central);
  connect(teleop, &gui::Teleoperator::velocityChanged, this,
          [this](double v, double w) { component_.teleoperate(v, w); });
  // The cleaned area is painted at every control tick of sim time (4 cm apart at full speed),
  // not at the GUI's refresh rate, so the band has no gaps however fast the simulation runs.
  component_.setOnTick([this](int64_t utime) { onTick(utime); });
  map_->setOverlay([this](QPainter& painter) { drawBelief(painter); });
  connect(&timer_, &QTimer::timeout, this, &VacuumWindow::refresh);
  timer_.start(50);
  refresh();
}

void VacuumWindow::onTick(int64_t utime) {
  if (component_.generation() != shown_generation_) {
    shown_generation_ = component_.generation();
    map_->clearPainted();
    plot_->clear();
    coverage_.reset();
    run_start_utime_ = last_sample_utime_ = -1;
    poses_before_start_.clear();
    end_said_ = false;
    belief_ = BeliefShown{};
  }
  followBelief();
  const auto& p = component_.truePose();
  if (!p.received() || p.utime() == last_pose_utime_) return;
  last_pose_utime_ = p.utime();
  map_->paintDisc(p.getX(), p.getY(), component_.robotRadiusM(), QColor(80, 170, 255, 200));
  // The percentage counts from the first Run to the end of the referee's episode, on the
  // referee's own grid (free floor reachable from where the robot stands) and the same poses
  // in time, sampled once per sim second for the plot.
  int64_t started_utime = component_.startedUtime();
  if (started_utime < 0) {
    // A replay (view-only): the algorithm never runs in this window; the referee's word (once
    // per sim second) says when the recorded episode started, and the poses seen meanwhile wait.
    const auto said = component_.refereeStatus().latest();
    if (said && said->started && said->generation == component_.generation()) {
      started_utime = said->utime - std::llround(said->elapsed_s * 1e6);
    }
  }
  if (started_utime < 0) {
    constexpr std::size_t kPosesBeforeStart = 2000;  // 40 s of poses at 50 Hz
    poses_before_start_.push_back({p.utime(), p.getX(), p.getY()});
    if (poses_before_start_.size() > kPosesBeforeStart) poses_before_start_.pop_front();
    return;
  }
  const int64_t episode_us = static_cast<int64_t>(std::llround(component_.runDurationS() * 1e6));
  auto inEpisode = [&](int64_t utime) { return utime >= run_start_utime_ && utime - run_start_utime_ <= episode_us; };
  if (run_start_utime_ < 0) {
    run_start_utime_ = started_utime;
    const PoseSeen first = poses_before_start_.empty() ? PoseSeen{p.utime(), p.getX(), p.getY()} : poses_before_start_.front();
    coverage_ = std::make_unique<CoverageGrid>(map_image_, transform_, first.x_m, first.y_m);
    for (const PoseSeen& seen : poses_before_start_) {
      if (inEpisode(seen.utime)) coverage_->markDisc(seen.x_m, seen.y_m, component_.robotRadiusM());
    }
    poses_before_start_.clear();
  }
  if (!inEpisode(p.utime())) return;
  coverage_->markDisc(p.getX(), p.getY(), component_.robotRadiusM());
  if (utime - last_sample_utime_ >= 1'000'000) {
    last_sample_utime_ = utime;
    plot_->addSample((utime - run_start_utime_) / 1e6, coverage_->coveragePercent());
  }
}

// The algorithm's belief after this tick's execute() (the window's thread: no call is running).
// Its frame is its own: it is put on the world where the truth was when it first spoke.
void VacuumWindow::followBelief() {
  const component::Belief& belief = component_.belief();
  const auto& truth = component_.truePose();
  if (component_.algorithm().hung() || !belief.hasPose() || !truth.received()) return;
  if (!belief_.placed) {
    belief_.placed = true;
    belief_.dx_m = truth.getX() - belief.x_m();
    belief_.dy_m = truth.getY() - belief.y_m();
  }
  belief_.has_pose = true;
  belief_.x_m = belief.x_m() + belief_.dx_m;
  belief_.y_m = belief.y_m() + belief_.dy_m;
  belief_.yaw_rad = belief.yaw_rad();
  if (belief.mapVersion() == belief_.map_version) return;
  belief_.map_version = belief.mapVersion();
  const component::BeliefMap& map = belief.map();
  QImage image(map.width, map.height, QImage::Format_ARGB32);
  for (int row = 0; row < map.height; ++row) {
    auto* line = reinterpret_cast<QRgb*>(image.scanLine(map.height - 1 - row));
    for (int col = 0; col < map.width; ++col) {
      const uint8_t cell = map.cells[static_cast<size_t>(row) * map.width + col];
      line[col] = cell >= 192 ? qRgba(200, 0, 200, 230) : cell <= 64 ? qRgba(200, 0, 200, 28) : qRgba(0, 0, 0, 0);
    }
  }
  belief_.map = image;
  belief_.map_world = QRectF(map.origin_x_m + belief_.dx_m, map.origin_y_m + belief_.dy_m, map.width * map.resolution_m,
                             map.height * map.resolution_m);
}

void VacuumWindow::drawBelief(QPainter& painter) const {
  if (!belief_.map.isNull()) {
    const QRectF& w = belief_.map_world;
    const QPointF top_left = map_->worldToWidget(w.left(), w.top() + w.height());
    const QPointF bottom_right = map_->worldToWidget(w.left() + w.width(), w.top());
    painter.drawImage(QRectF(top_left, bottom_right), belief_.map);
  }
  if (!belief_.has_pose) return;
  const QPointF centre = map_->worldToWidget(belief_.x_m, belief_.y_m);
  const QPointF ahead = map_->worldToWidget(belief_.x_m + 0.3 * std::cos(belief_.yaw_rad), belief_.y_m + 0.3 * std::sin(belief_.yaw_rad));
  const double radius_px = component_.robotRadiusM() * map_->pixelsPerMetre();
  painter.setPen(QPen(QColor(200, 0, 200), 2));
  painter.setBrush(Qt::NoBrush);
  painter.drawEllipse(centre, radius_px, radius_px);
  painter.drawLine(centre, ahead);
}

void VacuumWindow::refresh() {
  const auto& pose = component_.truePose();
  if (pose.received()) map_->setRobot(pose.getX(), pose.getY(), pose.getYaw(), 2 * component_.robotRadiusM(), 2 * component_.robotRadiusM());
  const auto said = component_.refereeStatus().latest();
  side_->show(component_.running(), said);
  if (said && said->finished && !end_said_) {
    end_said_ = true;
    std::fprintf(stderr, "vacuum-cleaner: this window counted %.2f %% of the floor cleaned since Run\n",
                 coverage_ ? coverage_->coveragePercent() : 0.0);
  }
  side_->status()->setText(QString("sim time %1 s\ncleaned %4 % of the floor since Run\nv = %2 m/s   w = %3 rad/s%5")
                       .arg(component_.simTimeUs() / 1e6, 0, 'f', 1)
                       .arg(component_.motors().getV(), 0, 'f', 2)
                       .arg(component_.motors().getW(), 0, 'f', 2)
                       .arg(coverage_ ? coverage_->coveragePercent() : 0.0, 0, 'f', 1)
                       .arg(belief_.has_pose ? "\nmagenta: its belief (api.belief)" : ""));
}

void VacuumWindow::screenshotAfter(const QString& png_path, int64_t sim_us) {
  // The panel too: its own timer (250 ms of wall time) may not have shown a fault yet.
  gui::screenshotAtSimTime(*this, [this] { return component_.simTimeUs(); }, [this] { refresh(); side_->algorithm()->refresh(); },
                           png_path, sim_us);
}

}  // namespace aula::vacuum
