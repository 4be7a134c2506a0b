#include "aula/teletaxi/gradient_field.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace aula::teletaxi {
namespace {
constexpr uint32_t kStraight = GradientField::kScale;
constexpr uint32_t kDiagonal = 141;  // sqrt(2) * kScale, to 0.03 %
}  // namespace

GradientField::GradientField(const cv::Mat& map, const FieldParams& params)
    : width_(map.cols), height_(map.rows), stride_(static_cast<size_t>(map.cols) + 2) {
  CV_Assert(map.type() == CV_8UC1 && !map.empty());
  cv::Mat distance;  // pixels to the nearest obstacle (Euclidean)
  cv::distanceTransform(map, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  cells_.assign(stride_ * (height_ + 2), CellData{kUnreached, kUnreached});  // border = blocked
  for (int y = 0; y < height_; ++y) {
    const float* d = distance.ptr<float>(y);
    for (int x = 0; x < width_; ++x) {
      if (d[x] < params.core_radius_cells) continue;
      double p = 0.0;
      if (d[x] < params.penalty_radius_cells) {
        const double span = params.penalty_radius_cells - params.core_radius_cells;
        p = params.penalty_max * (params.penalty_radius_cells - d[x]) / std::max(span, 1e-9);
      }
      cells_[index(x, y)].cost = static_cast<uint32_t>(std::lround(p * kScale));
    }
  }
  max_edge_ = kDiagonal;
  for (const CellData& c : cells_) {
    if (c.cost != kUnreached) max_edge_ = std::max(max_edge_, kDiagonal + c.cost);
  }
}

bool GradientField::traversable(int x, int y) const {
  return x >= 0 && y >= 0 && x < width_ && y < height_ && cells_[index(x, y)].cost != kUnreached;
}

float GradientField::penalty(int x, int y) const {
  if (!traversable(x, y)) return std::numeric_limits<float>::infinity();
  return static_cast<float>(cells_[index(x, y)].cost) / kScale;
}

float GradientField::value(int x, int y) const {
  if (!traversable(x, y)) return std::numeric_limits<float>::infinity();
  const uint32_t v = cells_[index(x, y)].field;
  return v == kUnreached ? std::numeric_limits<float>::infinity() : static_cast<float>(v) / kScale;
}

bool GradientField::compute(Cell goal) {
  for (CellData& c : cells_) c.field = c.cost == kUnreached ? 0 : kUnreached;
  goal_ = goal;
  if (!traversable(goal.x, goal.y)) {
    for (CellData& c : cells_) c.field = kUnreached;
    return false;
  }

  // Dial's algorithm: a circular array of buckets indexed by cost, wide enough for the
  // largest single edge (a diagonal step into the most penalised cell). Slots advance by
  // addition and wrap by one subtraction: a modulo per cost unit was most of the time.
  const size_t ring = max_edge_ + 1;
  if (buckets_.size() != ring) buckets_.assign(ring, {});
  for (auto& b : buckets_) b.clear();

  const ptrdiff_t s = static_cast<ptrdiff_t>(stride_);
  const ptrdiff_t offsets[8] = {1, -1, s, -s, s + 1, s - 1, -s + 1, -s - 1};
  const uint32_t steps[8] = {kStraight, kStraight, kStraight, kStraight, kDiagonal, kDiagonal, kDiagonal, kDiagonal};

  const uint32_t start = static_cast<uint32_t>(index(goal.x, goal.y));
  cells_[start].field = 0;
  buckets_[0].push_back(start);
  size_t pending = 1;
  CellData* grid = cells_.data();
  size_t slot = 0;
  for (uint32_t current = 0; pending > 0; ++current) {
    auto& bucket = buckets_[slot];
    if (!bucket.empty()) {
      for (size_t k = 0; k < bucket.size(); ++k) {
        const uint32_t cell = bucket[k];
        --pending;
        if (grid[cell].field != current) continue;  // stale entry: a shorter path was found
        for (int n = 0; n < 8; ++n) {
          const uint32_t next = static_cast<uint32_t>(cell + offsets[n]);
          CellData& neighbour = grid[next];
          const uint32_t delta = steps[n] + neighbour.cost;  // wraps for blocked cells: harmless,
          const uint32_t candidate = current + delta;        // their field 0 is never beaten
          if (candidate < neighbour.field) {
            neighbour.field = candidate;
            size_t target = slot + delta;
            if (target >= ring) target -= ring;
            buckets_[target].push_back(next);
            ++pending;
          }
        }
      }
      bucket.clear();
    }
    if (++slot == ring) slot = 0;
  }
  return true;
}

std::vector<Cell> GradientField::descend(Cell start) const {
  std::vector<Cell> path;
  if (!traversable(start.x, start.y) || cells_[index(start.x, start.y)].field == kUnreached) return path;
  Cell c = start;
  path.push_back(c);
  static constexpr int dx[8] = {1, -1, 0, 0, 1, -1, 1, -1};
  static constexpr int dy[8] = {0, 0, 1, -1, 1, 1, -1, -1};
  while (!(c == goal_)) {
    uint32_t best = cells_[index(c.x, c.y)].field;
    Cell next = c;
    for (int n = 0; n < 8; ++n) {
      const CellData& d = cells_[index(c.x + dx[n], c.y + dy[n])];
      const uint32_t v = d.field;
      if (d.cost != kUnreached && v < best) {
        best = v;
        next = {c.x + dx[n], c.y + dy[n]};
      }
    }
    if (next == c) break;  // cannot happen on a Dijkstra field; guards against a loop
    c = next;
    path.push_back(c);
  }
  return path;
}

}  // namespace aula::teletaxi
