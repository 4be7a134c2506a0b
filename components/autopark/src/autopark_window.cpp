#include "autopark_window.hpp"

#include <aula/geometry/angles.hpp>
#include <aula/gui/screenshot.hpp>
#include <aula/gui/teleoperator.hpp>
#include <aula/world/occupancy_map.hpp>

#include <QApplication>
#include <QHBoxLayout>
#include <QPainter>
#include <QVBoxLayout>

#include <cmath>

namespace aula::autopark {
namespace {

constexpr double kPixelsPerMetre = 12.0;
constexpr size_t kTrail = 600;  // 30 s at 20 Hz

QImage streetImage(const world::WorldSpec& world, geometry::MapTransform& transform) {
  const auto b = world::staticBounds(world);  // x_min, y_min, x_max, y_max
  transform.resolution_m = 1.0 / kPixelsPerMetre;
  transform.origin_x_m = b[0] - 1.0;
  transform.origin_y_m = b[3] + 1.0;
  transform.width_px = static_cast<int>(std::ceil((b[2] - b[0] + 2.0) * kPixelsPerMetre));
  transform.height_px = static_cast<int>(std::ceil((b[3] - b[1] + 2.0) * kPixelsPerMetre));
  const cv::Mat occupancy = world::rasterizeOccupancy(world, transform, 0.005, 1.5);
  QImage image(occupancy.cols, occupancy.rows, QImage::Format_Grayscale8);
  for (int r = 0; r < occupancy.rows; ++r) std::memcpy(image.scanLine(r), occupancy.ptr(r), occupancy.cols);
  return image;
}

QPolygonF rectangle(const gui::MapView& map, const geometry::OrientedBox& rect) {
  QPolygonF poly;
  for (const auto& c : rect.corners()) poly << map.worldToWidget(c.x(), c.y());
  return poly;
}

}  // namespace

AutoparkWindow::AutoparkWindow(AutoparkComponent& component)
    : component_(component), scene_(ParkingScene::fromWorld(component.world(), component.robotName())) {
  setWindowTitle("Autopark");
  auto* central = new QWidget(this);
  auto* layout = new QVBoxLayout(central);
  geometry::MapTransform transform;
  const QImage street = streetImage(component_.world(), transform);
  map_ = new gui::MapView(street, transform, central);
  // The whole street at 12 px/m, as tall as it is (the rest of the height goes to the lasers).
  map_->setFixedSize(street.width(), street.height());
  layout->addWidget(map_, 0, Qt::AlignHCenter);
  auto* bottom = new QHBoxLayout;
  lasers_ = new LaserView(component_, central);
  lasers_->setMinimumSize(420, 360);
  bottom->addWidget(lasers_, 1);
  auto* teleop = new gui::Teleoperator(component_.maxV(), component_.maxW(), central);
  side_ = new component::SidePanel(component_, *teleop, central);
  side_->status()->setMinimumWidth(240);
  side_->referee()->setMaximumWidth(360);
  side_->layout()->addStretch(1);
  bottom->addWidget(side_);
  bottom->addWidget(teleop);
  layout->addLayout(bottom, 1);
  setCentralWidget(central);
  connect(teleop, &gui::Teleoperator::velocityChanged, this, [this](double v, double w) { component_.teleoperate(v, w); });
  map_->setOverlay([this](QPainter& p) { drawCar(p); });
  // The trail is sampled on sim time (every control tick), not at the GUI's refresh rate.
  component_.setOnTick([this](int64_t) {
    if (component_.generation() != shown_generation_) {
      shown_generation_ = component_.generation();
      trail_.clear();
    }
    const auto& pose = component_.api().pose3d;
    if (!pose.received() || pose.utime() == last_trail_utime_) return;
    last_trail_utime_ = pose.utime();
    trail_.emplace_back(pose.getX(), pose.getY());
    if (trail_.size() > kTrail) trail_.pop_front();
  });
  connect(&timer_, &QTimer::timeout, this, &AutoparkWindow::refresh);
  timer_.start(50);
  refresh();
}

void AutoparkWindow::drawCar(QPainter& p) const {
  p.setRenderHint(QPainter::Antialiasing);
  // The ideal parking pose.
  p.setPen(QPen(QColor(0, 160, 0), 2));
  p.setBrush(Qt::NoBrush);
  p.drawPolygon(rectangle(*map_, {{scene_.ideal_x_m, scene_.ideal_y_m, scene_.ideal_yaw_rad}, scene_.car_length_m, scene_.car_width_m}));
  // The trail.
  p.setPen(QPen(QColor(220, 30, 30), 2));
  for (size_t i = 1; i < trail_.size(); ++i) {
    p.drawLine(map_->worldToWidget(trail_[i - 1].x(), trail_[i - 1].y()), map_->worldToWidget(trail_[i].x(), trail_[i].y()));
  }
  const auto& pose = component_.api().pose3d;
  if (!pose.received()) return;
  const double x = pose.getX(), y = pose.getY(), yaw = pose.getYaw();
  const double length = component_.api().car_length_m, width = component_.api().car_width_m;
  // Wheels: 0.7 x 0.25 m at the axles (front wheels steer with the commanded turn).
  const double c = std::cos(yaw), s = std::sin(yaw);
  const double v = component_.api().motors.getV(), w = component_.api().motors.getW();
  const double wheelbase = component_.api().wheelbase_m;
  const double steer = std::abs(v) > 0.05 ? std::clamp(std::atan(wheelbase * w / v), -0.6, 0.6) : 0.0;
  p.setPen(Qt::NoPen);
  p.setBrush(Qt::black);
  for (double ax : {-wheelbase / 2, wheelbase / 2}) {
    for (double side : {-1.0, 1.0}) {
      const double wx = ax, wy = side * (width / 2 - 0.05);
      const double wheel_yaw = yaw + (ax > 0 ? steer : 0.0);
      p.drawPolygon(rectangle(*map_, {{x + c * wx - s * wy, y + s * wx + c * wy, wheel_yaw}, 0.7, 0.3}));
    }
  }
  p.setPen(QPen(Qt::black, 1));
  p.setBrush(QColor(250, 215, 40));
  p.drawPolygon(rectangle(*map_, {{x, y, yaw}, length, width}));
  // The nose.
  p.setBrush(Qt::black);
  p.drawEllipse(map_->worldToWidget(x + c * (length / 2 - 0.3), y + s * (length / 2 - 0.3)), 2.5, 2.5);
}

void AutoparkWindow::refresh() {
  side_->show(component_.running(), component_.refereeStatus().latest());
  const auto& pose = component_.api().pose3d;
  side_->status()->setText(QString("sim time %1 s\nx %2 m  y %3 m  yaw %4 deg\nv = %5 m/s   w = %6 rad/s\n%7\n%8")
                       .arg(component_.simTimeUs() / 1e6, 0, 'f', 1)
                       .arg(pose.getX(), 0, 'f', 2)
                       .arg(pose.getY(), 0, 'f', 2)
                       .arg(geometry::headingDeg(pose.getYaw()), 0, 'f', 1)
                       .arg(component_.api().motors.getV(), 0, 'f', 2)
                       .arg(component_.api().motors.getW(), 0, 'f', 2)
                       .arg(component_.api().min_turn_radius_m > 0
                                ? QString("car-like, R = %1 m").arg(component_.api().min_turn_radius_m, 0, 'f', 1)
                                : QString("turns in place"))
                       .arg(QString::fromStdString(component_.api().status)));
  map_->update();
  lasers_->update();
}

void AutoparkWindow::screenshotAfter(const QString& png_path, int64_t sim_us) {
  gui::screenshotAtSimTime(*this, [this] { return component_.simTimeUs(); }, [this] { refresh(); }, png_path, sim_us);
}

LaserView::LaserView(const AutoparkComponent& component, QWidget* parent) : QWidget(parent), component_(component) {}

void LaserView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), QColor(250, 250, 250));
  p.setRenderHint(QPainter::Antialiasing);
  const AutoparkApi& api = component_.api();
  // Car frame, x up the widget; 24 m across the smaller side.
  const double scale = std::min(width(), height()) / 24.0;
  const QPointF centre(width() / 2.0, height() / 2.0);
  auto toWidget = [&](double x_m, double y_m) { return QPointF(centre.x() - y_m * scale, centre.y() - x_m * scale); };
  p.setPen(QPen(Qt::black, 1));
  p.setBrush(QColor(250, 215, 40));
  const double hl = api.car_length_m / 2, hw = api.car_width_m / 2;
  p.drawPolygon(QPolygonF({toWidget(hl, hw), toWidget(hl, -hw), toWidget(-hl, -hw), toWidget(-hl, hw)}));
  const struct {
    const component::Laser* laser;
    LaserMount mount;
    QColor color;
    const char* name;
  } scans[] = {{&api.laser1, api.mount1, QColor(220, 40, 40), "front"},
               {&api.laser2, api.mount2, QColor(40, 90, 220), "rear"},
               {&api.laser3, api.mount3, QColor(20, 150, 60), "right"}};
  int legend_y = 16;
  for (const auto& s : scans) {
    const auto& data = s.laser->getLaserData();
    p.setPen(QPen(s.color, 2));
    for (int i = 0; i < data.numLaser; ++i) {
      const double r = data.values_m[i];
      if (r >= data.maxRange - 0.05) continue;
      const double a = s.mount.yaw_rad + data.angle(i);
      p.drawPoint(toWidget(s.mount.x_m + r * std::cos(a), s.mount.y_m + r * std::sin(a)));
    }
    p.drawText(8, legend_y, QString("%1 laser").arg(s.name));
    legend_y += 16;
  }
}

}  // namespace aula::autopark
