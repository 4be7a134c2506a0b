#pragma once
// What crosses between the TeleTaxi component and its algorithm's own process
// (algorithm_box.hpp), said once for both ends. Every call: the pose, the commands as they stand,
// the sim clock, and the grid's destination and taxi cell in; the commands and whether a path was
// found back. The city's map crosses when that process has none yet; generatePath() (CallKind::Plan)
// takes the grid's field and path in and gives them back: they are what it computes (the window
// shows them when it returns, and grid.showGrid() opens the window then).

#include <aula/component/algorithm_host.hpp>
#include <aula/component/box_wire.hpp>
#include <aula/teletaxi/grid.hpp>
#include <aula/teletaxi/taxi_algorithm.hpp>

#include <memory>

namespace aula::teletaxi {

// `grid` is null at the algorithm's end until the map comes; `with_map`: the map crosses (the
// writing end says, once for each process of the algorithm; the reading end learns it).
void exchangeInputs(component::BoxWire& wire, component::Pose3d& pose, component::Motors& motors,
                    component::SimClock& clock, std::unique_ptr<Grid>& grid, bool& with_map, component::CallKind kind);
// `show_grid`: the algorithm called grid.showGrid() (the writing end says and clears it); the
// reading end calls its grid's showGrid() (the window's), once the field and path are in.
void exchangeOutputs(component::BoxWire& wire, component::Motors& motors, Grid& grid, bool& show_grid,
                     component::CallKind kind);

// The algorithm's end: its own devices and API (runAlgorithmBox<TaxiBox>), its grid made when
// the map comes.
class TaxiBox {
 public:
  using Algorithm = TaxiAlgorithm;
  explicit TaxiBox(component::Motors& motors) : motors_(motors) {}
  void readInputs(component::BoxWire& wire, component::CallKind kind);
  void invoke(TaxiAlgorithm& algorithm, component::CallKind kind);
  void writeOutputs(component::BoxWire& wire, component::CallKind kind);

 private:
  component::Motors& motors_;
  component::Pose3d pose_;
  std::unique_ptr<Grid> grid_;
  std::unique_ptr<TaxiApi> api_;
  component::SimClock clock_;
  bool show_grid_ = false;  // the algorithm asked to show the grid during this call
};

}  // namespace aula::teletaxi
