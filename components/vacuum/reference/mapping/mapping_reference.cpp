#include "mapping_reference.hpp"

#include <aula/geometry/angles.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aula::vacuum::mapping {
namespace {

using geometry::wrapAngle;

Point2 along(Point2 p, double d_m, double yaw_rad) { return {p.x_m + d_m * std::cos(yaw_rad), p.y_m + d_m * std::sin(yaw_rad)}; }
double distance(Point2 a, Point2 b) { return std::hypot(a.x_m - b.x_m, a.y_m - b.y_m); }

}  // namespace

MappingReference::MappingReference(uint64_t seed, const MappingSettings& settings)
    : s_(settings), coverage_(map_), rng_(seed * 2654435761ull + 7) {}

void MappingReference::execute(VacuumApi& api) {
  const auto& scan = api.laser.getLaserData();
  if (scan.numLaser == 0) return;  // no scan yet
  ++n_;
  period_s_ = api.period_s;
  const double yaw = api.pose3d.getYaw();
  scan_ = &scan;
  yaw_ = yaw;
  const bool bumped = api.bumper.getBumperData().state == 1;
  localize(scan, yaw, bumped);
  map_.markFree(est_, s_.footprint_m);
  if (trail_.empty() || distance(est_, trail_.back()) >= s_.trail_step_m) {
    trail_.push_back(est_);
    if (trail_.size() > 200) trail_.pop_front();  // 20 m: far more than unwedge_m needs
  }
  if (coverage_.sweep(est_) >= s_.fresh_cells || mode_ == Mode::Spin) fresh_s_ = now_s_;
  coverage_.expireBumps(now_s_);

  const bool turning_on_spot = cmd_v_ == 0 && cmd_w_ != 0;
  if (bumped && mode_ != Mode::Backoff && (cmd_v_ > 0 || turning_on_spot)) {
    onBump(api.bumper.getBumperData().bumper, yaw);
  } else if (bumped && mode_ == Mode::Backoff && cmd_v_ < 0 && backoff_v_ < 0 && now_s_ - mode_start_s_ > 2 * period_s_) {
    backoff_v_ = s_.backoff_mps;  // backing off pressed something behind: forward instead
    mode_start_s_ = now_s_;
  }
  // Nothing new swept for long, whatever the plans said (a goal it cannot reach and keeps
  // choosing, a spot it cannot leave): give up what it was doing and drive out by the laser.
  if (mode_ == Mode::Follow && now_s_ - fresh_s_ > s_.no_fresh_s) {
    fresh_s_ = now_s_;
    if (!waypoints_.empty()) coverage_.forget(waypoints_.back());
    escapeByLaser();
  }
  double v = 0, w = 0;
  switch (mode_) {
    case Mode::Spin:
      spin(yaw, w);
      break;
    case Mode::Backoff:
      backOff(v, w);
      break;
    case Mode::Follow:
      follow(yaw, v, w);
      break;
  }
  api.motors.sendV(v);
  api.motors.sendW(w);
  prev_cmd_w_ = cmd_w_;
  cmd_v_ = std::clamp(v, -s_.max_speed_mps, s_.max_speed_mps);
  cmd_w_ = w;
  tellBelief(api);
}

