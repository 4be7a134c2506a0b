#include "aula/autopark/reference_steps.hpp"

#include <aula/geometry/angles.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aula::autopark {

bool sensorsReady(const AutoparkApi& api) {
  return api.laser1.getLaserData().numLaser != 0 && api.laser2.getLaserData().numLaser != 0 &&
         api.laser3.getLaserData().numLaser != 0 && api.pose3d.received();
}

bool atArcStart(double to_go_m, double y_m, double lane_y_m, double yaw_rad) {
  return std::abs(to_go_m) < 0.05 && std::abs(y_m - lane_y_m) < 0.3 && std::abs(geometry::wrapAngle(yaw_rad)) < 0.05;
}

double approachSpeed(double to_go_m, double cruise_mps, double reverse_mps) {
  double v = std::clamp(0.8 * to_go_m, -reverse_mps, cruise_mps);
  if (std::abs(v) < 0.15) v = std::copysign(0.15, to_go_m);
  return v;
}

bool arrivedOffLane(double to_go_m, double off_lane_m) { return std::abs(to_go_m) < 0.5 && std::abs(off_lane_m) >= 0.3; }

double runUpM(double off_lane_m) { return 4.0 * std::abs(off_lane_m) + 4.0; }

bool firstArcDone(double remaining_m, double radius_m, double yaw_rad, double arc_rad) {
  return remaining_m <= radius_m * (1 - std::cos(yaw_rad)) || yaw_rad > arc_rad + 0.1;
}

Command centringCommand(double gap_front_m, double gap_rear_m, double yaw_rad, double radius_m) {
  const double error = (gap_front_m - gap_rear_m) / 2;  // > 0: move forward
  const double yaw_error = geometry::wrapAngle(yaw_rad);
  Command c;
  c.v_mps = std::clamp(0.8 * error, -0.5, 0.5);
  if (std::abs(c.v_mps) < 0.1) c.v_mps = std::copysign(0.1, error);
  const double limit = std::abs(c.v_mps) / radius_m;
  c.w_radps = std::clamp(-2.0 * yaw_error * (c.v_mps > 0 ? 1 : -1) * std::abs(c.v_mps), -limit, limit);
  if (std::abs(yaw_error) < 0.03) c.w_radps = 0;
  return c;
}

double rearClearanceM(const Slot& slot, double length_m, double width_m, double x_m, double y_m, double yaw_rad) {
  const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
  double clearance = std::numeric_limits<double>::infinity();
  for (const double along : {-length_m / 2, length_m / 2}) {
    for (const double across : {-width_m / 2, width_m / 2}) {
      const double cx = x_m + c * along - s * across, cy = y_m + s * along + c * across;
      if (cy < slot.edge_y_m) clearance = std::min(clearance, cx - slot.rear_x_m);
    }
  }
  return clearance;
}

bool centred(double gap_front_m, double gap_rear_m, double yaw_rad) {
  const double error = (gap_front_m - gap_rear_m) / 2;
  return std::abs(error) < 0.1 && std::abs(geometry::wrapAngle(yaw_rad)) < 0.03;
}

bool inSlot(const Slot& slot, double goal_y_m, double car_length_m, double x_m, double y_m, double yaw_rad) {
  const double half = car_length_m / 2;
  return x_m - half > slot.rear_x_m - 0.1 && x_m + half < slot.front_x_m + 0.1 && std::abs(y_m - goal_y_m) < 0.4 &&
         std::abs(geometry::wrapAngle(yaw_rad)) < 0.1;
}

double pastSlotM(const Slot& slot, int direction, double x_m) {
  return direction > 0 ? x_m - slot.front_x_m : slot.rear_x_m - x_m;
}

MappedStreet planningExtent(const MappedStreet& mapped, const Slot& slot, double x_m, double y_m, double lane_y_m,
                            double car_width_m) {
  MappedStreet e;
  e.min_x_m = std::max(mapped.min_x_m, std::min(x_m, slot.rear_x_m) - 12);
  e.max_x_m = std::min(mapped.max_x_m, std::max(x_m, slot.front_x_m) + 12);
  e.min_y_m = slot.curb_y_m;  // the slot's line: a curb the lasers may not see lies at or below it
  e.max_y_m = std::min(mapped.max_y_m, std::max(y_m, lane_y_m) + car_width_m / 2 + 3.0);
  return e;
}

ParkingPlannerOptions planOptions(unsigned seed, int attempt) {
  ParkingPlannerOptions options;
  options.seed = seed + static_cast<unsigned>(attempt);
  options.repeatable = true;  // sim time is the only clock: a loaded machine must not change the plan
  if (attempt > 0) {
    options.escape_step_m = 0.02;
    options.escape_cell_m = 0.025;
    options.escape_cell_yaw_rad = 0.0087;
    options.min_slot_clearance_m = 0.03;
    options.slot_clearance_step_m = 0.02;
    options.escape_max_expansions = 60000;
  }
  return options;
}

MappedStreet bodyExtent(const PlannedPath& path, const CarGeometry& car, const MappedStreet& start) {
  MappedStreet body = start;
  for (const Pose2D& p : path.poses) {
    for (const auto& corner : footprint(p, car, 0.0).corners()) {
      body.min_x_m = std::min(body.min_x_m, corner.x());
      body.max_x_m = std::max(body.max_x_m, corner.x());
      body.min_y_m = std::min(body.min_y_m, corner.y());
      body.max_y_m = std::max(body.max_y_m, corner.y());
    }
  }
  return body;
}

}  // namespace aula::autopark
