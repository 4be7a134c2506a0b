#include "aula/component/sim_control_panel.hpp"

#include <aula/lcm/bus.hpp>
#include <aula/sim_control_t.hpp>

#include <QHBoxLayout>
#include <QShortcut>

#include <algorithm>
#include <utility>
#include <QLabel>

namespace aula::component {

SimControlPanel::SimControlPanel(lcmbus::Bus& bus, QWidget* parent) : QWidget(parent), bus_(bus) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
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
}

void SimControlPanel::send(int8_t command, double real_time_factor) {
  aula::sim_control_t msg{};
  msg.command = command;
  msg.real_time_factor = real_time_factor;
  bus_.publish(lcmbus::kControlChannel, &msg);
}

}  // namespace aula::component
