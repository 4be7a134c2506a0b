#include "aula/gui/teleoperator.hpp"

#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPushButton>
#include <QShortcut>
#include <QVBoxLayout>

#include <algorithm>

namespace aula::gui {

TeleoperatorPad::TeleoperatorPad(QWidget* parent) : QWidget(parent) { setMinimumSize(140, 140); }

void TeleoperatorPad::recentre() {
  knob_ = {0, 0};
  update();
  emit moved(0, 0);
}

void TeleoperatorPad::nudge(double forward, double left) {
  knob_ = {std::clamp(knob_.x() - left, -1.0, 1.0), std::clamp(knob_.y() + forward, -1.0, 1.0)};
  update();
  emit moved(knob_.y(), -knob_.x());
}

void TeleoperatorPad::setFromWidget(const QPointF& p) {
  const double half = std::min(width(), height()) / 2.0;
  const QPointF c(width() / 2.0, height() / 2.0);
  knob_ = {std::clamp((p.x() - c.x()) / half, -1.0, 1.0), std::clamp((c.y() - p.y()) / half, -1.0, 1.0)};
  update();
  emit moved(knob_.y(), -knob_.x());
}

void TeleoperatorPad::mousePressEvent(QMouseEvent* e) { setFromWidget(e->pos()); }
void TeleoperatorPad::mouseMoveEvent(QMouseEvent* e) { setFromWidget(e->pos()); }

void TeleoperatorPad::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const double side = std::min(width(), height());
  const QRectF square((width() - side) / 2, (height() - side) / 2, side, side);
  p.fillRect(square, QColor(235, 235, 235));
  p.setPen(QPen(QColor(150, 150, 150), 1));
  p.drawRect(square);
  p.drawLine(QPointF(square.center().x(), square.top()), QPointF(square.center().x(), square.bottom()));
  p.drawLine(QPointF(square.left(), square.center().y()), QPointF(square.right(), square.center().y()));
  const QPointF k(square.center().x() + knob_.x() * side / 2, square.center().y() - knob_.y() * side / 2);
  p.setPen(QPen(QColor(200, 0, 0), 2));
  p.drawLine(square.center(), k);
  p.setBrush(QColor(220, 30, 30));
  p.drawEllipse(k, 8, 8);
}

Teleoperator::Teleoperator(double max_v_mps, double max_w_radps, QWidget* parent)
    : QWidget(parent), max_v_(max_v_mps), max_w_(max_w_radps) {
  auto* layout = new QVBoxLayout(this);
  pad_ = new TeleoperatorPad(this);
  label_ = new QLabel(this);
  auto* stop_button = new QPushButton("Stop", this);
  auto* title = new QLabel("Teleoperator (keys: W/S faster/slower, A/D left/right, X stop)", this);
  title->setWordWrap(true);
  layout->addWidget(title);
  layout->addWidget(pad_, 1);
  layout->addWidget(label_);
  layout->addWidget(stop_button);
  connect(pad_, &TeleoperatorPad::moved, this, &Teleoperator::update);
  connect(stop_button, &QPushButton::clicked, this, &Teleoperator::stop);
  // Window-wide keys; a disabled teleoperator (a replay's view-only window) ignores them.
  const struct {
    Qt::Key key;
    double forward, left;
  } keys[] = {{Qt::Key_W, 0.25, 0}, {Qt::Key_S, -0.25, 0}, {Qt::Key_A, 0, 0.25}, {Qt::Key_D, 0, -0.25}};
  for (const auto& k : keys) {
    auto* shortcut = new QShortcut(QKeySequence(k.key), this);
    shortcut->setContext(Qt::WindowShortcut);
    connect(shortcut, &QShortcut::activated, this, [this, k] {
      if (isEnabled()) pad_->nudge(k.forward, k.left);
    });
  }
  auto* stop_key = new QShortcut(QKeySequence(Qt::Key_X), this);
  stop_key->setContext(Qt::WindowShortcut);
  connect(stop_key, &QShortcut::activated, this, [this] {
    if (isEnabled()) stop();
  });
  update(0, 0);
}

void Teleoperator::stop() { pad_->recentre(); }

void Teleoperator::update(double forward, double left) {
  const double v = forward * max_v_, w = left * max_w_;
  label_->setText(QString("v = %1 m/s   w = %2 rad/s").arg(v, 0, 'f', 2).arg(w, 0, 'f', 2));
  emit velocityChanged(v, w);
}

}  // namespace aula::gui
