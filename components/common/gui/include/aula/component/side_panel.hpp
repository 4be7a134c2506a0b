#pragma once
// The side of a component window whose algorithm runs on a toggle (vacuum, Autopark): "Run my
// algorithm", the simulation's speed, the algorithm's build and faults with Reload, the referee's
// clock and the algorithm's status line, in that order. Run loads a rebuilt plugin first; Reload
// lets go of the teleoperator, since a reload puts the robot back at its start. A window adds its
// own widgets below (layout()) and shows its own text in status().

#include <aula/component/algorithm_panel.hpp>
#include <aula/component/referee_status_label.hpp>
#include <aula/gui/run_toggle.hpp>
#include <aula/gui/teleoperator.hpp>
#include <aula/lcm/bus.hpp>

#include <QLabel>
#include <QVBoxLayout>
#include <QWidget>

#include <functional>
#include <optional>

namespace aula::component {

class SidePanel : public QWidget {
 public:
  // `component`: an ExerciseComponent (algorithm(), bus(), reloadAlgorithm(), pressRun()).
  template <class Component>
  SidePanel(Component& component, gui::Teleoperator& teleop, QWidget* parent = nullptr)
      : SidePanel(component.algorithm(), component.bus(),
                  [&component, &teleop] {
                    teleop.stop();
                    return component.reloadAlgorithm();
                  },
                  [&component](bool on) { component.pressRun(on); }, parent) {}

  // At each refresh of the window: whether the algorithm runs, and the referee's latest word.
  void show(bool running, const std::optional<aula::referee_status_t>& referee);

  AlgorithmPanel* algorithm() const { return algorithm_; }
  RefereeStatusLabel* referee() const { return referee_; }
  QLabel* status() const { return status_; }
  QVBoxLayout* layout() const { return layout_; }

 private:
  SidePanel(const AlgorithmHostBase& host, lcmbus::Bus& bus, std::function<bool()> reload,
            std::function<void(bool)> set_running, QWidget* parent);

  QVBoxLayout* layout_;
  gui::RunToggle* run_;
  AlgorithmPanel* algorithm_;
  RefereeStatusLabel* referee_;
  QLabel* status_;
};

}  // namespace aula::component
