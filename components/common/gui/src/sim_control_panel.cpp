#include "aula/component/sim_control_panel.hpp"

#include <aula/lcm/bus.hpp>
#include <aula/sim_control_t.hpp>

#include <QHBoxLayout>
#include <QShortcut>
#include <QVBoxLayout>

#include <algorithm>
#include <cstdio>
#include <utility>

namespace aula::component {

namespace {

std::string times(double factor) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3gx", factor);
  return text;
}

}  // namespace

std::string paceText(const aula::sim_clock_t& tick) {
  // Paused (the button says so), not measured yet, as fast as possible: nothing to say.
  if (tick.paused || !(tick.real_time_factor > 0) || !(tick.target_real_time_factor > 0)) return "";
  // Within a tenth of the pace asked is keeping it (the measure is over the last second).
  if (tick.real_time_factor >= 0.9 * tick.target_real_time_factor) return "";
  return times(tick.real_time_factor) + ", not the " + times(tick.target_real_time_factor) +
         " asked: the machine cannot keep up" + (tick.lockstep ? " (the run is the same, slower)" : "");
}

SimControlPanel::SimControlPanel(lcmbus::Bus& bus, QWidget* parent) : QWidget(parent), bus_(bus) {
  auto* column = new QVBoxLayout(this);
  column->setContentsMargins(0, 0, 0, 0);
  auto* layout = new QHBoxLayout;
  column->addLayout(layout);
  speed_ = new QComboBox(this);
  speed_->addItem("as started", -1.0);  // the run's --rtf until the student picks one
  speed_->addItem("1x real time", 1.0);
  speed_->addItem("5x", 5.0);
  speed_->addItem("20x", 20.0);
  speed_->addItem("as fast as possible", 0.0);
  speed_->setToolTip("How fast the simulator runs (sim seconds per wall second); the marks do not depend on it");
  pause_ = new QPushButton("Pause", this);
  step_ = new QPushButton("Step", this);
  step_->setEnabled(false);
  step_->setToolTip("While paused: one clock tick of the simulation");
  layout->addWidget(new QLabel("speed", this));
  layout->addWidget(speed_, 1);
  layout->addWidget(pause_);
  layout->addWidget(step_);
  connect(speed_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          [this](int) {
            if (speed_->currentData().toDouble() >= 0) send(aula::sim_control_t::SET_RTF, speed_->currentData().toDouble());
          });
  connect(pause_, &QPushButton::clicked, this, [this] {
    paused_ = !paused_;
    send(paused_ ? aula::sim_control_t::PAUSE : aula::sim_control_t::RESUME);
    pause_->setText(paused_ ? "Resume" : "Pause");
    step_->setEnabled(paused_);
  });
  connect(step_, &QPushButton::clicked, this, [this] { send(aula::sim_control_t::STEP); });
  // Faster / slower from the keyboard: the next speed in the list ("as started" is only the
  // first choice, never stepped back to).
  for (const auto& [key, step] : {std::pair{QKeySequence("Ctrl+]"), 1}, std::pair{QKeySequence("Ctrl+["), -1}}) {
    auto* shortcut = new QShortcut(key, this);
    shortcut->setContext(Qt::WindowShortcut);
    connect(shortcut, &QShortcut::activated, this, [this, step = step] {
      if (!speed_->isEnabled()) return;
      speed_->setCurrentIndex(std::clamp(speed_->currentIndex() + step, 1, speed_->count() - 1));
    });
  }
  speed_->setToolTip(speed_->toolTip() + " (Ctrl+] faster, Ctrl+[ slower)");
  // Shown only while the machine cannot keep the pace: the window's layout is the same otherwise.
  pace_ = new QLabel(this);
  pace_->setWordWrap(true);
  pace_->setStyleSheet("color: #b35c00;");
  pace_->setToolTip("In lockstep the world waits for the algorithm and the referee at every control period: a "
                    "slower run is the same run, and its report the headless run's of its seed");
  pace_->hide();
  column->addWidget(pace_);
  clock_ = bus_.subscribe(lcmbus::kClockChannel, &SimControlPanel::onClock, this);
}

SimControlPanel::~SimControlPanel() { bus_.unsubscribe(clock_); }

void SimControlPanel::onClock(const lcm::ReceiveBuffer*, const std::string&, const aula::sim_clock_t* tick) {
  std::string text = paceText(*tick);
  // The pump runs in the window's thread, a tick at a time; the label changes only when its words do.
  if (text == pace_text_) return;
  pace_text_ = std::move(text);
  pace_->setText(QString::fromStdString(pace_text_));
  pace_->setVisible(!pace_text_.empty());
}

void SimControlPanel::send(int8_t command, double real_time_factor) {
  aula::sim_control_t msg{};
  msg.command = command;
  msg.real_time_factor = real_time_factor;
  bus_.publish(lcmbus::kControlChannel, &msg);
}

}  // namespace aula::component
