#pragma once
// Saves a widget as a PNG (QWidget::grab; works under QT_QPA_PLATFORM=offscreen and xvfb-run).
#include <QApplication>
#include <QString>
#include <QTimer>
#include <QWidget>

#include <cstdint>
#include <functional>

namespace aula::gui {
inline bool saveWidgetPng(QWidget& widget, const QString& path) { return widget.grab().save(path, "PNG"); }

// Once the simulated clock reaches sim_us: refresh the window, save it as png_path and quit the
// application (for `--screenshot=FILE.png`; sim time, so the picture shows the same moment on
// any machine).
inline void screenshotAtSimTime(QWidget& window, std::function<int64_t()> sim_time_us, std::function<void()> refresh,
                                const QString& png_path, int64_t sim_us) {
  auto* poll = new QTimer(&window);
  QObject::connect(poll, &QTimer::timeout, &window, [&window, sim_time_us, refresh, png_path, poll, sim_us] {
    if (sim_time_us() < sim_us) return;
    poll->stop();
    refresh();
    saveWidgetPng(window, png_path);
    QApplication::quit();
  });
  poll->start(20);
}
}  // namespace aula::gui
