#include "aula/component/console_panel.hpp"

#include <aula/config/paths.hpp>

#include <QFontDatabase>
#include <QScrollBar>
#include <QTextCursor>
#include <QVBoxLayout>

#include <dlfcn.h>

#include <filesystem>

namespace aula::component {

ConsolePanel::ConsolePanel(QWidget* parent) : QWidget(parent) {
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

// The Python host is loaded by the component (PluginLibrary), RTLD_LOCAL, once for the process:
// asked by name among the hosts, without loading any (RTLD_NOLOAD).
ConsolePanel::Take ConsolePanel::findTake() {
  namespace fs = std::filesystem;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(fs::path(config::libDir()) / "python", ec)) {
    void* handle = dlopen(entry.path().c_str(), RTLD_NOW | RTLD_NOLOAD);
    if (handle == nullptr) continue;
    auto take = reinterpret_cast<Take>(dlsym(handle, "aula_python_take_console"));
    dlclose(handle);  // the component's own handle keeps it loaded for good
    if (take != nullptr) return take;
  }
  return nullptr;
}

void ConsolePanel::refresh() {
  if (take_ == nullptr) take_ = findTake();
  if (take_ == nullptr) return;
  setVisible(true);
  const char* printed = take_();
  if (printed == nullptr || *printed == '\0') return;
  QScrollBar* bar = view_->verticalScrollBar();
  const bool at_end = bar->value() == bar->maximum();
  QTextCursor end(view_->document());
  end.movePosition(QTextCursor::End);
  end.insertText(QString::fromUtf8(printed));
  if (at_end) bar->setValue(bar->maximum());
}

}  // namespace aula::component
