#include "replay_window.hpp"

#include <QGuiApplication>
#include <QHBoxLayout>
#include <QPixmap>
#include <QScreen>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace aula::replay {

namespace {
constexpr int kTickMs = 20;
// Events per tick: 20 k/s, where LCM over UDP still delivers everything (engineering.md).
constexpr int kEventsPerTick = 400;
// The viewer windows need this long to load their maps and subscribe.
constexpr int kViewerStartMs = 2500;
constexpr double kAsFastAsPossible = 1e9;
}  // namespace

ReplayWindow::ReplayWindow(LogPlayer& player, std::function<void()> restart_viewers, const QString& title,
                           const QString& recorded, double speed)
    : player_(player), restart_viewers_(std::move(restart_viewers)) {
  setWindowTitle("Aula replay: " + title);
  auto* central = new QWidget(this);
  auto* layout = new QVBoxLayout(central);
  auto* what = new QLabel(recorded, central);
  what->setStyleSheet("font-weight: bold;");
  what->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(what);
  auto* controls = new QHBoxLayout;
  play_ = new QPushButton("Play", central);
  speed_ = new QComboBox(central);
  for (double factor : {0.5, 1.0, 2.0, 5.0, 20.0, 100.0}) speed_->addItem(QString("%1x").arg(factor), factor);
  speed_->addItem("as fast as possible", kAsFastAsPossible);
  const int initial = speed_->findData(speed);
  if (initial >= 0) {
    speed_->setCurrentIndex(initial);
  } else {
    speed_->addItem(QString("%1x").arg(speed), speed);
    speed_->setCurrentIndex(speed_->count() - 1);
  }
  time_ = new QLabel(central);
  time_->setMinimumWidth(220);
  controls->addWidget(play_);
  controls->addWidget(new QLabel("speed", central));
  controls->addWidget(speed_);
  controls->addWidget(time_, 1);
  slider_ = new QSlider(Qt::Horizontal, central);
  slider_->setRange(0, static_cast<int>(player_.durationUs() / 100'000));  // 0.1 s steps
  layout->addLayout(controls);
  layout->addWidget(slider_);
  auto* note = new QLabel(
      "View only: the component and referee windows show the recorded run (the algorithm does not run). "
      "Drag the slider to jump; jumping back restarts both windows and plays fast up to that point. "
      "`aula regrade` grades the log exactly.",
      central);
  note->setWordWrap(true);
  layout->addWidget(note);
  setCentralWidget(central);

  connect(play_, &QPushButton::clicked, this, [this] {
    playing_ = !playing_;
    refresh();
  });
  connect(slider_, &QSlider::sliderReleased, this, [this] { seek(static_cast<int64_t>(slider_->value()) * 100'000); });
  wall_.start();
  hold_until_ms_ = kViewerStartMs;
  playing_ = true;
  connect(&timer_, &QTimer::timeout, this, &ReplayWindow::tick);
  timer_.start(kTickMs);
  refresh();
}

void ReplayWindow::tick() {
  if (wall_.elapsed() < hold_until_ms_) {
    refresh();
    return;
  }
  const double speed = speed_->currentData().toDouble();
  if (playing_ && target_us_ < player_.durationUs()) {
    const double step_us = speed >= kAsFastAsPossible ? static_cast<double>(player_.durationUs()) : speed * kTickMs * 1000.0;
    // Never run ahead of what could be sent: the clock waits for the events.
    if (player_.positionUs() >= target_us_) target_us_ = std::min<int64_t>(player_.durationUs(), target_us_ + std::llround(step_us));
  }
  player_.playUntil(target_us_, kEventsPerTick);
  if (player_.atEnd()) playing_ = false;
  refresh();
}

void ReplayWindow::seek(int64_t target_us) {
  if (target_us < player_.positionUs()) {
    restart_viewers_();
    player_.rewind();
    hold_until_ms_ = wall_.elapsed() + kViewerStartMs;
  }
  target_us_ = target_us;
}

void ReplayWindow::refresh() {
  play_->setText(playing_ ? "Pause" : "Play");
  if (!slider_->isSliderDown()) slider_->setValue(static_cast<int>(player_.positionUs() / 100'000));
  const bool starting = wall_.elapsed() < hold_until_ms_;
  time_->setText(starting ? QString("starting the windows...")
                          : QString("sim time %1 / %2 s%3")
                                .arg(player_.positionUs() / 1e6, 0, 'f', 1)
                                .arg(player_.durationUs() / 1e6, 0, 'f', 1)
                                .arg(player_.positionUs() + 200'000 < target_us_ ? "  (catching up)" : ""));
}

void ReplayWindow::screenshotAt(const QString& png_path, double sim_s) {
  auto* poll = new QTimer(this);
  connect(poll, &QTimer::timeout, this, [this, png_path, sim_s, poll] {
    const int64_t at_us = std::min(player_.durationUs(), static_cast<int64_t>(sim_s * 1e6));
    if (wall_.elapsed() < hold_until_ms_ || (player_.positionUs() < at_us && !player_.atEnd())) return;
    playing_ = false;
    poll->stop();
    // Let the viewers paint what they were sent, then grab the screen with all three windows.
    QTimer::singleShot(1500, this, [png_path] {
      QScreen* screen = QGuiApplication::primaryScreen();
      const bool saved = screen != nullptr && screen->grabWindow(0).save(png_path);
      QCoreApplication::exit(saved ? 0 : 1);
    });
  });
  poll->start(50);
}

}  // namespace aula::replay