// What the cleaner believes, for the window and the run's log: its pose every period; its map
// every 10 s of sim time, within 3 m of where it has been, at twice its cell (a cell occupied if
// any of its four is, else free if one is known free, else unknown).
void MappingReference::tellBelief(VacuumApi& api) {
  api.belief.setPose(est_.x_m, est_.y_m, yaw_);
  visited_min_ = {std::min(visited_min_.x_m, est_.x_m), std::min(visited_min_.y_m, est_.y_m)};
  visited_max_ = {std::max(visited_max_.x_m, est_.x_m), std::max(visited_max_.y_m, est_.y_m)};
  if (now_s_ < next_belief_map_s_) return;
  next_belief_map_s_ = now_s_ + 10;
  constexpr double kMarginM = 3;
  const int i0 = std::max(0, map_.col(visited_min_.x_m - kMarginM)) & ~1;
  const int j0 = std::max(0, map_.row(visited_min_.y_m - kMarginM)) & ~1;
  const int i1 = std::min(map_.width(), map_.col(visited_max_.x_m + kMarginM));
  const int j1 = std::min(map_.width(), map_.row(visited_max_.y_m + kMarginM));
  component::BeliefMap belief;
  belief.width = std::max(1, (i1 - i0) / 2);
  belief.height = std::max(1, (j1 - j0) / 2);
  belief.resolution_m = 2 * map_.cellM();
  const Point2 corner = map_.centre(i0, j0);
  belief.origin_x_m = corner.x_m - map_.cellM() / 2;
  belief.origin_y_m = corner.y_m - map_.cellM() / 2;
  belief.cells.assign(static_cast<size_t>(belief.width) * belief.height, 128);
  for (int r = 0; r < belief.height; ++r) {
    for (int c = 0; c < belief.width; ++c) {
      bool occupied = false, free = false;
      for (int k = 0; k < 4; ++k) {
        const int i = i0 + 2 * c + k % 2, j = j0 + 2 * r + k / 2;
        occupied = occupied || map_.occupied(i, j);
        free = free || map_.knownFree(i, j);
      }
      belief.cells[static_cast<size_t>(r) * belief.width + c] = occupied ? 255 : free ? 0 : 128;
    }
  }
  api.belief.setMap(std::move(belief));
}

// A first look all round, a quarter turn at a time, each held still for a clean scan.
void MappingReference::spin(double yaw, double& w) {
  if (spin_quarters_ == 0) {
    spin_target_ = yaw;
    spin_quarters_ = 1;
  }
  const double error = wrapAngle(spin_target_ - yaw);
  if (std::abs(error) > 0.05) {
    w = std::copysign(std::clamp(s_.turn_gain_per_s * std::abs(error), 0.3, s_.turn_max_radps), error);
  } else if (++spin_hold_ >= 3) {
    spin_hold_ = 0;
    if (spin_quarters_++ >= 4) decide();
    else spin_target_ = wrapAngle(spin_target_ + M_PI / 2);
  }
}

// A bump moving forward: back off, and unless the map has a wall there, the plans keep away from
// it for a while (the laser missed something). A bump turning on the spot: a disc pressed on a
// wall may not turn (friction), so it moves off too; back, or forward if backing off pressed it.
void MappingReference::onBump(int bumper, double yaw) {
  if (cmd_v_ > 0) {
    // Where it touched: straight ahead, or (a side's glance) about half way round to that side.
    const double bearing_rad = bumper == 1 ? 0.0 : (bumper == 0 ? 1 : -1) * s_.side_bump_rad;
    const Point2 ahead = along(est_, s_.bump_ahead_m, yaw + bearing_rad);
    // Bumped from here before: the wall there is a centimetre or two nearer than the map has it
    // (a path along h2's corridor clipped a box's corner for 50 s), so it is marked anyway.
    const bool repeated = distance(est_, last_bump_m_) < s_.same_goal_m;
    if (repeated || map_.clearanceM(map_.col(ahead.x_m), map_.row(ahead.y_m)) > s_.bump_known_m) {
      coverage_.addBump(ahead, now_s_ + s_.bump_memory_s);
    }
    last_bump_m_ = est_;
  }
  // The same goal bumped on the way to again: the disc does not pass where the map has it clear
  // (h2: 700 bumps in a 0.43 m corridor, each push dragging the estimate along it unseen).
  if (mode_ == Mode::Follow && !waypoints_.empty()) {
    const Point2 goal = waypoints_.back();
    goal_bumps_ = distance(goal, bumped_goal_) < s_.same_goal_m ? goal_bumps_ + 1 : 1;
    bumped_goal_ = goal;
    if (goal_bumps_ >= s_.goal_bumps) {
      coverage_.forget(goal);
      goal_bumps_ = 0;
    }
  }
  if (distance(est_, last_wedge_m_) > s_.unwedge_m) wedge_repeats_ = 0;  // out of the last wedge
  unwedge_ = unwedge_ || wedged(est_);
  const bool again = now_s_ - backoff_end_s_ < s_.backoff_s;  // the last backoff ended pressed
  backoff_v_ = cmd_v_ > 0 || !again ? -s_.backoff_mps : -backoff_v_;
  mode_ = Mode::Backoff;
  mode_start_s_ = now_s_;
  if (wedge_repeats_ >= 2) wiggle();
}

