#include "aula/component/algorithm_panel.hpp"

#include "aula/component/console_panel.hpp"

#include <QFileInfo>
#include <QShortcut>
#include <QVBoxLayout>

namespace aula::component {

AlgorithmPanel::AlgorithmPanel(const AlgorithmHostBase& host, std::function<bool()> reload_algorithm, QWidget* parent)
    : QWidget(parent), host_(host), reload_(std::move(reload_algorithm)) {
  setObjectName("AlgorithmPanel");  // a replay's view-only window hides it (app::runComponent)
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  build_ = new QLabel(this);
  build_->setWordWrap(true);
  build_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  rebuilt_ = new QLabel(this);
  rebuilt_->setWordWrap(true);
  rebuilt_->setStyleSheet("color: #1565c0; font-weight: bold;");
  fault_ = new QLabel(this);
  fault_->setWordWrap(true);
  fault_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  fault_->setStyleSheet("color: white; background: #c62828; padding: 4px; font-weight: bold;");
  non_finite_ = new QLabel(this);
  non_finite_->setWordWrap(true);
  non_finite_->setStyleSheet("color: #e65100;");
  reload_button_ = new QPushButton(host_.isPlugin() ? "Reload algorithm (Ctrl+R)" : "Restart episode (Ctrl+R)", this);
  reload_button_->setToolTip(
      "Loads the algorithm again (a new build of the plugin, or your MyAlgorithm.py read again), puts the robot back "
      "at its start and starts a new "
      "episode; the simulator and the referee keep running");
  for (QWidget* w : {static_cast<QWidget*>(build_), static_cast<QWidget*>(rebuilt_), static_cast<QWidget*>(fault_),
                     static_cast<QWidget*>(non_finite_), static_cast<QWidget*>(reload_button_)}) {
    layout->addWidget(w);
  }
  layout->addWidget(new ConsolePanel(host_, this));  // a Python program's print(), shown once one is loaded
  connect(reload_button_, &QPushButton::clicked, this, [this] { reload(); });
  // Window-wide, so it works wherever the focus is.
  auto* shortcut = new QShortcut(QKeySequence("Ctrl+R"), this);
  shortcut->setContext(Qt::WindowShortcut);
  connect(shortcut, &QShortcut::activated, this, [this] { reload(); });
  // A linker replaces the file (the watch is lost with the old inode): watch the folder too and
  // watch the file again whenever either changes.
  connect(&watcher_, &QFileSystemWatcher::fileChanged, this, [this] {
    watchPlugin();
    refresh();
  });
  connect(&watcher_, &QFileSystemWatcher::directoryChanged, this, [this] {
    watchPlugin();
    refresh();
  });
  watchPlugin();
  connect(&timer_, &QTimer::timeout, this, &AlgorithmPanel::refresh);
  timer_.start(250);
  refresh();
}

void AlgorithmPanel::watchPlugin() {
  if (!host_.isPlugin()) return;  // a built-in is Aula's own build: nothing of the student's to watch
  const std::string path = host_.pluginPath();
  const QString file = QString::fromStdString(path);
  const QString folder = QFileInfo(file).absolutePath();
  if (!watcher_.directories().contains(folder)) watcher_.addPath(folder);
  if (!watcher_.files().contains(file) && QFileInfo::exists(file)) watcher_.addPath(file);
}

void AlgorithmPanel::reloadIfRebuilt() {
  if (host_.pluginChanged()) reload();
}

void AlgorithmPanel::reload() {
  if (host_.hung()) return;
  reload_();
  refresh();
}

void AlgorithmPanel::refresh() {
  build_->setText("Algorithm: " + QString::fromStdString(host_.label()));
  const bool rebuilt = host_.pluginChanged();
  const bool python = PluginLibrary::isPythonFile(host_.pluginPath());
  rebuilt_->setText(!rebuilt ? ""
                    : python ? "A new version is on disk: press Reload (Ctrl+R) to use it"
                             : "A new build is on disk: press Reload (Ctrl+R) to use it");
  rebuilt_->setVisible(rebuilt);
  QString fault = host_.fault().empty() ? "" : "Your algorithm was stopped: " + QString::fromStdString(host_.fault());
  if (host_.hung()) {
    // The call is still running on its thread: nothing can reload under it.
    fault += python ? ". The robot is stopped. Fix it, save, and start the run again."
                    : ". The robot is stopped. Fix it, rebuild, and start the run again.";
    reload_button_->setEnabled(false);
  }
  fault_->setText(fault);
  fault_->setVisible(!host_.fault().empty());
  const std::string refused = host_.nonFiniteSummary();
  non_finite_->setText(QString::fromStdString(refused));
  non_finite_->setVisible(!refused.empty());
}

}  // namespace aula::component
