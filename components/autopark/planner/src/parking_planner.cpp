#include <aula/autopark/footprint_checker.hpp>
#include <aula/autopark/parking_planner.hpp>
#include <aula/geometry/angles.hpp>

#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateSampler.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/datastructures/NearestNeighborsLinear.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <memory>
#include <queue>
#include <tuple>
#include <unordered_set>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace aula::autopark {
namespace {

using Clock = std::chrono::steady_clock;

// One constant-curvature motion of the rear axle: curvature in 1/m (+ left), signed length (+ forward).
struct Move {
  double kappa;
  double length_m;
};

Pose2D integrate(const Pose2D& p, double kappa, double ds) {
  if (std::abs(kappa) < 1e-12) {
    return {p.x_m + ds * std::cos(p.yaw_rad), p.y_m + ds * std::sin(p.yaw_rad), p.yaw_rad};
  }
  const double yaw1 = p.yaw_rad + kappa * ds;
  return {p.x_m + (std::sin(yaw1) - std::sin(p.yaw_rad)) / kappa,
          p.y_m + (std::cos(p.yaw_rad) - std::cos(yaw1)) / kappa, geometry::wrapAngle(yaw1)};
}

int sign(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

// Uniform SE(2) sampler with its own seed, so a plan() call is repeatable without touching
// OMPL's process-wide seed (ompl::RNG::setSeed works once per process only).
class SeededSE2Sampler : public ob::StateSampler {
 public:
  SeededSE2Sampler(const ob::StateSpace* space, unsigned seed) : ob::StateSampler(space) {
    rng_.setLocalSeed(seed);
    bounds_ = space->as<ob::SE2StateSpace>()->getBounds();
  }
  void sampleUniform(ob::State* state) override {
    auto* s = state->as<ob::SE2StateSpace::StateType>();
    s->setXY(rng_.uniformReal(bounds_.low[0], bounds_.high[0]), rng_.uniformReal(bounds_.low[1], bounds_.high[1]));
    s->setYaw(rng_.uniformReal(-M_PI, M_PI));
  }
  void sampleUniformNear(ob::State* state, const ob::State* near, double distance) override {
    auto* s = state->as<ob::SE2StateSpace::StateType>();
    const auto* n = near->as<ob::SE2StateSpace::StateType>();
    s->setXY(std::clamp(n->getX() + rng_.uniformReal(-distance, distance), bounds_.low[0], bounds_.high[0]),
             std::clamp(n->getY() + rng_.uniformReal(-distance, distance), bounds_.low[1], bounds_.high[1]));
    s->setYaw(geometry::wrapAngle(n->getYaw() + rng_.uniformReal(-distance, distance)));
  }
  void sampleGaussian(ob::State* state, const ob::State* mean, double stdDev) override {
    auto* s = state->as<ob::SE2StateSpace::StateType>();
    const auto* m = mean->as<ob::SE2StateSpace::StateType>();
    s->setXY(std::clamp(rng_.gaussian(m->getX(), stdDev), bounds_.low[0], bounds_.high[0]),
             std::clamp(rng_.gaussian(m->getY(), stdDev), bounds_.low[1], bounds_.high[1]));
    s->setYaw(geometry::wrapAngle(rng_.gaussian(m->getYaw(), stdDev)));
  }

 private:
  ob::RealVectorBounds bounds_{2};
};

struct Escape {
  bool ok = false;
  std::vector<Move> moves;  // from the goal outwards
  Pose2D exit_rear;         // rear-axle pose at the end
  double length_m = 0.0;
};

// Escape (un-parking) search from the goal pose: a small deterministic hybrid A* over short
// constant-curvature moves {forward, reverse} x {full left, straight, full right}. A move is driven
// up to move_len_m, or as far as it stays collision-free (with clearance), so short wiggles near the
// curb and the neighbouring cars are possible. Cost = length + cusp penalty; the heuristic is the
// lateral distance still missing to the exit condition (weighted, so the search is greedy).
class EscapeSearch {
 public:
  // clearance_m: inflation used for the escape moves; cell_m / cell_yaw_rad: duplicate detection.
  EscapeSearch(const FootprintChecker& checker, const CarGeometry& car, const ParkingPlanner::Options& opt,
               const Pose2D& goal_rear, Clock::time_point deadline, double clearance_m, double cell_m,
               double cell_yaw_rad)
      : checker_(checker), car_(car), opt_(opt), goal_rear_(goal_rear), goal_centre_(rearAxleToCentre(goal_rear, car)),
        deadline_(deadline), clearance_m_(clearance_m), cell_m_(cell_m), cell_yaw_rad_(cell_yaw_rad) {}

  Escape run() const {
    // Exit to the side(s) where a laterally shifted car fits; the street side first.
    std::vector<int> sides;
    for (int side : {+1, -1}) {
      Pose2D shifted = goal_centre_;
      shifted.x_m += -std::sin(goal_centre_.yaw_rad) * side * opt_.exit_lateral_m;
      shifted.y_m += std::cos(goal_centre_.yaw_rad) * side * opt_.exit_lateral_m;
      if (checker_.freeCentre(shifted, opt_.clearance_m)) sides.push_back(side);
    }
    for (int side : sides) {
      Escape e = search(side);
      if (e.ok) return e;
    }
    return {};
  }

 private:
  struct Node {
    Pose2D pose;  // rear axle
    double g;
    int parent;
    double kappa;
    double length;  // signed, of the move from the parent
  };

  double lateral(const Pose2D& rear) const {
    const Pose2D c = rearAxleToCentre(rear, car_);
    const double dx = c.x_m - goal_centre_.x_m, dy = c.y_m - goal_centre_.y_m;
    return -std::sin(goal_centre_.yaw_rad) * dx + std::cos(goal_centre_.yaw_rad) * dy;
  }

  bool exitReached(const Pose2D& rear, int side) const {
    return side * lateral(rear) >= opt_.exit_lateral_m &&
           checker_.freeCentre(rearAxleToCentre(rear, car_), opt_.clearance_m + opt_.exit_margin_m);
  }

  // A move driven from a node: where it ends, how far it got, whether it left the slot.
  struct Drive {
    Pose2D end;  // rear axle
    double length_m = 0.0;
    bool exited = false;
  };
  using Item = std::tuple<double, int>;  // f, node index (ties: older node first)
  using OpenList = std::priority_queue<Item, std::vector<Item>, std::greater<Item>>;

  Escape search(int side) const {
    const double k = 1.0 / car_.min_turn_radius_m;
    // {forward, reverse} x {towards the exit side, straight, away}: the order breaks ties.
    const std::pair<int, double> motions[] = {{+1, side * k}, {+1, 0.0}, {+1, -side * k},
                                              {-1, side * k}, {-1, 0.0}, {-1, -side * k}};
    std::vector<Node> nodes{{goal_rear_, 0.0, -1, 0.0, 0.0}};
    OpenList open;
    open.push({heuristic(goal_rear_, side), 0});
    std::unordered_set<long long> closed;
    int expansions = 0;
    while (!open.empty()) {
      const int ni = std::get<1>(open.top());
      open.pop();
      const Node cur = nodes[ni];  // a copy: nodes grows below
      if (!closed.insert(cellKey(cur.pose)).second) continue;
      if (budgetSpent(++expansions)) break;
      for (const auto& [dir, kappa] : motions) {
        const Drive d = drive(cur.pose, kappa, dir, side);
        if (d.length_m < opt_.escape_step_m * 0.5) continue;
        const double g = costTo(cur, kappa, dir, d.length_m);
        nodes.push_back({d.end, g, ni, kappa, dir * d.length_m});
        const int child = static_cast<int>(nodes.size()) - 1;
        if (d.exited) return escapeTo(nodes, child);
        if (closed.count(cellKey(d.end))) continue;
        open.push({g + heuristic(d.end, side), child});
      }
    }
    return {};
  }

  // Duplicate-detection cell of a rear-axle pose, relative to the goal.
  long long cellKey(const Pose2D& p) const {
    const double xy_res = cell_m_, yaw_res = cell_yaw_rad_;
    const auto ix = static_cast<long long>(std::floor((p.x_m - goal_rear_.x_m) / xy_res));
    const auto iy = static_cast<long long>(std::floor((p.y_m - goal_rear_.y_m) / xy_res));
    const auto it = static_cast<long long>(std::floor(geometry::wrapAngle(p.yaw_rad) / yaw_res));
    return ((ix + 100000) * 200003LL + (iy + 100000)) * 4099LL + (it + 2048);
  }

  double heuristic(const Pose2D& p, int side) const {
    return opt_.escape_heuristic_weight * std::max(0.0, opt_.exit_lateral_m - side * lateral(p));
  }

  // Out of expansions, or out of time (the clock is read every 64 expansions only, and never when repeatable).
  bool budgetSpent(int expansions) const {
    if (expansions > opt_.escape_max_expansions) return true;
    return !opt_.repeatable && (expansions & 63) == 0 && Clock::now() > deadline_;
  }

  // Drives one move up to escape_move_m, stopping before a collision or once the exit is reached.
  Drive drive(const Pose2D& from, double kappa, int dir, int side) const {
    const double step = opt_.escape_step_m;
    Drive d{from};
    while (d.length_m + step <= opt_.escape_move_m + 1e-9) {
      const Pose2D next = integrate(d.end, kappa, dir * step);
      if (!checker_.freeCentre(rearAxleToCentre(next, car_), clearance_m_)) break;
      d.end = next;
      d.length_m += step;
      if (exitReached(d.end, side)) {
        d.exited = true;
        break;
      }
    }
    return d;
  }

  // Path cost after a move of `length_m` from `from`: length, plus penalties for a cusp and a
  // steering change (none for the first move out of the goal).
  double costTo(const Node& from, double kappa, int dir, double length_m) const {
    double g = from.g + length_m;
    if (from.parent >= 0 && sign(from.length) != dir) g += opt_.escape_cusp_cost_m;
    if (from.parent >= 0 && kappa != from.kappa) g += opt_.escape_steer_change_cost_m;
    return g;
  }

  // The moves from the goal to node `last`, which reached the exit.
  static Escape escapeTo(const std::vector<Node>& nodes, int last) {
    Escape e;
    for (int n = last; nodes[n].parent >= 0; n = nodes[n].parent) {
      e.moves.push_back({nodes[n].kappa, nodes[n].length});
      e.length_m += std::abs(nodes[n].length);
    }
    std::reverse(e.moves.begin(), e.moves.end());
    e.exit_rear = nodes[last].pose;
    e.ok = true;
    return e;
  }

  const FootprintChecker& checker_;
  const CarGeometry& car_;
  const ParkingPlanner::Options& opt_;
  Pose2D goal_rear_;
  Pose2D goal_centre_;
  Clock::time_point deadline_;
  double clearance_m_, cell_m_, cell_yaw_rad_;
};

void appendReedsShepp(const ob::ReedsSheppStateSpace& space, double radius, const ob::State* a,
                      const ob::State* b, std::vector<Move>& moves) {
  const auto path = space.reedsShepp(a, b);
  for (int i = 0; i < 5; ++i) {
    const double len = path.length_[i] * radius;
    if (path.type_[i] == ob::ReedsSheppStateSpace::RS_NOP || std::abs(len) < 1e-9) continue;
    double kappa = 0.0;
    if (path.type_[i] == ob::ReedsSheppStateSpace::RS_LEFT) kappa = 1.0 / radius;
    if (path.type_[i] == ob::ReedsSheppStateSpace::RS_RIGHT) kappa = -1.0 / radius;
    moves.push_back({kappa, len});
  }
}

Pose2D toPose(const ob::State* st) {
  const auto* s = st->as<ob::SE2StateSpace::StateType>();
  return {s->getX(), s->getY(), s->getYaw()};
}

void setState(ob::State* st, const Pose2D& p) {
  auto* s = st->as<ob::SE2StateSpace::StateType>();
  s->setXY(p.x_m, p.y_m);
  s->setYaw(geometry::wrapAngle(p.yaw_rad));
}

// The Reeds-Shepp space over the grid's extent, its states checked by the footprint checker at
// motion_check_step_m, sampled with the plan's own seed.
ob::SpaceInformationPtr reedsSheppSpace(const OccupancyGrid& grid, const FootprintChecker& checker, double radius,
                                        const ParkingPlanner::Options& opt) {
  auto space = std::make_shared<ob::ReedsSheppStateSpace>(radius);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, grid.minX_m());
  bounds.setHigh(0, grid.maxX_m());
  bounds.setLow(1, grid.minY_m());
  bounds.setHigh(1, grid.maxY_m());
  space->setBounds(bounds);
  const unsigned seed = opt.seed;
  space->setStateSamplerAllocator(
      [seed](const ob::StateSpace* s) { return std::make_shared<SeededSE2Sampler>(s, seed); });

  auto si = std::make_shared<ob::SpaceInformation>(space);
  const ob::SpaceInformation* sip = si.get();
  si->setStateValidityChecker([sip, &checker](const ob::State* st) {
    // Reeds-Shepp motions can leave the bounds; Debian's OMPL asserts on such states elsewhere.
    if (!sip->satisfiesBounds(st)) return false;
    return checker.freeRearAxle(toPose(st));
  });
  si->setStateValidityCheckingResolution(opt.motion_check_step_m / space->getMaximumExtent());
  si->setup();
  return si;
}

// Greedy shortcut: from each kept state jump to the farthest state reachable by a valid
// Reeds-Shepp motion. Deterministic (OMPL's PathSimplifier draws from its own unseeded RNG).
std::vector<const ob::State*> shortcut(const ob::SpaceInformation& si, og::PathGeometric& path) {
  const auto& ps = path.getStates();
  std::vector<const ob::State*> kept{ps.front()};
  size_t i = 0;
  while (i + 1 < ps.size()) {
    size_t j = ps.size() - 1;
    for (; j > i + 1; --j) {
      if (si.checkMotion(ps[i], ps[j])) break;
    }
    kept.push_back(ps[j]);
    i = j;
  }
  return kept;
}

// When RRTConnect stops: after rrt_max_checks questions when repeatable (no clock), else after time_left_s.
ob::PlannerTerminationCondition stopCondition(const ParkingPlanner::Options& opt, double time_left_s) {
  if (!opt.repeatable) return ob::timedPlannerTerminationCondition(std::max(0.0, time_left_s));
  return ob::PlannerTerminationCondition([asked = 0, most = opt.rrt_max_checks]() mutable { return ++asked > most; });
}

// OMPL: Reeds-Shepp RRTConnect from start to goal (rear-axle poses), then a deterministic greedy
// shortcut. Appends the motions to `moves`.
bool planReedsShepp(const OccupancyGrid& grid, const FootprintChecker& checker, const CarGeometry& car,
                    const ParkingPlanner::Options& opt, const Pose2D& start, const Pose2D& goal,
                    double time_left_s, std::vector<Move>& moves, std::string& message) {
  const double radius = car.min_turn_radius_m;
  const ob::SpaceInformationPtr si = reedsSheppSpace(grid, checker, radius, opt);
  const auto& space = *si->getStateSpace()->as<ob::ReedsSheppStateSpace>();
  ob::ScopedState<> s(si->getStateSpace()), g(si->getStateSpace());
  setState(s.get(), start);
  setState(g.get(), goal);

  og::PathGeometric path(si);
  if (si->checkMotion(s.get(), g.get())) {
    path.append(s.get());
    path.append(g.get());
  } else {
    auto pdef = std::make_shared<ob::ProblemDefinition>(si);
    pdef->setStartAndGoalStates(s, g, 1e-6);
    auto planner = std::make_shared<og::RRTConnect>(si);
    if (opt.deterministic_nn) planner->setNearestNeighbors<ompl::NearestNeighborsLinear>();  // GNAT draws randoms
    if (opt.range_m > 0) planner->setRange(opt.range_m);
    planner->setProblemDefinition(pdef);
    const ob::PlannerStatus status = planner->solve(stopCondition(opt, time_left_s));
    if (status != ob::PlannerStatus::EXACT_SOLUTION) {
      message = std::string("RRTConnect: ") + status.asString();
      return false;
    }
    path = *pdef->getSolutionPath()->as<og::PathGeometric>();
  }
  const std::vector<const ob::State*> kept = shortcut(*si, path);
  for (size_t k = 0; k + 1 < kept.size(); ++k) appendReedsShepp(space, radius, kept[k], kept[k + 1], moves);
  return true;
}

// Why planning cannot start from `start` to `goal` (rear axle), or "" when it can.
std::string endpointProblem(const FootprintChecker& checker, const ParkingPlanner::Options& opt, const Pose2D& start,
                            const Pose2D& goal, const Pose2D& goal_centre) {
  if (!checker.freeRearAxle(start)) return "start pose in collision (with clearance)";
  // The escape may lower the clearance in the slot, so a goal that fits only that way is fine.
  const double goal_clearance = opt.use_escape ? std::min(opt.clearance_m, opt.min_slot_clearance_m) : opt.clearance_m;
  if (!checker.freeRearAxle(goal) && !checker.freeCentre(goal_centre, goal_clearance)) {
    return "goal pose in collision (with clearance)";
  }
  return "";
}

// The unsolved result: why, and no poses (the figures gathered so far stay).
PlannedPath unsolved(PlannedPath out, const std::string& why, double planning_time_s) {
  out.solved = false;
  out.poses.clear();
  out.direction.clear();
  out.curvature_per_m.clear();
  out.message = why;
  out.planning_time_s = planning_time_s;
  return out;
}

// Escape passes: full clearance with coarse then fine duplicate cells; then the in-slot clearance
// is lowered step by step down to min_slot_clearance_m (tight slots, see docs/planner.md).
// `clearance_m` is set to the clearance of the escape found (left alone if none is).
Escape escapeFromSlot(const FootprintChecker& checker, const CarGeometry& car, const ParkingPlanner::Options& opt,
                      const Pose2D& goal_rear, const Pose2D& goal_centre, Clock::time_point deadline,
                      double& clearance_m) {
  Escape escape;
  for (double clearance = opt.clearance_m; !escape.ok && clearance >= opt.min_slot_clearance_m - 1e-9;
       clearance -= opt.slot_clearance_step_m) {
    if (!checker.freeCentre(goal_centre, clearance)) break;
    for (const double scale : {2.0, 1.0}) {
      escape = EscapeSearch(checker, car, opt, goal_rear, deadline, clearance, scale * opt.escape_cell_m,
                            scale * opt.escape_cell_yaw_rad).run();
      if (escape.ok) {
        clearance_m = clearance;
        break;
      }
    }
    if (opt.slot_clearance_step_m <= 0) break;
  }
  return escape;
}

// The escape driven backwards: from the exit into the slot.
std::vector<Move> reversed(const Escape& escape) {
  std::vector<Move> moves;
  for (auto it = escape.moves.rbegin(); it != escape.moves.rend(); ++it) moves.push_back({it->kappa, -it->length_m});
  return moves;
}

// Consecutive motions of the same curvature and direction, merged into one.
std::vector<Move> merged(const std::vector<Move>& moves) {
  std::vector<Move> out;
  for (const Move& m : moves) {
    if (!out.empty() && std::abs(out.back().kappa - m.kappa) < 1e-12 && sign(out.back().length_m) == sign(m.length_m)) {
      out.back().length_m += m.length_m;
    } else {
      out.push_back(m);
    }
  }
  return out;
}

// Dense sampling of the rear axle along `moves` from `start_rear`, output as centre poses (with
// direction, curvature, cusps and length) in `out`.
void sampleDensely(const std::vector<Move>& moves, const Pose2D& start_rear, const Pose2D& start_centre,
                   const CarGeometry& car, double output_step_m, PlannedPath& out) {
  Pose2D p = start_rear;
  out.poses.push_back(start_centre);
  out.direction.push_back(moves.empty() ? 1 : sign(moves.front().length_m));
  out.curvature_per_m.push_back(moves.empty() ? 0.0 : moves.front().kappa);
  for (size_t k = 0; k < moves.size(); ++k) {
    const Move& m = moves[k];
    if (k > 0 && sign(m.length_m) != sign(moves[k - 1].length_m)) ++out.cusps;
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(m.length_m) / output_step_m)));
    for (int j = 1; j <= n; ++j) {
      const Pose2D q = integrate(p, m.kappa, m.length_m * j / n);
      out.poses.push_back(rearAxleToCentre(q, car));
      out.direction.push_back(sign(m.length_m));
      out.curvature_per_m.push_back(m.kappa);
    }
    p = integrate(p, m.kappa, m.length_m);
    out.length_m += std::abs(m.length_m);
  }
}