// Backing off (or a wiggle's move) for its time, then the next decision.
void MappingReference::backOff(double& v, double& w) {
  v = backoff_v_;
  w = backoff_w_;
  if (now_s_ - mode_start_s_ <= s_.backoff_s) return;
  backoff_end_s_ = now_s_;
  backoff_w_ = 0;
  on_lane_ = false;
  decide();
  v = 0;
  w = 0;
}

// Wedged again where backing out along its trail did not get it out (seen under realistic noise:
// pinned between a box's corner and a wall, a gap narrower than the disc, where turning on the
// spot rubbed and did not turn, for 650 s): each bump there tries the next of six moves,
// backwards and forwards on arcs each way and turns each way, until one gets it out.
void MappingReference::wiggle() {
  static constexpr double kMoves[6][2] = {{-1, 1}, {-1, -1}, {1, 1}, {1, -1}, {0, 1}, {0, -1}};
  const double* move = kMoves[wiggle_step_++ % 6];
  backoff_v_ = move[0] * s_.backoff_mps;
  backoff_w_ = move[1] * s_.wiggle_radps;
  mode_start_s_ = now_s_ + s_.wiggle_s - s_.backoff_s;  // Backoff ends backoff_s after this
}

void MappingReference::localize(const component::LaserData& scan, double yaw, bool bumped) {
  // The executes come period_s apart, and the newest scan is never from the future: the scans'
  // stamps place the executes on the simulated clock.
  const double stamp_s = scan.timeStamp * 1e-6;
  const double exec_s = n_ * period_s_;
  if (!clock_started_) {
    clock_started_ = true;
    clock_offset_s_ = stamp_s - exec_s;
    last_now_s_ = stamp_s;
    last_yaw_ = yaw;
  }
  clock_offset_s_ = std::max(clock_offset_s_, stamp_s - exec_s);
  now_s_ = clock_offset_s_ + exec_s;
  const double dt = std::max(0.0, now_s_ - last_now_s_);
  const double dyaw = wrapAngle(yaw - last_yaw_);
  // Pressed on something, it does not go where it is told, backing off included (h2: wedged in a
  // box's corner, every backoff it did not make moved the estimate 6 cm, and it was lost).
  const bool blocked = bumped && cmd_v_ != 0;
  if (!blocked) {
    const Point2 before = est_;
    est_ = along(est_, cmd_v_ * dt, last_yaw_ + dyaw / 2);
    // The wheels deliver their command only so well: the estimate's uncertainty grows along
    // each axis with the way driven along it.
    sigma_x_m_ += s_.slip_per_m * std::abs(est_.x_m - before.x_m);
    sigma_y_m_ += s_.slip_per_m * std::abs(est_.y_m - before.y_m);
  }
  if (bumped) {  // pressed on something, it may slide or be pushed any way
    sigma_x_m_ += s_.pressed_sigma_m;
    sigma_y_m_ += s_.pressed_sigma_m;
  }
  sigma_x_m_ = std::min(sigma_x_m_, s_.lost_window_m);
  sigma_y_m_ = std::min(sigma_y_m_, s_.lost_window_m);

  if (scan.timeStamp != last_stamp_) {
    // Where the laser was when it scanned: back along the last command, the yaw interpolated.
    const double age_s = std::clamp(now_s_ - stamp_s, 0.0, dt > 0 ? dt : period_s_);
    const double yaw_s = dt > 0 ? yaw - dyaw * age_s / dt : yaw;
    const Point2 robot_s = blocked ? est_ : along(est_, -cmd_v_ * age_s, yaw_s);
    const Point2 predicted = along(robot_s, s_.laser_forward_m, yaw_s);
    const double w_max = std::max(std::abs(cmd_w_), std::abs(prev_cmd_w_));
    if (!mapped_once_) {
      map_.insert(scan, yaw_s, predicted);
      mapped_once_ = true;
      last_insert_ = predicted;
      last_insert_yaw_ = yaw_s;
    } else if (w_max <= s_.match_max_w_radps) {
      correct(scan, yaw_s, predicted, w_max, bumped);
    }
  }
  last_now_s_ = now_s_;
  last_yaw_ = yaw;
  last_stamp_ = scan.timeStamp;
}

