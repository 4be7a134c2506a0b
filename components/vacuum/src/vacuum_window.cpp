#include "vacuum_window.hpp"

#include <aula/component/widgets/screenshot.hpp>
#include <aula/world/map_transform.hpp>

#include <QApplication>
#include <QHBoxLayout>
#include <QVBoxLayout>

#include <cmath>
#include <stdexcept>

namespace aula::vacuum {

VacuumWindow::VacuumWindow(VacuumComponent& component) : component_(component) {
  setWindowTitle("Vacuum cleaner");
  std::string image;
  const auto yaml = std::string(AULA_MAPS_DIR) + "/" + component_.mapYaml();
  const world::MapTransform transform = world::MapTransform::load(yaml, &image);
  QImage map(QString::fromStdString(image));
  if (map.isNull()) throw std::runtime_error(image + ": cannot read the map image");
  auto* central = new QWidget(this);
  auto* layout = new QHBoxLayout(central);
  map_ = new component::MapView(map.convertToFormat(QImage::Format_Grayscale8), transform, central);
  map_->setMinimumSize(560, 560);
  layout->addWidget(map_, 1);
  auto* side = new QVBoxLayout;
  run_ = new component::RunToggle(central);
  status_ = new QLabel(central);
  status_->setWordWrap(true);
  status_->setMinimumWidth(260);
  auto* teleop = new component::Teleoperator(component_.maxV(), component_.maxW(), central);
  side->addWidget(run_);
  side->addWidget(status_);
  side->addWidget(teleop);
  side->addStretch(1);
  layout->addLayout(side);
  setCentralWidget(central);
  connect(run_, &component::RunToggle::runningChanged, this, [this](bool on) { component_.setRunning(on); });
  connect(teleop, &component::Teleoperator::velocityChanged, this,
          [this](double v, double w) { component_.teleoperate(v, w); });
  // The cleaned area is painted at every control tick of sim time (4 cm apart at full speed),
  // not at the GUI's refresh rate, so the band has no gaps however fast the simulation runs.
  component_.setOnTick([this](int64_t) {
    const auto& p = component_.truePose();
    if (p.received() && p.utime() != last_pose_utime_) {
      last_pose_utime_ = p.utime();
      map_->paintDisc(p.getX(), p.getY(), 0.165, QColor(80, 170, 255, 200));
    }
  });
  connect(&timer_, &QTimer::timeout, this, &VacuumWindow::refresh);
  timer_.start(50);
  refresh();
}

void VacuumWindow::refresh() {
  const auto& pose = component_.truePose();
  if (pose.received()) map_->setRobot(pose.getX(), pose.getY(), pose.getYaw(), 0.33, 0.33);
  run_->setRunning(component_.running());
  status_->setText(QString("Algorithm: %1\nsim time %2 s\nv = %3 m/s   w = %4 rad/s")
                       .arg(QString::fromStdString(component_.algorithmName()))
                       .arg(component_.simTimeUs() / 1e6, 0, 'f', 1)
                       .arg(component_.motors().getV(), 0, 'f', 2)
                       .arg(component_.motors().getW(), 0, 'f', 2));
}

void VacuumWindow::screenshotAfter(const QString& png_path, int64_t sim_us) {
  component::screenshotAtSimTime(*this, [this] { return component_.simTimeUs(); }, [this] { refresh(); }, png_path, sim_us);
}

}  // namespace aula::vacuum
