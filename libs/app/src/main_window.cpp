#include "aula/app/main_window.hpp"

#include <QCoreApplication>
#include <QEvent>
#include <QPointer>
#include <QTimer>
#include <QWidget>

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

}  // namespace aula::app
