#pragma once
// The component window's console: what the student's Python program prints (print(), and its
// stderr), as RoboticsAcademy's page shows it. The Python host keeps the text (python_host.hpp,
// takeConsole(): at most 64 KB between two looks); this panel shows the last kMaxLines lines and
// says so. It stays hidden for a C++ algorithm (whose output goes to the terminal).

#include <QLabel>
#include <QPlainTextEdit>
#include <QTimer>
#include <QWidget>

#include <string>

namespace aula::component {

class ConsolePanel : public QWidget {
 public:
  static constexpr int kMaxLines = 500;

  explicit ConsolePanel(QWidget* parent = nullptr);
  // Shows what was printed since the last look; called on the window's timer.
  void refresh();
  // The text now shown (tests).
  QString text() const { return view_->toPlainText(); }

 private:
  // The loaded Python host's aula_python_take_console, or nullptr while none is loaded.
  using Take = const char* (*)();
  Take findTake();

  QLabel* title_;
  QPlainTextEdit* view_;
  QTimer timer_;
  Take take_ = nullptr;
};

}  // namespace aula::component
