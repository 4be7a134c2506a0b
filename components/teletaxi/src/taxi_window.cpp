#include "taxi_window.hpp"

#include <aula/app/main_window.hpp>
#include <aula/geometry/angles.hpp>
#include <aula/gui/screenshot.hpp>

#include <QApplication>
#include <QPainter>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QVBoxLayout>

#include <cmath>

namespace aula::teletaxi {
namespace {
QImage toQImage(const cv::Mat& gray) {
  return QImage(gray.data, gray.cols, gray.rows, static_cast<int>(gray.step), QImage::Format_Grayscale8).copy();
}
}  // namespace

TaxiWindow::TaxiWindow(TaxiComponent& component) : component_(component) {
  setWindowTitle("TeleTaxi - Gradient Path Planning");
  auto* central = new QWidget(this);
  auto* layout = new QHBoxLayout(central);
  map_ = new gui::MapView(toQImage(component_.grid().getMap()), component_.grid().transform(), central);
  map_->setMinimumSize(600, 600);
  layout->addWidget(map_, 1);

  auto* side = new QVBoxLayout;
  auto* info = new QGroupBox("Taxi", central);
  auto* info_layout = new QVBoxLayout(info);
  destination_label_ = new QLabel(info);
  position_label_ = new QLabel(info);
  velocity_label_ = new QLabel(info);
  status_label_ = new QLabel(info);
  status_label_->setWordWrap(true);
  // Four lines, whatever it says: GO! and Stop below it stay where the student clicks.
  status_label_->setFixedHeight(4 * status_label_->fontMetrics().lineSpacing());
  status_label_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  velocity_label_->setWordWrap(true);
  info->setMinimumWidth(330);
  referee_ = new component::RefereeStatusLabel("GO!", info);
  for (auto* l : {destination_label_, position_label_, velocity_label_, status_label_}) info_layout->addWidget(l);
  info_layout->addWidget(referee_);
  side->addWidget(info);
  algorithm_ = new component::AlgorithmPanel(component_.algorithm(), [this] { return reloadAlgorithm(); }, central);
  side->addWidget(algorithm_);
  side->addWidget(new component::SimControlPanel(component_.bus(), central));

  auto* generate = new QPushButton("Generate Path", central);
  auto* go = new QPushButton("GO!", central);
  auto* stop = new QPushButton("Stop", central);
  go->setStyleSheet("background-color: #3c3; font-weight: bold;");
  stop->setStyleSheet("background-color: #d33; font-weight: bold;");
  side->addWidget(generate);
  side->addWidget(go);
  side->addWidget(stop);
  auto* teleop = teleop_ = new gui::Teleoperator(component_.maxV(), component_.maxW(), central);
  side->addWidget(teleop);
  side->addStretch(1);
  layout->addLayout(side);
  setCentralWidget(central);

  connect(map_, &gui::MapView::worldDoubleClicked, this, [this](double x, double y) {
    if (const auto problem = component_.destinationProblem(x, y)) {
      status_label_->setText("Destination refused: " + QString::fromStdString(*problem));
      return;
    }
    component_.setDestination(x, y);
    map_->setPath({});
    path_shown_ = false;
    status_label_->setText("Destination chosen: press Generate Path");
  });
  connect(generate, &QPushButton::clicked, this, [this] {
    algorithm_->reloadIfRebuilt();
    std::string why;
    if (!component_.generatePath(&why)) {
      status_label_->setText(QString::fromStdString(why));
    } else if (!component_.hasPath()) {
      // Say what happened, not what was hoped for: the template's generatePath() marks nothing.
      status_label_->setText("generatePath() returned without marking a path (Grid::setPathVal / setPathFinded): "
                             "nothing to follow yet");
    } else {
      status_label_->setText("Path generated: press GO!");
    }
    path_shown_ = false;
  });
  connect(go, &QPushButton::clicked, this, [this] {
    std::string why;
    status_label_->setText(component_.go(&why) ? "Driving..." : QString::fromStdString(why));
  });
  connect(stop, &QPushButton::clicked, this, [this, teleop] {
    component_.stop();
    teleop->stop();
    status_label_->setText("Stopped");
  });
  connect(teleop, &gui::Teleoperator::velocityChanged, this,
          [this](double v, double w) { component_.teleoperate(v, w); });
  // The student's generatePath() calls showGrid() on the algorithm's thread: the window opens on
  // the GUI's, once the call has returned.
  component_.grid().setShowGridHandler(
      [this] { QMetaObject::invokeMethod(this, [this] { showGridField(); }, Qt::QueuedConnection); });
  connect(&timer_, &QTimer::timeout, this, &TaxiWindow::refresh);
  timer_.start(50);
  refresh();
}

bool TaxiWindow::reloadAlgorithm() {
  teleop_->stop();  // the taxi is put back at its start: the teleoperator lets go of it too
  const bool loaded = component_.reloadAlgorithm();
  map_->setPath({});
  status_label_->setText(loaded ? "Algorithm reloaded, taxi back at its start: press Generate Path" : "The reload failed: see below");
  return loaded;
}

void TaxiWindow::updatePathOverlay() {
  const Grid& grid = component_.grid();
  std::vector<QPointF> cells;
  // Path cells in the order of the taxi -> destination descent is not stored in the Grid, so
  // draw the marked cells as points (green), as the original did.
  for (int y = 0; y < grid.getHeight(); ++y) {
    for (int x = 0; x < grid.getWidth(); ++x) {
      if (grid.getPathVal(x, y) != 0.0f) {
        const auto [wx, wy] = grid.gridToWorld(x, y);
        cells.emplace_back(wx, wy);
      }
    }
  }
  map_->setOverlay([this, cells](QPainter& p) {
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0, 180, 0));
    const double r = std::max(1.5, map_->pixelsPerMetre() * component_.grid().transform().resolution_m * 0.5);
    for (const auto& c : cells) p.drawEllipse(map_->worldToWidget(c.x(), c.y()), r, r);
  });
  path_shown_ = true;
}

