#include <aula/autopark/footprint_checker.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aula::autopark {

FootprintChecker::FootprintChecker(const OccupancyGrid& grid, const CarGeometry& car, double inflation_m)
    : ox_(grid.minX_m()), oy_(grid.minY_m()), res_(grid.resolution_m()), width_(grid.width()),
      height_(grid.height()), car_(car), inflation_m_(inflation_m) {
  prefix_.assign(static_cast<size_t>(height_) * (width_ + 1), 0);
  const auto& cells = grid.cells();
  for (int r = 0; r < height_; ++r) {
    int* p = &prefix_[static_cast<size_t>(r) * (width_ + 1)];
    // The sweep below climbs in y: band r is the grid's row height - 1 - r (north-up).
    const std::uint8_t* row = &cells[static_cast<size_t>(height_ - 1 - r) * width_];
    for (int c = 0; c < width_; ++c) p[c + 1] = p[c] + (row[c] ? 1 : 0);
  }
}

bool FootprintChecker::freeCentre(const Pose2D& centre) const { return freeCentre(centre, inflation_m_); }

bool FootprintChecker::freeCentre(const Pose2D& centre, double inflation_m) const {
  const auto corners = footprint(centre, car_, inflation_m).corners();
  double ymin = std::numeric_limits<double>::infinity(), ymax = -ymin;
  for (const auto& p : corners) {
    ymin = std::min(ymin, p.y());
    ymax = std::max(ymax, p.y());
  }
  const int r0 = static_cast<int>(std::floor((ymin - oy_) / res_));
  const int r1 = static_cast<int>(std::floor((ymax - oy_) / res_));
  if (r0 < 0 || r1 >= height_) return false;
  // Edges as x(y) = x0 + (y - y0) * slope over [y0, y1] (horizontal edges add nothing: their
  // end points are vertices, handled below).
  struct Edge {
    double y0, y1, x0, slope;
  };
  Edge edges[4];
  int ne = 0;
  for (int i = 0; i < 4; ++i) {
    const auto& a = corners[i];
    const auto& b = corners[(i + 1) % 4];
    const double dy = b.y() - a.y();
    if (std::abs(dy) < 1e-12) continue;
    const auto& lo = dy > 0 ? a : b;
    const auto& hi = dy > 0 ? b : a;
    edges[ne++] = {lo.y(), hi.y(), lo.x(), (hi.x() - lo.x()) / (hi.y() - lo.y())};
  }
  // x-range of the box's chord at height y (y within [ymin, ymax]).
  auto chord = [&](double y, double& lo, double& hi) {
    for (int i = 0; i < ne; ++i) {
      const Edge& e = edges[i];
      if (y < e.y0 || y > e.y1) continue;
      const double x = e.x0 + (y - e.y0) * e.slope;
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  };
  double prev_lo = std::numeric_limits<double>::infinity(), prev_hi = -prev_lo;
  chord(ymin, prev_lo, prev_hi);
  for (const auto& p : corners) {  // at ymin the chord may be a horizontal edge or a vertex
    if (p.y() <= ymin) {
      prev_lo = std::min(prev_lo, p.x());
      prev_hi = std::max(prev_hi, p.x());
    }
  }
  for (int r = r0; r <= r1; ++r) {
    // Span of the box within this row's band = hull of the chords at the band's (clipped) edges
    // and the vertices inside the band (the box is convex).
    const double b1 = std::min(oy_ + (r + 1) * res_, ymax);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    chord(b1, lo, hi);
    if (b1 >= ymax) {
      for (const auto& p : corners) {
        if (p.y() >= ymax) {
          lo = std::min(lo, p.x());
          hi = std::max(hi, p.x());
        }
      }
    }
    double xmin = std::min(lo, prev_lo), xmax = std::max(hi, prev_hi);
    const double b0 = oy_ + r * res_;
    for (const auto& p : corners) {
      if (p.y() > b0 && p.y() < b1) {
        xmin = std::min(xmin, p.x());
        xmax = std::max(xmax, p.x());
      }
    }
    prev_lo = lo;
    prev_hi = hi;
    if (!(xmin <= xmax)) continue;
    const int c0 = static_cast<int>(std::floor((xmin - ox_) / res_));
    const int c1 = static_cast<int>(std::floor((xmax - ox_) / res_));
    if (c0 < 0 || c1 >= width_) return false;
    const int* p = &prefix_[static_cast<size_t>(r) * (width_ + 1)];
    if (p[c1 + 1] - p[c0] > 0) return false;
  }
  return true;
}

}  // namespace aula::autopark
