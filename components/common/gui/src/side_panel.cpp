#include "aula/component/side_panel.hpp"

#include <aula/component/sim_control_panel.hpp>

namespace aula::component {

SidePanel::SidePanel(const AlgorithmHostBase& host, lcmbus::Bus& bus, std::function<bool()> reload,
                     std::function<void(bool)> set_running, QWidget* parent)
    : QWidget(parent) {
  layout_ = new QVBoxLayout(this);
  layout_->setContentsMargins(0, 0, 0, 0);  // laid out as a column of the window's own layout
  run_ = new gui::RunToggle(this);
  algorithm_ = new AlgorithmPanel(host, std::move(reload), this);
  referee_ = new RefereeStatusLabel("Run my algorithm", this);
  status_ = new QLabel(this);
  status_->setWordWrap(true);  // the algorithm's status can be a sentence
  layout_->addWidget(run_);
  layout_->addWidget(new SimControlPanel(bus, this));
  layout_->addWidget(algorithm_);
  layout_->addWidget(referee_);
  layout_->addWidget(status_);
  connect(run_, &gui::RunToggle::runningChanged, this, [this, set_running = std::move(set_running)](bool on) {
    if (on) algorithm_->reloadIfRebuilt();
    set_running(on);
  });
}

void SidePanel::show(bool running, const std::optional<aula::referee_status_t>& referee) {
  run_->setRunning(running);
  referee_->setStatus(referee);
}

}  // namespace aula::component
