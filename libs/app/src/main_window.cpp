#include "aula/app/main_window.hpp"

#include <aula/settings/tables.hpp>

#include <QCoreApplication>
#include <QEvent>
#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <iostream>

namespace aula::app {
namespace {

class QuitWhenClosed : public QObject {
 public:
  using QObject::QObject;

  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() == QEvent::Close) {
      // Looked at once the window has handled the close: hidden means it accepted it.
      QPointer<QWidget> window = static_cast<QWidget*>(watched);
      QTimer::singleShot(0, this, [window] {
        if (window != nullptr && !window->isVisible()) QCoreApplication::quit();
      });
    }
    return false;
  }
};

}  // namespace

void quitWhenClosed(QWidget& window) { window.installEventFilter(new QuitWhenClosed(&window)); }

void placeWindow(QWidget& window, const desktop::Placement& placement, const std::string& program) {
  const QSize content = window.minimumSizeHint();
  const desktop::Size& size = placement.size;
  if (content.width() > size.width_px || content.height() > size.height_px) {
    std::cerr << program << ": the window \"" << window.windowTitle().toStdString() << "\" is set to " << size.width_px
              << " x " << size.height_px << " px, its content needs " << content.width() << " x " << content.height()
              << ": parts are cut off\n";
  }
  window.setFixedSize(size.width_px, size.height_px);
  if (placement.frame_corner) window.move(placement.frame_corner->x_px, placement.frame_corner->y_px);
}

void placeMainWindow(QWidget& window, const std::string& program, const config::Config& settings) {
  const auto windows = desktop::windowsOf(settings::tableOf(program));
  if (!windows.empty()) placeWindow(window, desktop::placementOf(settings, windows.front()), program);
}

}  // namespace aula::app
