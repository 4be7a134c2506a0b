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

BoxChord::BoxChord(const std::array<Eigen::Vector2d, 4>& corners) : corners_(corners) {
  for (int i = 0; i < 4; ++i) {
    const auto& a = corners[i];
    const auto& b = corners[(i + 1) % 4];
    const double dy = b.y() - a.y();
    if (std::abs(dy) < 1e-12) continue;
    const auto& lo = dy > 0 ? a : b;
    const auto& hi = dy > 0 ? b : a;
    edges_[count_++] = {lo.y(), hi.y(), lo.x(), (hi.x() - lo.x()) / (hi.y() - lo.y())};
  }
}

void BoxChord::widen(double y, double& lo_x, double& hi_x) const {
  for (int i = 0; i < count_; ++i) {
    const Edge& e = edges_[i];
    if (y < e.y0 || y > e.y1) continue;
    const double x = e.x0 + (y - e.y0) * e.slope;
    lo_x = std::min(lo_x, x);
    hi_x = std::max(hi_x, x);
  }
}

void BoxChord::widenByCorners(bool (*keep)(double corner_y, double y0, double y1), double y0, double y1, double& lo_x,
                              double& hi_x) const {
  for (const auto& p : corners_) {
    if (!keep(p.y(), y0, y1)) continue;
    lo_x = std::min(lo_x, p.x());
    hi_x = std::max(hi_x, p.x());
  }
}

BoxChord::Span BoxChord::bottom(double ymin) const {
  Span span;
  widen(ymin, span.lo_x, span.hi_x);
  // At ymin the chord may be a horizontal edge or a vertex.
  widenByCorners([](double cy, double y0, double) { return cy <= y0; }, ymin, ymin, span.lo_x, span.hi_x);
  return span;
}

BoxChord::Span BoxChord::top(double b1, double ymax) const {
  Span span;
  widen(b1, span.lo_x, span.hi_x);
  if (b1 >= ymax) widenByCorners([](double cy, double y0, double) { return cy >= y0; }, ymax, ymax, span.lo_x, span.hi_x);
  return span;
}

BoxChord::Span BoxChord::band(const Span& below, const Span& above, double b0, double b1) const {
  // The box is convex: its span in the band is the hull of the chords at the band's (clipped)
  // edges and the corners strictly inside it.
  Span span{std::min(above.lo_x, below.lo_x), std::max(above.hi_x, below.hi_x)};
  widenByCorners([](double cy, double y0, double y1) { return cy > y0 && cy < y1; }, b0, b1, span.lo_x, span.hi_x);
  return span;
}

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
  const BoxChord chord(corners);
  BoxChord::Span below = chord.bottom(ymin);
  for (int r = r0; r <= r1; ++r) {
    const double b1 = std::min(oy_ + (r + 1) * res_, ymax);
    const BoxChord::Span above = chord.top(b1, ymax);
    const BoxChord::Span span = chord.band(below, above, oy_ + r * res_, b1);
    below = above;
    if (!(span.lo_x <= span.hi_x)) continue;
    if (rowBlocked(r, span.lo_x, span.hi_x)) return false;
  }
  return true;
}

bool FootprintChecker::rowBlocked(int row, double lo_x, double hi_x) const {
  const int c0 = static_cast<int>(std::floor((lo_x - ox_) / res_));
  const int c1 = static_cast<int>(std::floor((hi_x - ox_) / res_));
  if (c0 < 0 || c1 >= width_) return true;
  const int* p = &prefix_[static_cast<size_t>(row) * (width_ + 1)];
  return p[c1 + 1] - p[c0] > 0;
}

}  // namespace aula::autopark
