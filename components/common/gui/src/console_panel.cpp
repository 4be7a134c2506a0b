#include "aula/component/console_panel.hpp"

#include <QFontDatabase>
#include <QScrollBar>
#include <QTextCursor>
#include <QVBoxLayout>

namespace aula::component {

ConsolePanel::ConsolePanel(const AlgorithmHostBase& host, QWidget* parent) : QWidget(parent), host_(host) {
  setObjectName("ConsolePanel");
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  title_ = new QLabel(QString("Console: what your program prints (the last %1 lines)").arg(kMaxLines), this);
  view_ = new QPlainTextEdit(this);
  view_->setReadOnly(true);
  view_->setMaximumBlockCount(kMaxLines);
  view_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  view_->setLineWrapMode(QPlainTextEdit::WidgetWidth);  // the panel is narrow: a long line wraps
  // Three lines at least, so that the windows' other panels keep their room; more when there is room.
  const int line_px = view_->fontMetrics().lineSpacing();
  view_->setMinimumHeight(3 * line_px + 8);
  view_->setMaximumHeight(8 * line_px + 8);
  view_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
  layout->addWidget(title_);
  layout->addWidget(view_);
  setVisible(false);  // until a Python program is loaded
  connect(&timer_, &QTimer::timeout, this, &ConsolePanel::refresh);
  timer_.start(100);
}

void ConsolePanel::refresh() {
  setVisible(host_.takesPrints());
  if (host_.printed().total() == seen_) return;
  const std::string printed = host_.printed().since(seen_);
  QScrollBar* bar = view_->verticalScrollBar();
  const bool at_end = bar->value() == bar->maximum();
  QTextCursor end(view_->document());
  end.movePosition(QTextCursor::End);
  end.insertText(QString::fromStdString(printed));
  if (at_end) bar->setValue(bar->maximum());
}

}  // namespace aula::component
