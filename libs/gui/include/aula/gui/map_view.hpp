#pragma once
// A generated occupancy map with overlays drawn in WORLD coordinates through the one
// MapTransform: robot glyphs, paths, markers and a painted layer (e.g. the cleaned area).

#include <aula/geometry/map_transform.hpp>

#include <QColor>
#include <QImage>
#include <QPointF>
#include <QWidget>

#include <functional>
#include <optional>
#include <vector>

namespace aula::gui {

class MapView : public QWidget {
  Q_OBJECT
 public:
  MapView(QImage map, geometry::MapTransform transform, QWidget* parent = nullptr);

  // Robot glyph: a triangle of the given footprint pointing along yaw (CCW from +x).
  void setRobot(double x_m, double y_m, double yaw_rad, double length_m, double width_m);
  void setPath(std::vector<QPointF> world_points, QColor color = QColor(0, 170, 0));
  void setMarker(std::optional<QPointF> world_point);  // red X
  void clearPainted();
  void paintDisc(double x_m, double y_m, double radius_m, QColor color);  // into the painted layer
  // Extra drawing in widget coordinates, after the built-in overlays.
  void setOverlay(std::function<void(QPainter&)> overlay) { overlay_ = std::move(overlay); }

  QPointF worldToWidget(double x_m, double y_m) const;
  QPointF widgetToWorld(const QPointF& p) const;
  double pixelsPerMetre() const;
  const geometry::MapTransform& transform() const { return transform_; }
  QSize sizeHint() const override { return map_.size().expandedTo(QSize(400, 400)); }

 signals:
  void worldDoubleClicked(double x_m, double y_m);

 protected:
  void paintEvent(QPaintEvent*) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;

 private:
  QRectF imageRect() const;  // where the map is drawn, keeping its aspect ratio

  QImage map_;
  QImage painted_;
  geometry::MapTransform transform_;
  bool have_robot_ = false;
  double robot_x_ = 0, robot_y_ = 0, robot_yaw_ = 0, robot_length_ = 1, robot_width_ = 1;
  std::vector<QPointF> path_;
  QColor path_color_;
  std::optional<QPointF> marker_;
  std::function<void(QPainter&)> overlay_;
};

}  // namespace aula::gui
