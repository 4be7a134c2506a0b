#pragma once
// The classic vacuum reference's (RoombaReference.cpp, --algorithm=classic) tuning and its
// steps that are plain arithmetic on laser ranges, apart so that each is tested alone.
#include <aula/component/devices.hpp>

#include <algorithm>
#include <cmath>

namespace aula::vacuum::roomba {

// Every tuning constant of the reference, with its unit. The defaults are the tuned values.
struct Settings {
  double max_speed_mps = 0.5;
  // Spiral: the radius grows by spiral_growth_m2ps / radius each second (never divided by less
  // than spiral_min_radius_m); it ends when something is ahead or after spiral_max_s.
  double spiral_start_radius_m = 0.15;
  double spiral_growth_m2ps = 0.05;
  double spiral_min_radius_m = 0.1;
  double spiral_stop_front_m = 0.3;
  double spiral_stop_wide_m = 0.2;
  double spiral_max_s = 40.0;
  // Laser sectors, from straight ahead (rad).
  double front_half_rad = 0.45;
  double front_wide_half_rad = 1.0;
  double right_from_rad = -1.58;
  double right_to_rad = -1.25;
  // Dead reckoning: a wall this close at the nose means the robot did not move.
  double blocked_front_m = 0.12;
  // Straight runs.
  double cross_slow_front_m = 0.5;
  double cross_slow_speed_mps = 0.3;
  double cross_stop_front_m = 0.22;
  double cross_stop_wide_m = 0.17;
  double quick_fail_reset_s = 1.0;   // a run longer than this is not boxed in
  double quick_fail_window_s = 0.5;  // blocked this soon after a turn is a quick fail
  int quick_fails_to_escape = 3;
  // Wall following (right hand).
  double wall_every_s = 60.0;        // at most one wall-follow per this long
  double wall_trigger_right_m = 0.5; // a wall this close on the right starts one
  double wall_time_s = 45.0;
  double wall_corner_front_m = 0.3;
  double wall_corner_wide_m = 0.18;
  double wall_corner_turn_radps = 1.8;
  double wall_lost_m = 0.7;
  double wall_search_speed_mps = 0.3;
  double wall_search_turn_radps = 1.3;
  double wall_speed_mps = 0.45;
  double wall_gain_radps_per_m = 5.0;
  double wall_follow_distance_m = 0.24;
  double wall_max_turn_radps = 1.5;
  // Bumps and escapes.
  double bump_debounce_s = 0.3;
  double bump_window_s = 5.0;
  int bumps_to_trapped = 3;
  double backoff_speed_mps = 0.15;
  double backoff_s = 0.3;
  double backoff_trapped_s = 0.8;
  double trapped_turn_spread_rad = 0.7;  // trapped: turn round, +- this
  double spin_speed_mps = 0.05;          // slower than this counts as spinning on the spot
  double spin_limit_s = 4.0;
  // Turning on the spot to a heading.
  double turn_max_radps = 2.8;
  double turn_min_radps = 0.5;
  double turn_gain_per_s = 3.0;
  double turn_tolerance_rad = 0.1;
  double turn_timeout_s = 3.0;
  // Choosing a heading.
  int heading_half_width_beams = 8;  // ~8 degrees, the robot's width at ~1 m
  double heading_skip_ahead_rad = 0.35;
  double heading_min_clear_m = 0.8;
  double heading_max_reach_m = 4.0;
  double novelty_floor = 0.05;
  double novelty_start_m = 0.5;
  double open_half_rad = 1.57;
  double open_side_m = 0.9;       // free this far in the front half (+- open_half_rad): open space
  double spiral_chance = 0.35;    // in open space, spiral with this probability
  // Dead-reckoned memory.
  double memory_cell_m = 0.25;
};

// A motor command: forward speed and turn rate.
struct Command {
  double v_mps = 0;
  double w_radps = 0;
};

// The laser's nearest echo within [from_rad, to_rad] of straight ahead (max range if none).
inline double sectorMin(const component::LaserData& laser, double from_rad, double to_rad) {
  double m = laser.maxRange;
  for (int i = 0; i < laser.numLaser; ++i) {
    const double a = laser.angle(i);
    if (a >= from_rad && a <= to_rad) m = std::min<double>(m, laser.values_m[i]);
  }
  return m;
}

// The spiral's radius after dt_s: it grows by spiral_growth_m2ps / radius each second, so the
// rings stay about equally far apart as they widen.
inline double spiralRadiusAfter(const Settings& s, double radius_m, double dt_s) {
  return radius_m + s.spiral_growth_m2ps * dt_s / std::max(radius_m, s.spiral_min_radius_m);
}

// Right-hand wall following on three ranges: a corner ahead turns left on the spot, a wall lost
// on the right curves right to find it, else it steers to keep wall_follow_distance_m from it.
inline Command wallFollow(const Settings& s, double front_m, double front_wide_m, double right_m) {
  if (front_m < s.wall_corner_front_m || front_wide_m < s.wall_corner_wide_m) return {0.0, s.wall_corner_turn_radps};
  if (right_m > s.wall_lost_m) return {s.wall_search_speed_mps, -s.wall_search_turn_radps};
  return {s.wall_speed_mps, std::clamp(-s.wall_gain_radps_per_m * (right_m - s.wall_follow_distance_m),
                                       -s.wall_max_turn_radps, s.wall_max_turn_radps)};
}

// Turning on the spot to a heading error: faster the farther off, within turn_max_radps.
inline double turnRate(const Settings& s, double error_rad) {
  return std::copysign(std::min(s.turn_max_radps, s.turn_min_radps + s.turn_gain_per_s * std::abs(error_rad)), error_rad);
}

}  // namespace aula::vacuum::roomba
