#pragma once
// The referee's clock in a component's window: "time left 14:32 - coverage 12.30 %" while the
// episode runs, and how it ended ("Time's up: ...", "Arrived: ...") in bold once the referee
// ends it. The text is the referee's (RefereeStatusListener); the window only shows it.

#include <aula/component/referee_status.hpp>

#include <QLabel>

#include <optional>
#include <string>

namespace aula::component {

class RefereeStatusLabel : public QLabel {
 public:
  // `start_action`: what starts the referee's clock in this window ("Run my algorithm", "GO!").
  explicit RefereeStatusLabel(std::string start_action, QWidget* parent = nullptr);
  void setStatus(const std::optional<aula::referee_status_t>& status);

 private:
  std::string start_action_;
  bool finished_shown_ = false;
};

}  // namespace aula::component
