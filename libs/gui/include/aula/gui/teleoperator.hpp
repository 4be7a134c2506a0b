#pragma once
// JdeRobot's 2D teleoperator: drag the knob; up/down is v (forward positive), left/right is w
// (left positive, CCW), scaled by maxV / maxW. Stop recentres it. The keyboard drives it too,
// anywhere in its window: W/S a quarter faster/slower, A/D a quarter more to the left/right, X stops.

#include <QWidget>

class QLabel;

namespace aula::gui {

class TeleoperatorPad : public QWidget {
  Q_OBJECT
 public:
  explicit TeleoperatorPad(QWidget* parent = nullptr);
  QSize sizeHint() const override { return {180, 180}; }
  void recentre();
  // Moves the knob by a fraction of each axis (forward, left), clamped to the pad.
  void nudge(double forward, double left);
  QPointF knob() const { return knob_; }  // each axis in [-1, 1], y up positive

 signals:
  void moved(double forward, double left);  // each in [-1, 1]

 protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent* e) override;
  void mouseMoveEvent(QMouseEvent* e) override;

 private:
  void setFromWidget(const QPointF& p);
  QPointF knob_{0, 0};
};

class Teleoperator : public QWidget {
  Q_OBJECT
 public:
  Teleoperator(double max_v_mps, double max_w_radps, QWidget* parent = nullptr);
  void stop();

 signals:
  void velocityChanged(double v_mps, double w_radps);

 private:
  void update(double forward, double left);
  double max_v_, max_w_;
  TeleoperatorPad* pad_;
  QLabel* label_;
};

}  // namespace aula::gui
