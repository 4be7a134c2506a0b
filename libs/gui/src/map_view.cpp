#include "aula/gui/map_view.hpp"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace aula::gui {

MapView::MapView(QImage map, geometry::MapTransform transform, QWidget* parent)
    : QWidget(parent), map_(std::move(map)), transform_(transform) {
  painted_ = QImage(map_.size(), QImage::Format_ARGB32);
  painted_.fill(Qt::transparent);
  setMinimumSize(200, 200);
}

QRectF MapView::imageRect() const {
  const double scale = std::min(width() / static_cast<double>(map_.width()), height() / static_cast<double>(map_.height()));
  const double w = map_.width() * scale, h = map_.height() * scale;
  return QRectF((width() - w) / 2, (height() - h) / 2, w, h);
}

double MapView::pixelsPerMetre() const {
  return imageRect().width() / map_.width() / transform_.resolution_m;
}

QPointF MapView::worldToWidget(double x_m, double y_m) const {
  const QRectF r = imageRect();
  const double scale = r.width() / map_.width();
  return {r.left() + transform_.worldToColF(x_m) * scale, r.top() + transform_.worldToRowF(y_m) * scale};
}

QPointF MapView::widgetToWorld(const QPointF& p) const {
  const QRectF r = imageRect();
  const double scale = r.width() / map_.width();
  const double col = (p.x() - r.left()) / scale, row = (p.y() - r.top()) / scale;
  return {transform_.origin_x_m + col * transform_.resolution_m, transform_.origin_y_m - row * transform_.resolution_m};
}

void MapView::setRobot(double x_m, double y_m, double yaw_rad, double length_m, double width_m) {
  have_robot_ = true;
  robot_x_ = x_m;
  robot_y_ = y_m;
  robot_yaw_ = yaw_rad;
  robot_length_ = length_m;
  robot_width_ = width_m;
  update();
}

void MapView::setPath(std::vector<QPointF> world_points, QColor color) {
  path_ = std::move(world_points);
  path_color_ = color;
  update();
}

void MapView::setMarker(std::optional<QPointF> world_point) {
  marker_ = world_point;
  update();
}

void MapView::clearPainted() {
  painted_.fill(Qt::transparent);
  update();
}

void MapView::paintDisc(double x_m, double y_m, double radius_m, QColor color) {
  // Exact pixels: every map pixel whose centre lies within the disc.
  const double r_px = radius_m / transform_.resolution_m;
  const double cx = transform_.worldToColF(x_m), cy = transform_.worldToRowF(y_m);
  const QRgb rgb = color.rgba();
  for (int row = static_cast<int>(std::floor(cy - r_px)); row <= static_cast<int>(std::ceil(cy + r_px)); ++row) {
    if (row < 0 || row >= painted_.height()) continue;
    auto* line = reinterpret_cast<QRgb*>(painted_.scanLine(row));
    for (int col = static_cast<int>(std::floor(cx - r_px)); col <= static_cast<int>(std::ceil(cx + r_px)); ++col) {
      if (col < 0 || col >= painted_.width()) continue;
      const double dx = col + 0.5 - cx, dy = row + 0.5 - cy;
      if (dx * dx + dy * dy <= r_px * r_px) line[col] = rgb;
    }
  }
  update();
}

void MapView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), QColor(60, 60, 60));
  const QRectF r = imageRect();
  p.drawImage(r, map_);
  p.drawImage(r, painted_);
  p.setRenderHint(QPainter::Antialiasing, true);
  if (path_.size() >= 2) {
    QPainterPath line;
    line.moveTo(worldToWidget(path_[0].x(), path_[0].y()));
    for (size_t i = 1; i < path_.size(); ++i) line.lineTo(worldToWidget(path_[i].x(), path_[i].y()));
    p.setPen(QPen(path_color_, 2.0));
    p.drawPath(line);
  }
  if (marker_) {
    const QPointF c = worldToWidget(marker_->x(), marker_->y());
    p.setPen(QPen(Qt::red, 3.0));
    p.drawLine(c + QPointF(-7, -7), c + QPointF(7, 7));
    p.drawLine(c + QPointF(-7, 7), c + QPointF(7, -7));
  }
  if (have_robot_) {
    // Triangle: nose at the front, base at the back; at least 14 px long to stay visible.
    const double ppm = pixelsPerMetre();
    const double length_px = std::max(14.0, robot_length_ * ppm), width_px = std::max(10.0, robot_width_ * ppm);
    const QPointF c = worldToWidget(robot_x_, robot_y_);
    const double ux = std::cos(robot_yaw_), uy = -std::sin(robot_yaw_);  // screen y grows down
    const QPointF fwd(ux, uy), left(uy, -ux);
    QPolygonF tri;
    tri << c + fwd * (length_px / 2) << c - fwd * (length_px / 2) + left * (width_px / 2)
        << c - fwd * (length_px / 2) - left * (width_px / 2);
    p.setPen(QPen(Qt::black, 1.0));
    p.setBrush(QColor(30, 90, 230));
    p.drawPolygon(tri);
  }
  if (overlay_) overlay_(p);
}

void MapView::mouseDoubleClickEvent(QMouseEvent* event) {
  if (!imageRect().contains(event->pos())) return;
  const QPointF w = widgetToWorld(event->pos());
  emit worldDoubleClicked(w.x(), w.y());
}

}  // namespace aula::gui