// Why the path `out` (rear axle ending at `goal`) cannot be used, or "" when it can. Motions were checked at
// motion_check_step_m / escape_step_m; samples in between may graze by a few mm, hence the
// half-clearance tolerance here.
std::string denseProblem(const PlannedPath& out, const FootprintChecker& checker, const CarGeometry& car,
                         const ParkingPlanner::Options& opt, const Pose2D& goal) {
  for (const Pose2D& c : out.poses) {
    if (!checker.freeCentre(c, 0.5 * std::min(opt.clearance_m, out.escape_clearance_m))) {
      return "dense path check failed";
    }
  }
  const Pose2D end = centreToRearAxle(out.poses.back(), car);
  if (std::hypot(end.x_m - goal.x_m, end.y_m - goal.y_m) > 1e-3 ||
      std::abs(geometry::wrapAngle(end.yaw_rad - goal.yaw_rad)) > 1e-3) {
    return "internal: path does not end at the goal";
  }
  return "";
}

}  // namespace

ParkingPlanner::ParkingPlanner(CarGeometry car, Options options) : car_(car), options_(options) {}

PlannedPath ParkingPlanner::plan(const OccupancyGrid& grid, const Pose2D& start_centre,
                                 const Pose2D& goal_centre) const {
  const auto t0 = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  if (options_.quiet) ompl::msg::setLogLevel(ompl::msg::LOG_WARN);

  PlannedPath out;
  if (grid.width() <= 0 || grid.height() <= 0) return unsolved(out, "empty grid", elapsed());
  const FootprintChecker checker(grid, car_, options_.clearance_m);
  const Pose2D start = centreToRearAxle(start_centre, car_);
  const Pose2D goal = centreToRearAxle(goal_centre, car_);
  std::string why = endpointProblem(checker, options_, start, goal, goal_centre);
  if (!why.empty()) return unsolved(out, why, elapsed());
  out.escape_clearance_m = options_.clearance_m;

  // With the escape, OMPL plans only to where the escape leaves the slot; the escape, reversed, ends the path.
  Pose2D ompl_goal = goal;
  std::vector<Move> tail;
  if (options_.use_escape) {
    const auto deadline = t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options_.time_limit_s));
    const Escape escape = escapeFromSlot(checker, car_, options_, goal, goal_centre, deadline, out.escape_clearance_m);
    if (!escape.ok) return unsolved(out, "no escape manoeuvre out of the slot", elapsed());
    ompl_goal = escape.exit_rear;
    tail = reversed(escape);
    out.escape_moves = static_cast<int>(escape.moves.size());
    out.escape_time_s = elapsed();
  }
  std::vector<Move> moves;
  if (!planReedsShepp(grid, checker, car_, options_, start, ompl_goal, options_.time_limit_s - elapsed(), moves, why)) {
    return unsolved(out, why, elapsed());
  }
  moves.insert(moves.end(), tail.begin(), tail.end());

  sampleDensely(merged(moves), start, start_centre, car_, options_.output_step_m, out);
  why = denseProblem(out, checker, car_, options_, goal);
  if (!why.empty()) return unsolved(out, why, elapsed());
  out.poses.back() = goal_centre;
  out.solved = true;
  out.planning_time_s = elapsed();
  return out;
}

bool MappedStreet::contains(const geometry::OrientedBox& box) const {
  for (const auto& p : box.corners()) {
    if (p.x() < min_x_m || p.x() > max_x_m || p.y() < min_y_m || p.y() > max_y_m) return false;
  }
  return true;
}

std::string pathLeavesStreet(const PlannedPath& path, const CarGeometry& car, const MappedStreet& street) {
  for (const Pose2D& p : path.poses) {
    if (street.contains(footprint(p, car, 0.0))) continue;
    char why[200];
    std::snprintf(why, sizeof why, "leaves the mapped street at x %.2f y %.2f (mapped x %.2f to %.2f, y %.2f to %.2f)", p.x_m,
                  p.y_m, street.min_x_m, street.max_x_m, street.min_y_m, street.max_y_m);
    return why;
  }
  return "";
}

}  // namespace aula::autopark
