#include "aula/autopark/two_arc_park.hpp"

#include <aula/geometry/oriented_box.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace aula::autopark {
namespace {

constexpr double kMaxArcRad = 1.2;  // steeper than this, the car would be across the street
constexpr double kObstacleReachM = 6.0;
constexpr double kCurbMarginM = 0.05;

geometry::OrientedBox box(double x0, double x1, double y0, double y1) {
  return {{(x0 + x1) / 2, (y0 + y1) / 2, 0.0}, x1 - x0, y1 - y0};
}

// The two parked cars and the curb, as the lasers measured them. The curb is kept a smaller
// margin from: the body's corner swings over it in the second arc (its face is low, and the
// lasers see it exactly), where a car's bumper is not to be touched at all.
std::array<geometry::OrientedBox, 3> obstacles(const Slot& slot, double margin_m) {
  return {box(slot.rear_x_m - kObstacleReachM, slot.rear_x_m, slot.curb_y_m, slot.edge_y_m).inflated(margin_m),
          box(slot.front_x_m, slot.front_x_m + kObstacleReachM, slot.curb_y_m, slot.edge_y_m).inflated(margin_m),
          box(slot.rear_x_m - kObstacleReachM, slot.front_x_m + kObstacleReachM, slot.curb_y_m - 2.0, slot.curb_y_m)
              .inflated(kCurbMarginM)};
}

double arcAngle(double lane_y_m, double goal_y_m, double radius_m) {
  const double cos_arc = 1.0 - (lane_y_m - goal_y_m) / (2 * radius_m);
  return cos_arc < std::cos(kMaxArcRad) ? -1.0 : std::acos(std::clamp(cos_arc, -1.0, 1.0));
}

}  // namespace

bool twoArcSweepClear(const Slot& slot, double lane_y_m, double goal_y_m, double radius_m, double end_x_m,
                      const CarShape& car, double margin_m) {
  const double arc = arcAngle(lane_y_m, goal_y_m, radius_m);
  if (arc < 0) return false;
  const auto blocked = obstacles(slot, margin_m);
  const double c = car.turn_centre_x_m;
  // The turning point's path: two arcs of radius R; the first (reversing, the rear swinging
  // towards the curb) about a centre below the start, the second about one above the end.
  const double end_pivot_x = end_x_m + c;
  const double start_pivot_x = end_pivot_x + 2 * radius_m * std::sin(arc);
  auto clearAt = [&](double pivot_x, double pivot_y, double yaw) {
    const geometry::OrientedBox body{{pivot_x - c * std::cos(yaw), pivot_y - c * std::sin(yaw), yaw}, car.length_m,
                                     car.width_m};
    return std::none_of(blocked.begin(), blocked.end(), [&](const auto& b) { return geometry::overlap(body, b); });
  };
  const int steps = std::max(8, static_cast<int>(arc / 0.01));
  for (int i = 0; i <= steps; ++i) {
    const double phi = arc * i / steps;
    // First arc: yaw 0 -> arc.
    if (!clearAt(start_pivot_x - radius_m * std::sin(phi), lane_y_m - radius_m + radius_m * std::cos(phi), phi)) return false;
    // Second arc: yaw arc -> 0, about (start - 2R sin(arc), lane_y - R + 2R cos(arc)).
    const double cx = start_pivot_x - 2 * radius_m * std::sin(arc), cy = lane_y_m - radius_m + 2 * radius_m * std::cos(arc);
    if (!clearAt(cx + radius_m * std::sin(phi), cy - radius_m * std::cos(phi), phi)) return false;
  }
  return true;
}

TwoArcPlan planTwoArcPark(const Slot& slot, double lane_y_m, const CarShape& car) {
  TwoArcPlan plan;
  plan.lane_y_m = lane_y_m;
  plan.goal_y_m = slot.curb_y_m + kCurbClearanceM + car.width_m / 2;
  std::vector<double> radii;
  if (car.min_turn_radius_m > 0) {
    radii = {std::max(5.0, car.min_turn_radius_m)};
  } else {
    for (double r = 5.0; r >= 2.5 - 1e-9; r -= 0.25) radii.push_back(r);  // it turns in place: any radius
  }
  // End points: inside the slot, nearest first to a little behind its centre (the car then
  // drives forward to the centre; reversing in close behind the car ahead is where parks scrape).
  const double half = car.length_m / 2 + kSweepMarginM;
  const double preferred = slot.centreXM() - std::clamp((slot.lengthM() - car.length_m) / 2 - 0.6, 0.0, 1.0);
  auto findIn = [&](const Slot& s, TwoArcPlan& out) {
    std::vector<double> ends;
    for (double x = s.rear_x_m + half; x <= s.front_x_m - half + 1e-9; x += 0.05) ends.push_back(x);
    std::sort(ends.begin(), ends.end(), [&](double a, double b) { return std::abs(a - preferred) < std::abs(b - preferred); });
    for (const double radius : radii) {
      for (const double end_x : ends) {
        if (!twoArcSweepClear(s, lane_y_m, out.goal_y_m, radius, end_x, car)) continue;
        out.radius_m = radius;
        out.arc_rad = arcAngle(lane_y_m, out.goal_y_m, radius);
        out.end_x_m = end_x;
        out.start_x_m = end_x + 2 * radius * std::sin(out.arc_rad);
        return true;
      }
    }
    return false;
  };
  plan.feasible = findIn(slot, plan);
  if (plan.feasible) return plan;
  // What this street would need: the same slot, longer (its far car further ahead).
  Slot longer = slot;
  TwoArcPlan probe = plan;
  for (double extra = 0.1; extra <= 8.0 + 1e-9; extra += 0.1) {
    longer.front_x_m = slot.front_x_m + extra;
    if (findIn(longer, probe)) {
      plan.needed_length_m = longer.lengthM();
      break;
    }
  }
  char why[160];
  if (plan.needed_length_m > 0) {
    std::snprintf(why, sizeof why, "slot too short for a reactive park: %.1f m, need %.1f m", slot.lengthM(),
                  plan.needed_length_m);
  } else {
    std::snprintf(why, sizeof why, "no two-arc park fits this slot (%.1f m long, the lane %.1f m from its line)",
                  slot.lengthM(), lane_y_m - plan.goal_y_m);
  }
  plan.why = why;
  return plan;
}

}  // namespace aula::autopark
