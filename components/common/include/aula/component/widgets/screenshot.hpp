#pragma once
// Saves a widget as a PNG (QWidget::grab; works under QT_QPA_PLATFORM=offscreen and xvfb-run).
#include <QString>
#include <QWidget>

namespace aula::component {
inline bool saveWidgetPng(QWidget& widget, const QString& path) { return widget.grab().save(path, "PNG"); }
}  // namespace aula::component
