// TeleTaxi reference solution: Gradient Path Planning.
// generatePath(): the full field from the destination (wavefront + obstacle penalty) is
// written into the student's Grid, the steepest-descent path is marked on it.
// execute(): a look-ahead pilot follows the path smoothly and stops at the destination.
#include <aula/teletaxi/gradient_field.hpp>
#include <aula/teletaxi/references.hpp>
#include <aula/teletaxi/path_pilot.hpp>
#include <aula/teletaxi/taxi_algorithm.hpp>

#include <cmath>
#include <memory>

namespace aula::teletaxi {
namespace {

class GppReference : public TaxiAlgorithm {
 public:
  void generatePath(TaxiApi& api) override {
    Grid& grid = api.grid;
    if (!field_ || field_->width() != grid.getWidth()) field_ = std::make_unique<GradientField>(grid.getMap());
    const auto [gx, gy] = grid.getDestiny();
    const auto [px, py] = grid.getPose();
    pilot_.setPath({});
    if (!field_->compute({gx, gy})) return;  // destination inside a building or too close to one
    for (int y = 0; y < grid.getHeight(); ++y) {
      for (int x = 0; x < grid.getWidth(); ++x) {
        const float v = field_->value(x, y);
        grid.setVal(x, y, std::isfinite(v) ? v : -1.0f);
      }
    }
    // The taxi may start in a cell of the penalty core (near a wall): descend from the nearest
    // traversable cell around it.
    Cell start{px, py};
    for (int r = 0; r <= 4 && !field_->traversable(start.x, start.y); ++r) {
      for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
          if (field_->traversable(px + dx, py + dy) && std::isfinite(field_->value(px + dx, py + dy))) start = {px + dx, py + dy};
        }
      }
    }
    std::vector<Point2> points;
    for (const Cell& c : field_->descend(start)) {
      grid.setPathVal(c.x, c.y, 1.0f);
      const auto [wx, wy] = grid.gridToWorld(c.x, c.y);
      points.push_back({wx, wy});
    }
    pilot_.setPath(points);
    grid.setPathFinded();
  }

  void execute(TaxiApi& api) override {
    const double x = api.sensor.getRobotX(), y = api.sensor.getRobotY();
    const int64_t utime = api.sensor.utime();
    const double dt_s = (utime - last_utime_) / 1e6;
    const double speed = last_utime_ >= 0 && dt_s > 0 ? std::hypot(x - last_x_, y - last_y_) / dt_s : 0.0;
    last_utime_ = utime;
    last_x_ = x;
    last_y_ = y;
    const PilotCommand cmd = pilot_.command(x, y, api.sensor.getRobotTheta(), speed);
    api.vel.setV(cmd.v_mps);
    api.vel.setW(cmd.w_radps);
  }

 private:
  std::unique_ptr<GradientField> field_;
  PathPilot pilot_;
  int64_t last_utime_ = -1;
  double last_x_ = 0, last_y_ = 0;
};

}  // namespace

std::unique_ptr<TaxiAlgorithm> makeReferenceAlgorithm() { return std::make_unique<GppReference>(); }

}  // namespace aula::teletaxi
