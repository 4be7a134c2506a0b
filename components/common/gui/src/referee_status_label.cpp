#include "aula/component/referee_status_label.hpp"

namespace aula::component {

RefereeStatusLabel::RefereeStatusLabel(std::string start_action, QWidget* parent)
    : QLabel(parent), start_action_(std::move(start_action)) {
  setWordWrap(true);
  // Three lines and the finished style's padding, from the start: the text that comes later
  // (how the episode ended) must not push the buttons below it.
  setFixedHeight(3 * fontMetrics().lineSpacing() + 2 * 4 + 4);
  setAlignment(Qt::AlignLeft | Qt::AlignTop);
  setToolTip("The referee's clock (sim time): the episode's time left and how it ended");
  setStatus(std::nullopt);
}

void RefereeStatusLabel::setStatus(const std::optional<aula::referee_status_t>& status) {
  const bool finished = status && status->finished;
  if (finished != finished_shown_) {
    setStyleSheet(finished ? "font-weight: bold; color: white; background: #2e7d32; padding: 4px;" : "");
    finished_shown_ = finished;
  }
  setText("Referee: " + QString::fromStdString(refereeStatusLine(status, start_action_)));
}

}  // namespace aula::component
