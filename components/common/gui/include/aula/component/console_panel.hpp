#pragma once
// The component window's console: what the student's Python program prints (print(), and its
// stderr), as RoboticsAcademy's page shows it. The component takes the text after each tick and
// keeps it (AlgorithmHostBase::printed(): the last 64 KB); this panel shows the last kMaxLines
// lines and says so. It stays hidden for a C++ algorithm (whose output goes to the terminal).

#include <aula/component/algorithm_host.hpp>

#include <QLabel>
#include <QPlainTextEdit>
#include <QTimer>
#include <QWidget>

#include <cstdint>
#include <string>

namespace aula::component {

class ConsolePanel : public QWidget {
 public:
  static constexpr int kMaxLines = 500;

  explicit ConsolePanel(const AlgorithmHostBase& host, QWidget* parent = nullptr);
  // Shows what was printed since the last look; called on the window's timer.
  void refresh();
  // The text now shown (tests).
  QString text() const { return view_->toPlainText(); }

 private:
  QLabel* title_;
  QPlainTextEdit* view_;
  QTimer timer_;
  const AlgorithmHostBase& host_;
  uint64_t seen_ = 0;  // how much of what was printed is shown
};

}  // namespace aula::component