// Matches a scan taken at yaw_s from `predicted` (the laser's place by the commands) and
// corrects the estimate by it; draws it into the map when it fits well.
//
// How far from the prediction a fit may move the estimate (its gate) is what the estimate may be
// off by now, per axis: 2.5 sigma, which grows with the way driven since that axis was last fixed
// (2 % of wheel slip under realistic noise) and while pressed on something. Along a corridor (an
// axis the scan does not sharpen) the best fit is anywhere along it: only the sharp axes say
// where the laser is. Beyond the gate, a fit is a jump: taken only when clearly better than the
// best fit within the gate, and confirmed (confirmJump); else tracking goes on with that best
// fit within the gate, and draws nothing. Measured under realistic noise (CHANGELOG.md, "Performance history"):
// a fixed 5 cm gate refused the true correction once the estimate had drifted along a corridor,
// and the cleaner never corrected again.
void MappingReference::correct(const component::LaserData& scan, double yaw_s, Point2 predicted, double w_max,
                               bool pressed) {
  const auto all = ScanMap::endpoints(scan, yaw_s, s_.match_range_m, s_.match_stride);
  const double gate_x_m = std::max(s_.track_window_m, s_.gate_sigmas * sigma_x_m_);
  const double gate_y_m = std::max(s_.track_window_m, s_.gate_sigmas * sigma_y_m_);
  const double gate_m = std::min(s_.lost_window_m, std::max(gate_x_m, gate_y_m));
  // After a poor match, or while a jump is being confirmed, the widest search.
  const bool searching = poor_matches_ > 0 || jump_count_ > 0;
  ScanMatch m = map_.matchSeen(all, predicted, searching ? s_.lost_window_m : gate_m);
  if (m.points < 10) return;
  const auto sharpOffset = [&](const ScanMatch& fit) {
    return Point2{fit.sharpness_x >= s_.min_sharpness ? fit.laser_m.x_m - predicted.x_m : 0.0,
                  fit.sharpness_y >= s_.min_sharpness ? fit.laser_m.y_m - predicted.y_m : 0.0};
  };
  const auto withinGate = [&](Point2 offset) { return std::abs(offset.x_m) <= gate_x_m && std::abs(offset.y_m) <= gate_y_m; };
  bool jump = !withinGate(sharpOffset(m)), ambiguous = false;
  if (jump) {
    const ScanMatch near = map_.matchSeen(all, predicted, gate_m, true);
    const bool better = m.score >= near.score + s_.jump_margin;
    if (!better) jump_count_ = 0;
    if (!(better && confirmJump(m, predicted, all.size(), w_max, pressed))) {
      if (near.points < 10 || near.score < s_.good_match || !withinGate(sharpOffset(near))) {
        ++poor_matches_;
        return;
      }
      m = near;
      jump = false;
      ambiguous = true;
    }
  } else if (m.score < s_.good_match) {
    ++poor_matches_;
    return;
  }
  if (!jump && !ambiguous) jump_count_ = 0;
  poor_matches_ = 0;
  const bool sharp_x = m.sharpness_x >= s_.min_sharpness, sharp_y = m.sharpness_y >= s_.min_sharpness;
  if (sharp_x) est_.x_m += m.laser_m.x_m - predicted.x_m;
  if (sharp_y) est_.y_m += m.laser_m.y_m - predicted.y_m;
  if (sharp_x) sigma_x_m_ = s_.fixed_sigma_m;
  if (sharp_y) sigma_y_m_ = s_.fixed_sigma_m;
  const bool moved = distance(m.laser_m, last_insert_) >= s_.map_every_m ||
                     std::abs(wrapAngle(yaw_s - last_insert_yaw_)) >= s_.map_every_rad;
  // Enough of the scan on walls the map has (a face seen for the first time is not, and must be
  // drawn from a scan placed by the rest), and no fit elsewhere about as good.
  const bool enough = m.points * 4 >= static_cast<int>(all.size());
  // Each axis fixed by this fit or still known from the last (within insert_sigma_m). A room just
  // entered shows the scan few walls the map has, often along one axis only: drawn only where
  // both were sharp, the room was never drawn, its floor never planned, and the cleaner left it
  // for good (the house under noise, seed 3: half the house unvisited, 32 %).
  const bool held_x = sharp_x || sigma_x_m_ <= s_.insert_sigma_m, held_y = sharp_y || sigma_y_m_ <= s_.insert_sigma_m;
  if (!ambiguous && held_x && held_y && enough && m.score >= s_.map_good_match && w_max <= s_.map_max_w_radps && moved) {
    const Point2 drawn_at{sharp_x ? m.laser_m.x_m : predicted.x_m, sharp_y ? m.laser_m.y_m : predicted.y_m};
    map_.insert(scan, yaw_s, drawn_at);
    last_insert_ = drawn_at;
    last_insert_yaw_ = yaw_s;
  }
}

