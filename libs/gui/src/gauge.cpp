#include "aula/gui/gauge.hpp"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace aula::gui {

Gauge::Gauge(QString title, QString unit, double min, double max, double sweep_deg, QWidget* parent)
    : QWidget(parent), title_(std::move(title)), unit_(std::move(unit)), min_(min), max_(max), sweep_deg_(sweep_deg) {
  setMinimumSize(140, 140);
}

double Gauge::angleOf(double value) const {
  if (world_heading_) return value;  // the map's +x is the dial's 3 o'clock, +y its 12
  const double f = (std::clamp(value, min_, max_) - min_) / (max_ - min_);
  // A full circle starts at the top (north, 0) and turns clockwise like a compass;
  // a partial dial is centred on the top.
  const double start = sweep_deg_ >= 360 ? 90.0 : 90.0 + sweep_deg_ / 2;
  return start - f * sweep_deg_;
}

void Gauge::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const double side = std::min(width(), height()) - 10;
  const QRectF dial((width() - side) / 2, (height() - side) / 2, side, side);
  p.setPen(QPen(QColor(80, 80, 80), 2));
  p.setBrush(QColor(250, 250, 250));
  p.drawEllipse(dial);
  for (const Band& b : bands_) {
    const double a0 = angleOf(b.from), a1 = angleOf(b.to);
    p.setPen(QPen(b.color, side * 0.07, Qt::SolidLine, Qt::FlatCap));
    const QRectF arc = dial.adjusted(side * 0.06, side * 0.06, -side * 0.06, -side * 0.06);
    p.drawArc(arc, static_cast<int>(a0 * 16), static_cast<int>((a1 - a0) * 16));
  }
  const double a = angleOf(value_) * M_PI / 180.0;
  const QPointF c = dial.center();
  p.setPen(QPen(QColor(200, 0, 0), 3));
  p.drawLine(c, c + QPointF(std::cos(a), -std::sin(a)) * side * 0.4);
  p.setPen(Qt::black);
  p.drawText(QRectF(dial.left(), c.y() + side * 0.12, side, 20), Qt::AlignCenter,
             QString("%1 %2").arg(value_, 0, 'f', 1).arg(unit_));
  p.drawText(QRectF(dial.left(), c.y() - side * 0.3, side, 20), Qt::AlignCenter, title_);
}

}  // namespace aula::gui
