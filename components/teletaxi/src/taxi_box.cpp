#include "aula/teletaxi/taxi_box.hpp"

#include <cstring>
#include <stdexcept>

namespace aula::teletaxi {

namespace {

constexpr int kMaxSidePx = 1 << 14;

// A grid's layer (its field or its path: CV_32FC1 of the map's size), in place.
void ioLayer(component::BoxWire& wire, const cv::Mat& layer, const char* what) {
  wire.ioBytes(layer.data, layer.total() * layer.elemSize(), what);  // continuous: made by Grid
}

void ioCell(component::BoxWire& wire, std::pair<int, int>& cell, const char* what) {
  wire.io(cell.first, what);
  wire.io(cell.second, what);
}

}  // namespace

void exchangeInputs(component::BoxWire& wire, component::Pose3d& pose, component::Motors& motors,
                    component::SimClock& clock, std::unique_ptr<Grid>& grid, bool& with_map, component::CallKind kind) {
  component::ioPose(wire, pose);
  component::ioMotorCommands(wire, motors);
  component::ioClock(wire, clock);
  wire.io(with_map, "grid");
  if (with_map) {
    geometry::MapTransform t = wire.isReading() ? geometry::MapTransform{} : grid->transform();
    wire.io(t.resolution_m, "grid");
    wire.io(t.origin_x_m, "grid");
    wire.io(t.origin_y_m, "grid");
    wire.io(t.width_px, "grid");
    wire.io(t.height_px, "grid");
    if (t.width_px <= 0 || t.height_px <= 0 || t.width_px > kMaxSidePx || t.height_px > kMaxSidePx) {
      throw component::BoxWireError("grid: a map of " + std::to_string(t.width_px) + " x " + std::to_string(t.height_px));
    }
    cv::Mat map = wire.isReading() ? cv::Mat(t.height_px, t.width_px, CV_8UC1) : grid->getMap();
    wire.ioBytes(map.data, map.total(), "grid map");
    if (wire.isReading()) {
      if (grid) throw component::BoxWireError("grid: a second map");  // the API's grid stays the one grid
      grid = std::make_unique<Grid>(map, t);
    }
  }
  if (!grid) throw component::BoxWireError("grid: a call before the map");
  std::pair<int, int> destiny = grid->getDestiny(), cell = grid->getPose();
  ioCell(wire, destiny, "grid destination");
  ioCell(wire, cell, "grid pose");
  if (wire.isReading()) {
    grid->setDestiny(destiny.first, destiny.second);
    grid->setPose(cell.first, cell.second);
  }
  if (kind != component::CallKind::Plan) return;
  bool found = grid->isPathFinded();
  wire.io(found, "grid");
  if (wire.isReading() && !found) grid->resetPath();
  ioLayer(wire, grid->field(), "grid field");
  ioLayer(wire, grid->path(), "grid path");
  if (wire.isReading() && found) grid->setPathFinded();
}

void exchangeOutputs(component::BoxWire& wire, component::Motors& motors, Grid& grid, bool& show_grid,
                     component::CallKind kind) {
  component::ioMotorCommands(wire, motors);
  bool found = grid.isPathFinded();
  wire.io(found, "grid");
  if (kind == component::CallKind::Plan) {
    if (wire.isReading() && !found) grid.resetPath();
    ioLayer(wire, grid.field(), "grid field");
    ioLayer(wire, grid.path(), "grid path");
  }
  if (wire.isReading() && found) grid.setPathFinded();
  wire.io(show_grid, "grid");
  if (!wire.isReading()) {
    show_grid = false;
  } else if (show_grid) {
    grid.showGrid();
  }
}

void TaxiBox::readInputs(component::BoxWire& wire, component::CallKind kind) {
  bool with_map = false;
  exchangeInputs(wire, pose_, motors_, clock_, grid_, with_map, kind);
  if (!api_) {
    api_ = std::make_unique<TaxiApi>(pose_, motors_, *grid_);
    grid_->setShowGridHandler([this] { show_grid_ = true; });
  }
  api_->clock = clock_;
}

void TaxiBox::invoke(TaxiAlgorithm& algorithm, component::CallKind kind) {
  if (kind == component::CallKind::Plan) {
    algorithm.generatePath(*api_);
  } else {
    algorithm.execute(*api_);
  }
}

void TaxiBox::writeOutputs(component::BoxWire& wire, component::CallKind kind) {
  exchangeOutputs(wire, motors_, *grid_, show_grid_, kind);
}

}  // namespace aula::teletaxi