// A jump is taken only when it explains most of the scan (h2 seed 9: a jump of 0.19 m fitted 27
// of 52 points) and the next scans, driving straight and not pressed on anything (scans from one
// place agree whatever they fit), find the same offset.
bool MappingReference::confirmJump(const ScanMatch& m, Point2 predicted, size_t points, double w_max, bool pressed) {
  if (m.score < s_.map_good_match || w_max > s_.jump_max_w_radps || pressed ||
      m.points < s_.jump_min_explained * static_cast<double>(points)) {
    jump_count_ = 0;
    return false;
  }
  const Point2 offset{m.laser_m.x_m - predicted.x_m, m.laser_m.y_m - predicted.y_m};
  jump_count_ = jump_count_ > 0 && distance(offset, jump_offset_) <= s_.jump_agree_m ? jump_count_ + 1 : 1;
  jump_offset_ = offset;
  return jump_count_ >= s_.jump_confirm_scans;
}

void MappingReference::enterFollow(std::vector<Point2> waypoints) {
  waypoints_ = std::move(waypoints);
  mode_ = Mode::Follow;
  mode_start_s_ = now_s_;
  double length_m = 0;
  Point2 at = est_;
  for (const Point2& p : waypoints_) {
    length_m += distance(at, p);
    at = p;
  }
  deadline_s_ = now_s_ + length_m / s_.follow_min_mps + s_.follow_slack_s;
  progress_at_ = est_;
  progress_s_ = now_s_;
}

void MappingReference::decide() {
  const Point2 p = est_;
  const bool was_hugging = hugging_ && on_lane_;
  hugging_ = false;
  if (unwedge_ && unwedge()) return;
  if (was_hugging && roundTheCorner(p)) return;
  // 0. Too close to a wall (a bump, a push): out to the nearest place the plans may start from.
  if (!coverage_.traversable(p)) {
    const Point2 out = coverage_.nearestTraversable(p, s_.escape_radius_m);
    if (distance(out, p) > 0) {
      on_lane_ = false;
      enterFollow({out});
      return;
    }
  }
  // 1. The boustrophedon: a sidestep, and a lane back beside the last one.
  if (on_lane_ && (sidestep(p) || hugWall(p))) return;
  // 2. A new lane from here.
  if (newLane(p)) return;
  // 3. The nearest unswept floor, then a lane from there.
  on_lane_ = false;
  std::vector<Point2> path = coverage_.pathToUnswept(p, false, true);
  if (path.empty()) path = coverage_.pathToUnswept(p);
  if (path.empty()) path = coverage_.pathToUnswept(p, true);
  if (!path.empty()) {
    enterFollow(std::move(path));
    return;
  }
  // 4. All swept.
  secondPass(p);
}

