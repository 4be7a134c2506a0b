// A TeleTaxi algorithm that follows the grid's path, for the test that one API serves two
// languages: its Python port (tests/data/python/teletaxi_follow/MyAlgorithm.py) must earn the
// same report, byte for byte but the algorithm's name. generatePath(): a breadth-first wave from
// the destination over the clear cells (free, and 2 cells from any obstacle) into the grid's
// field, and the steepest descent from the taxi's cell into the grid's path; execute(): a
// look-ahead along that path. No random draw.
// Keep the two in step, line by line.
#include <aula/teletaxi/taxi_algorithm.hpp>

#include <cmath>
#include <deque>
#include <vector>

namespace aula::teletaxi {
namespace {

double wrap(double a) {
  while (a > M_PI) a -= 2 * M_PI;
  while (a < -M_PI) a += 2 * M_PI;
  return a;
}

const int kSteps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
const int kMargin = 2;  // cells

class Follow : public TaxiAlgorithm {
 public:
  void generatePath(TaxiApi& api) override {
    Grid& grid = api.grid;
    const int width = grid.getWidth(), height = grid.getHeight();
    const auto [gx, gy] = grid.getDestiny();
    const auto [px, py] = grid.getPose();
    std::vector<bool> clear(width * height, false);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        bool all_free = true;
        for (int dy = -kMargin; dy <= kMargin; ++dy) {
          for (int dx = -kMargin; dx <= kMargin; ++dx) all_free = all_free && grid.isFree(x + dx, y + dy);
        }
        clear[y * width + x] = all_free;
      }
    }
    std::vector<int> distance(width * height, -1);
    std::deque<std::pair<int, int>> wave;
    if (clear[gy * width + gx]) {
      distance[gy * width + gx] = 0;
      wave.push_back({gx, gy});
    }
    while (!wave.empty()) {
      const auto [x, y] = wave.front();
      wave.pop_front();
      const int d = distance[y * width + x];
      grid.setVal(x, y, static_cast<float>(d));
      for (const auto& step : kSteps) {
        const int nx = x + step[0], ny = y + step[1];
        if (nx >= 0 && ny >= 0 && nx < width && ny < height && clear[ny * width + nx] && distance[ny * width + nx] < 0) {
          distance[ny * width + nx] = d + 1;
          wave.push_back({nx, ny});
        }
      }
    }
    path_.clear();
    progress_ = 0;
    // The taxi may stand closer to a wall than the margin: start from the first reached cell around it.
    int x = -1, y = -1;
    for (int r = 0; r <= 4 && x < 0; ++r) {
      for (int dy = -r; dy <= r && x < 0; ++dy) {
        for (int dx = -r; dx <= r && x < 0; ++dx) {
          const int cx = px + dx, cy = py + dy;
          if (cx >= 0 && cy >= 0 && cx < width && cy < height && distance[cy * width + cx] >= 0) {
            x = cx;
            y = cy;
          }
        }
      }
    }
    if (x < 0) return;
    for (;;) {
      grid.setPathVal(x, y, 1.0f);
      const auto [wx, wy] = grid.gridToWorld(x, y);
      path_.push_back({wx, wy});
      const int d = distance[y * width + x];
      if (d == 0) break;
      for (const auto& step : kSteps) {
        const int nx = x + step[0], ny = y + step[1];
        if (nx >= 0 && ny >= 0 && nx < width && ny < height && distance[ny * width + nx] == d - 1) {
          x = nx;
          y = ny;
          break;
        }
      }
    }
    grid.setPathFinded();
  }

  void execute(TaxiApi& api) override {
    const double x = api.sensor.getRobotX(), y = api.sensor.getRobotY(), yaw = api.sensor.getRobotTheta();
    if (path_.empty()) {
      api.vel.setV(0.0);
      api.vel.setW(0.0);
      return;
    }
    const int last = static_cast<int>(path_.size()) - 1;
    // The closest point a little ahead (the taxi cuts corners), then past what is near.
    const int window_end = std::min(progress_ + 20, last);
    for (int i = progress_ + 1; i <= window_end; ++i) {
      if (distanceTo(path_[i], x, y) < distanceTo(path_[progress_], x, y)) progress_ = i;
    }
    while (progress_ < last && distanceTo(path_[progress_], x, y) < 4.0) progress_ += 1;
    const std::pair<double, double>& target = path_[std::min(progress_ + 6, last)];
    const double to_goal = distanceTo(path_[last], x, y);
    const double error = wrap(std::atan2(target.second - y, target.first - x) - yaw);
    double v = 0.0, w = 0.0;
    if (to_goal > 1.0) {
      v = std::min(6.0, 0.5 + 0.5 * to_goal) * std::max(0.0, std::cos(error));
      w = 2.0 * error;
    }
    api.vel.setV(v);
    api.vel.setW(w);
  }

 private:
  static double distanceTo(const std::pair<double, double>& p, double x, double y) {
    const double dx = p.first - x, dy = p.second - y;
    return std::sqrt(dx * dx + dy * dy);
  }

  std::vector<std::pair<double, double>> path_;
  int progress_ = 0;
};

}  // namespace

std::unique_ptr<TaxiAlgorithm> makeStudentAlgorithm() { return std::make_unique<Follow>(); }

}  // namespace aula::teletaxi