void TaxiWindow::refresh() {
  const auto& pose = component_.pose();
  if (pose.received()) map_->setRobot(pose.getX(), pose.getY(), pose.getYaw(), 4.0, 2.0);
  const auto dest = component_.destination();
  map_->setMarker(dest ? std::optional<QPointF>(QPointF(dest->first, dest->second)) : std::nullopt);
  destination_label_->setText(dest ? QString("Destination: (%1, %2) m").arg(dest->first, 0, 'f', 1).arg(dest->second, 0, 'f', 1)
                                   : QString("Destination: double-click on the map"));
  position_label_->setText(pose.received() ? QString("Position: (%1, %2) m, %3 deg")
                                                 .arg(pose.getX(), 0, 'f', 1)
                                                 .arg(pose.getY(), 0, 'f', 1)
                                                 .arg(geometry::headingDeg(pose.getYaw()), 0, 'f', 0)
                                           : QString("Position: waiting for the simulator"));
  velocity_label_->setText(QString("v = %1 m/s   w = %2 rad/s\nsim time %3 s")
                               .arg(component_.motors().getV(), 0, 'f', 2)
                               .arg(component_.motors().getW(), 0, 'f', 2)
                               .arg(component_.simTimeUs() / 1e6, 0, 'f', 1));
  const auto said = component_.refereeStatus().latest();
  referee_->setStatus(said);
  if (said && said->finished && end_shown_generation_ != component_.generation()) {
    // The referee ended the episode: the component stopped the algorithm, so the teleoperator
    // drives again. Say how it ended instead of "Driving...".
    end_shown_generation_ = component_.generation();
    status_label_->setText(QString::fromStdString(said->ending) +
                           " - the algorithm is stopped; the teleoperator drives the taxi");
  }
  if (const auto refused = component_.refusal()) {
    status_label_->setText("Autostart refused: " + QString::fromStdString(*refused));
  }
  if (component_.grid().isPathFinded() && !path_shown_) updatePathOverlay();
  if (!component_.grid().isPathFinded() && path_shown_) {
    map_->setOverlay(nullptr);
    path_shown_ = false;
  }
}

void TaxiWindow::showGridField() {
  if (grid_window_ == nullptr) {
    grid_window_ = new QLabel(this, Qt::Window);  // a window of its own, owned by the main one
    grid_window_->setWindowTitle("Grid Field");
    grid_window_->setAlignment(Qt::AlignCenter);
    app::placeWindow(*grid_window_, component_.gridWindow(), "teletaxi");
  }
  // The field fills the window's fixed size, whatever the map's shape.
  const QImage field = toQImage(component_.grid().fieldImage());
  grid_window_->setPixmap(
      QPixmap::fromImage(field.scaled(grid_window_->size(), Qt::KeepAspectRatio, Qt::FastTransformation)));
  grid_window_->show();
}

bool TaxiWindow::screenshotWhenReady(const QString& png_path) {
  auto* poll = new QTimer(this);
  auto started = std::make_shared<int>(0);
  connect(poll, &QTimer::timeout, this, [this, png_path, poll, started] {
    refresh();
    // With autostart, wait until the referee has ended the episode, so the picture shows the
    // path, the taxi at the destination and how the episode ended (2 minutes at most).
    const auto said = component_.refereeStatus().latest();
    const bool ready = component_.pose().received() && (!component_.autostart() || (said && said->finished));
    if (ready || ++*started > (component_.autostart() ? 1200 : 100)) {
      poll->stop();
      gui::saveWidgetPng(*this, png_path);
      if (grid_window_ != nullptr) gui::saveWidgetPng(*grid_window_, QString(png_path).replace(".png", "_grid.png"));
      QApplication::quit();
    }
  });
  poll->start(100);
  return true;
}

}  // namespace aula::teletaxi
