#pragma once
// The player's window: play/pause, a speed factor, a time slider over the run's sim time. The
// events go out on the replay's private bus to the view-only component and referee windows;
// seeking back restarts those two (they have seen the future) and plays fast up to the point.

#include "log_player.hpp"

#include <QComboBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QMainWindow>
#include <QPushButton>
#include <QSlider>
#include <QTimer>

#include <functional>

namespace aula::replay {

class ReplayWindow : public QMainWindow {
 public:
  // Its fixed size, in the launcher's layout with the viewers' windows (aula/desktop).
  static constexpr int kWidthPx = 760;
  static constexpr int kHeightPx = 170;

  // `restart_viewers`: stops and starts the component and referee windows again. `recorded`:
  // what was recorded (exercise, world, seed, algorithm), shown above the controls.
  ReplayWindow(LogPlayer& player, std::function<void()> restart_viewers, const QString& title, const QString& recorded,
               double speed);
  // Grabs the whole screen (all three windows) to `png_path` once the replay reaches `sim_s`,
  // then quits.
  void screenshotAt(const QString& png_path, double sim_s);

 private:
  void tick();
  void seek(int64_t target_us);
  void refresh();

  LogPlayer& player_;
  std::function<void()> restart_viewers_;
  QPushButton* play_;
  QComboBox* speed_;
  QSlider* slider_;
  QLabel* time_;
  QTimer timer_;
  QElapsedTimer wall_;
  bool playing_ = false;
  int64_t target_us_ = 0;
  qint64 hold_until_ms_ = 0;  // the viewer windows are starting: nothing is sent before
};

}  // namespace aula::replay
