#pragma once
// Saves a widget as a PNG (QWidget::grab; works under QT_QPA_PLATFORM=offscreen and xvfb-run).
#include <QApplication>
#include <QString>
#include <QTimer>
#include <QWidget>

#include <chrono>
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

// Once `finished()` says the episode has ended: `last()` (the window's final mark), save the window
// as png_path and quit the application (a referee window's `--screenshot=FILE.png`: the picture
// shows the end of the run). A run that never ends is ended by its referee's own limits or its
// peers' going; the wall-clock backstop only keeps a picture-taking process from waiting forever.
inline void screenshotWhenFinished(QWidget& window, std::function<bool()> finished, std::function<void()> last,
                                   const QString& png_path, std::chrono::milliseconds backstop = std::chrono::minutes(10)) {
  auto* poll = new QTimer(&window);
  const auto deadline = std::chrono::steady_clock::now() + backstop;
  QObject::connect(poll, &QTimer::timeout, &window, [&window, finished, last, png_path, poll, deadline] {
    if (!finished() && std::chrono::steady_clock::now() < deadline) return;
    poll->stop();
    last();
    saveWidgetPng(window, png_path);
    QApplication::quit();
  });
  poll->start(50);
}
}  // namespace aula::gui