// A sidestep of lane_spacing_m and a lane back beside the last one, on either side (its own
// first). After the first pass, lanes along walls only: lanes again over the rest found little
// (h2: 1.4 points in its last 300 s), and the strips along walls are most of the floor left.
bool MappingReference::sidestep(Point2 p) {
  if (passes_ > 1) return false;
  for (int side : {side_, -side_}) {
    const Point2 q{p.x_m - side * lane_dy_ * s_.lane_spacing_m, p.y_m + side * lane_dx_ * s_.lane_spacing_m};
    if (!coverage_.traversable(q) || !coverage_.segmentClear(p, q, 0.05)) continue;
    const Lane back = coverage_.lane(q, -lane_dx_, -lane_dy_);
    if (back.unswept_m < s_.min_lane_m) continue;
    side_ = side;
    lane_dx_ = -lane_dx_;
    lane_dy_ = -lane_dy_;
    enterFollow({q, back.end_m});
    return true;
  }
  return false;
}

// All swept: a second pass catches what the first one missed (once: if that finds nothing
// either, the robot is boxed in; it looks round again).
void MappingReference::secondPass(Point2 p) {
  if (now_s_ - last_reset_s_ < s_.escape_radius_m / s_.follow_min_mps + s_.follow_slack_s) {
    escapeByLaser();
    return;
  }
  last_reset_s_ = now_s_;
  coverage_.resetSwept(s_.second_pass_m);
  ++passes_;
  coverage_.sweep(est_);
  std::vector<Point2> path = coverage_.pathToUnswept(p);
  if (!path.empty()) {
    enterFollow(std::move(path));
  } else {
    escapeByLaser();
  }
}

