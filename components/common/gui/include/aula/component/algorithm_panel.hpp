#pragma once
// The component window's view of the student's algorithm: which build runs (the plugin's file
// time), the fault that halted it (in red, where the student looks, not only on stderr), motor
// commands refused as NaN/inf, and hot reload: the plugin file is watched, a new build on disk
// is announced, and "Reload" (Ctrl+R) or the next Run loads it without restarting the
// simulator or the referee.

#include <aula/component/algorithm_host.hpp>

#include <QFileSystemWatcher>
#include <QLabel>
#include <QPushButton>
#include <QTimer>
#include <QWidget>

#include <functional>

namespace aula::component {

class AlgorithmPanel : public QWidget {
 public:
  // `reload_algorithm`: the component's reloadAlgorithm() (false when the new build could not be used).
  AlgorithmPanel(const AlgorithmHostBase& host, std::function<bool()> reload_algorithm, QWidget* parent = nullptr);

  // Called before a Run: a rebuilt plugin waiting on disk is loaded first.
  void reloadIfRebuilt();
  void refresh();

 private:
  void reload();
  void watchPlugin();

  const AlgorithmHostBase& host_;
  std::function<bool()> reload_;
  QLabel* build_;
  QLabel* rebuilt_;
  QLabel* fault_;
  QLabel* non_finite_;
  QPushButton* reload_button_;
  QFileSystemWatcher watcher_;
  QTimer timer_;
};

}  // namespace aula::component
