#pragma once
// A round dial: a needle over coloured bands (speedometer, heading dial, orientation gauge).

#include <QColor>
#include <QString>
#include <QWidget>

#include <vector>

namespace aula::gui {

class Gauge : public QWidget {
  Q_OBJECT
 public:
  struct Band {
    double from, to;
    QColor color;
  };
  // The dial spans [min, max] over `sweep_deg` degrees (270 for a speedometer, 360 for a compass).
  Gauge(QString title, QString unit, double min, double max, double sweep_deg = 270, QWidget* parent = nullptr);
  void setBands(std::vector<Band> bands) { bands_ = std::move(bands); update(); }
  void setValue(double value) { value_ = value; update(); }
  // A heading dial: the needle points where the robot points on the map (the value is degrees
  // counter-clockwise from +x, geometry::headingDeg), whatever min, max and sweep say.
  void setWorldHeading(bool on) { world_heading_ = on; update(); }
  double value() const { return value_; }
  QSize sizeHint() const override { return {170, 170}; }

 protected:
  void paintEvent(QPaintEvent*) override;

 private:
  double angleOf(double value) const;  // degrees, Qt convention (CCW from 3 o'clock)
  QString title_, unit_;
  double min_, max_, sweep_deg_;
  double value_ = 0;
  bool world_heading_ = false;
  std::vector<Band> bands_;
};

}  // namespace aula::gui