// A new lane from p: one of the ways with about the most unswept floor (seeded).
bool MappingReference::newLane(Point2 p) {
  const std::pair<int, int> ways[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  Lane lanes[4];
  double longest_m = 0;
  for (int k = 0; k < 4; ++k) {
    lanes[k] = coverage_.lane(p, ways[k].first, ways[k].second);
    longest_m = std::max(longest_m, lanes[k].unswept_m);
  }
  if (longest_m < s_.min_lane_m) return false;
  std::vector<int> good;
  for (int k = 0; k < 4; ++k) {
    if (lanes[k].unswept_m >= s_.lane_choice * longest_m) good.push_back(k);
  }
  const int k = good[std::uniform_int_distribution<size_t>(0, good.size() - 1)(rng_)];
  on_lane_ = true;
  lane_dx_ = ways[k].first;
  lane_dy_ = ways[k].second;
  side_ = std::uniform_int_distribution<int>(0, 1)(rng_) ? 1 : -1;
  if (startAtWall(p)) return true;
  if (passes_ == 1) enterFollow({lanes[k].end_m});
  return passes_ == 1;
}

// No lane fits beside the last one: the wall is nearer than lane_spacing_m, and the strip along
// it (up to 0.1 m beside every wall, 11 % of the shipped house) is swept by a lane back along it.
bool MappingReference::hugWall(Point2 p) {
  const auto [q, back] = coverage_.besideWall(p, -side_ * lane_dy_, side_ * lane_dx_, -lane_dx_, -lane_dy_,
                                              s_.lane_spacing_m - map_.cellM(), s_.min_hug_m, s_.hug_strip_m, false);
  if (back.unswept_m < s_.min_lane_m) return false;
  wall_dx_ = -side_ * lane_dy_;
  wall_dy_ = side_ * lane_dx_;
  lane_dx_ = -lane_dx_;
  lane_dy_ = -lane_dy_;
  enterFollow({q, back.end_m});
  hugging_ = true;
  return true;
}

// Bumped here again and again (a gap the disc barely fits, between a box and a wall the map
// draws a centimetre off: g1 seed 4 was wedged for 600 s, 1026 bumps): wedged.
bool MappingReference::wedged(Point2 p) {
  recent_bumps_.emplace_back(now_s_, p);
  while (now_s_ - recent_bumps_.front().first > s_.wedge_window_s) recent_bumps_.pop_front();
  if (static_cast<int>(recent_bumps_.size()) < s_.wedge_bumps) return false;
  for (const auto& bump : recent_bumps_) {
    if (distance(bump.second, p) > s_.wedge_m) return false;
  }
  recent_bumps_.clear();
  wedge_repeats_ = distance(p, last_wedge_m_) < s_.wedge_m ? wedge_repeats_ + 1 : 1;
  last_wedge_m_ = p;
  return true;
}

// Out of a wedge the way it came in, along its own trail (floor it has driven on), and the
// plans keep away from the spot for the rest of the run.
bool MappingReference::unwedge() {
  unwedge_ = false;
  const Point2 wedge = est_;
  std::vector<Point2> way;
  for (auto it = trail_.rbegin(); it != trail_.rend(); ++it) {
    if (distance(*it, wedge) < s_.trail_step_m) continue;
    way.push_back(*it);
    if (distance(*it, wedge) >= s_.unwedge_m) break;
  }
  coverage_.addBump(wedge, std::numeric_limits<double>::infinity());
  if (way.empty()) return false;
  on_lane_ = false;
  // The way out behind: in reverse, not turning round (a disc pressed on both sides may not turn).
  const Point2 out = way.back();
  const double bearing = wrapAngle(std::atan2(out.y_m - wedge.y_m, out.x_m - wedge.x_m) - yaw_);
  if (std::abs(bearing) > M_PI / 2) {
    backoff_v_ = -s_.backoff_mps;
    mode_ = Mode::Backoff;
    mode_start_s_ = now_s_ + distance(out, wedge) / s_.backoff_mps - s_.backoff_s;
    return true;
  }
  escaping_ = true;  // through floor the plans now keep away from
  enterFollow(std::move(way));
  return true;
}

// A lane along a wall ended: on along the next wall, round the corner. At a wall ahead (an inner
// corner), along it away from the last one; where the last wall ended (an outer corner), past its
// end and round it.
bool MappingReference::roundTheCorner(Point2 p) {
  const int dx = lane_dx_, dy = lane_dy_, wx = wall_dx_, wy = wall_dy_;
  const auto [q, inner] = coverage_.besideWall(p, dx, dy, -wx, -wy, s_.corner_reach_m, 0.0, s_.hug_strip_m, true);
  if (inner.unswept_m >= s_.min_lane_m) {
    lane_dx_ = -wx, lane_dy_ = -wy, wall_dx_ = dx, wall_dy_ = dy;
    enterFollow({q, inner.end_m});
    hugging_ = true;
    return true;
  }
  const double hug_m = coverage_.settings().hug_clearance_m;
  const Point2 past{p.x_m + dx * s_.corner_past_m, p.y_m + dy * s_.corner_past_m};
  if (!coverage_.passable(past, hug_m) || !coverage_.segmentClear(p, past, 0.05, hug_m)) return false;
  const Lane outer = coverage_.wallLane(past, wx, wy, -dx, -dy, hug_m, s_.hug_strip_m);
  if (outer.unswept_m < s_.min_lane_m) return false;
  lane_dx_ = wx, lane_dy_ = wy, wall_dx_ = -dx, wall_dy_ = -dy;
  enterFollow({past, outer.end_m});
  hugging_ = true;
  return true;
}

// A new run of lanes (lane_dx_, lane_dy_) from p: if a wall along them is near on one side, the
// first lane goes along it and the next ones away from it (else no lane sweeps beside it).
bool MappingReference::startAtWall(Point2 p) {
  for (int side : {side_, -side_}) {
    const auto [q, first] = coverage_.besideWall(p, side * lane_dy_, -side * lane_dx_, lane_dx_, lane_dy_,
                                                 s_.max_slide_m, s_.min_hug_m, s_.hug_strip_m, true);
    if (first.unswept_m < s_.min_lane_m) continue;
    side_ = side;  // the lanes to come go away from the wall
    wall_dx_ = side * lane_dy_;
    wall_dy_ = -side * lane_dx_;
    enterFollow({q, first.end_m});
    hugging_ = true;
    return true;
  }
  return false;
}

// The map shows no way out (a passage drawn too narrow, a bump marked in a doorway): trust the
// laser instead, and drive a little way into the most open direction it sees now.
void MappingReference::escapeByLaser() {
  const component::LaserData& scan = *scan_;
  const int half = s_.escape_half_beams;
  double best_m = -1, best_rad = 0;
  for (int i = half; i + half < scan.numLaser; ++i) {
    double clear_m = scan.maxRange;
    for (int k = i - half; k <= i + half; ++k) clear_m = std::min<double>(clear_m, scan.values_m[k]);
    if (clear_m > best_m) {
      best_m = clear_m;
      best_rad = scan.angle(i);
    }
  }
  on_lane_ = false;
  const double go_m = std::clamp(best_m - s_.escape_margin_m, 0.0, s_.escape_run_m);
  if (go_m < s_.escape_min_m) {  // walls close all round ahead: back out the way it came
    backoff_v_ = -s_.backoff_mps;
    mode_ = Mode::Backoff;
    mode_start_s_ = now_s_ + s_.backoff_s;  // twice as long as after a bump
    return;
  }
  escaping_ = true;
  enterFollow({along(est_, go_m, yaw_ + best_rad)});
}

void MappingReference::follow(double yaw, double& v, double& w) {
  // Arrived at a waypoint (or beside it: turning round to it would only sweep what is swept), or
  // it is not reachable any more (the map grew a wall on it).
  const auto arrived = [&](Point2 p) {
    const double d = distance(est_, p);
    const double error = std::abs(wrapAngle(std::atan2(p.y_m - est_.y_m, p.x_m - est_.x_m) - yaw));
    return d < s_.arrive_m || (d < s_.beside_m && error > M_PI / 2);
  };
  while (!waypoints_.empty() && arrived(waypoints_.front())) waypoints_.erase(waypoints_.begin());
  const bool blocked = !escaping_ && !waypoints_.empty() &&
                       !(hugging_ ? coverage_.passable(waypoints_.back(), coverage_.settings().hug_clearance_m)
                                  : coverage_.traversable(waypoints_.back()));
  if (distance(est_, progress_at_) > s_.stuck_m) {
    progress_at_ = est_;
    progress_s_ = now_s_;
  }
  const bool stuck = now_s_ - progress_s_ > s_.stuck_s || now_s_ > deadline_s_;
  if (waypoints_.empty() || blocked || stuck) {
    if (stuck && !waypoints_.empty()) coverage_.forget(waypoints_.back());
    escaping_ = false;
    if (blocked || stuck) on_lane_ = false;
    waypoints_.clear();
    decide();
    if (mode_ != Mode::Follow || waypoints_.empty()) return;
  }
  const Point2 target = waypoints_.front();
  const double error = wrapAngle(std::atan2(target.y_m - est_.y_m, target.x_m - est_.x_m) - yaw);
  if (std::abs(error) > s_.turn_in_place_rad) {
    w = std::copysign(std::clamp(s_.turn_gain_per_s * std::abs(error), s_.turn_min_radps, s_.turn_max_radps), error);
    return;
  }
  const double d = distance(est_, target);
  v = std::min(s_.max_speed_mps, s_.approach_min_mps + s_.approach_gain_per_s * d);
  w = std::clamp(s_.turn_gain_per_s * error, -s_.steer_max_radps, s_.steer_max_radps);
}

std::unique_ptr<VacuumAlgorithm> makeMappingReferenceAlgorithm(uint64_t seed) { return std::make_unique<MappingReference>(seed); }

}  // namespace aula::vacuum::mapping
