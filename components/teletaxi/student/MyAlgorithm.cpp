// ============================================================================================
//  TeleTaxi: YOUR Gradient Path Planning goes here.
//
//  generatePath(api) runs once when you press "Generate Path" (headless: at start-up once the
//  destination and the taxi's position are known). Fill api.grid with your field:
//      api.grid.getDestiny()  -> (x, y) cell of the destination      (x = column, y = row)
//      api.grid.getPose()     -> (x, y) cell of the taxi
//      api.grid.getMap()      -> the city map, cv::Mat 8-bit: 0 obstacle, 255 free
//      api.grid.setVal(x, y, v) / getVal(x, y)       your field (floats, all 0 at first)
//      api.grid.setPathVal(x, y, v) / getPathVal(x, y)  mark the path cells (non-zero)
//      api.grid.setPathFinded()   the GUI then draws your path in green
//      api.grid.showGrid()        opens the "Grid Field" window
//      api.grid.gridToWorld(x, y) / worldToGrid(x_m, y_m)
//
//  execute(api) runs every control period (80 ms of simulated time) after "GO!":
//      api.sensor.getRobotX(), getRobotY(), getRobotTheta()   metres, radians
//      api.vel.setV(v_mps), api.vel.setW(w_radps)             clamped to MaxV / MaxW
//      api.time_s()                                          sim time of this call, seconds
//
//  Until you write something, this template keeps the taxi still.
// ============================================================================================
#include <aula/teletaxi/taxi_algorithm.hpp>

namespace aula::teletaxi {
namespace {

class MyAlgorithm : public TaxiAlgorithm {
 public:
  void generatePath(TaxiApi& api) override {
    // TODO: fill the field from the destination, then mark the path.
    (void)api;
  }

  void execute(TaxiApi& api) override {
    // TODO: follow your path. Meanwhile: stay still.
    api.vel.setV(0.0);
    api.vel.setW(0.0);
  }
};

}  // namespace

std::unique_ptr<TaxiAlgorithm> makeStudentAlgorithm() { return std::make_unique<MyAlgorithm>(); }

}  // namespace aula::teletaxi
