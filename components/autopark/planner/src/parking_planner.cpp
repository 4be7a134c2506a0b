#include <aula/autopark/footprint_checker.hpp>
#include <aula/autopark/parking_planner.hpp>

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
          p.y_m + (std::cos(p.yaw_rad) - std::cos(yaw1)) / kappa, wrapAngle(yaw1)};
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
    s->setYaw(wrapAngle(n->getYaw() + rng_.uniformReal(-distance, distance)));
  }
  void sampleGaussian(ob::State* state, const ob::State* mean, double stdDev) override {
    auto* s = state->as<ob::SE2StateSpace::StateType>();
    const auto* m = mean->as<ob::SE2StateSpace::StateType>();
    s->setXY(std::clamp(rng_.gaussian(m->getX(), stdDev), bounds_.low[0], bounds_.high[0]),
             std::clamp(rng_.gaussian(m->getY(), stdDev), bounds_.low[1], bounds_.high[1]));
    s->setYaw(wrapAngle(rng_.gaussian(m->getYaw(), stdDev)));
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

  Escape search(int side) const {
    const double k = 1.0 / car_.min_turn_radius_m;
    const double step = opt_.escape_step_m;
    const double move_len = opt_.escape_move_m;
    const double xy_res = cell_m_, yaw_res = cell_yaw_rad_;
    auto key = [&](const Pose2D& p) {
      const auto ix = static_cast<long long>(std::floor((p.x_m - goal_rear_.x_m) / xy_res));
      const auto iy = static_cast<long long>(std::floor((p.y_m - goal_rear_.y_m) / xy_res));
      const auto it = static_cast<long long>(std::floor(wrapAngle(p.yaw_rad) / yaw_res));
      return ((ix + 100000) * 200003LL + (iy + 100000)) * 4099LL + (it + 2048);
    };
    auto h = [&](const Pose2D& p) { return opt_.escape_heuristic_weight * std::max(0.0, opt_.exit_lateral_m - side * lateral(p)); };

    std::vector<Node> nodes{{goal_rear_, 0.0, -1, 0.0, 0.0}};
    using Item = std::tuple<double, int>;  // f, node index (ties: older node first)
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
    open.push({h(goal_rear_), 0});
    std::unordered_set<long long> closed;
    Escape e;
    int expansions = 0;
    while (!open.empty()) {
      const int ni = std::get<1>(open.top());
      open.pop();
      const Node cur = nodes[ni];
      if (!closed.insert(key(cur.pose)).second) continue;
      if (++expansions > opt_.escape_max_expansions || ((expansions & 63) == 0 && Clock::now() > deadline_)) break;
      for (int dir : {+1, -1}) {
        for (double kappa : {side * k, 0.0, -side * k}) {
          Pose2D p = cur.pose;
          double len = 0.0;
          bool exited = false;
          while (len + step <= move_len + 1e-9) {
            const Pose2D next = integrate(p, kappa, dir * step);
            if (!checker_.freeCentre(rearAxleToCentre(next, car_), clearance_m_)) break;
            p = next;
            len += step;
            if (exitReached(p, side)) {
              exited = true;
              break;
            }
          }
          if (len < step * 0.5) continue;
          double g = cur.g + len;
          if (cur.parent >= 0 && sign(cur.length) != dir) g += opt_.escape_cusp_cost_m;
          if (cur.parent >= 0 && kappa != cur.kappa) g += opt_.escape_steer_change_cost_m;
          nodes.push_back({p, g, ni, kappa, dir * len});
          const int child = static_cast<int>(nodes.size()) - 1;
          if (exited) {
            for (int n = child; nodes[n].parent >= 0; n = nodes[n].parent) {
              e.moves.push_back({nodes[n].kappa, nodes[n].length});
              e.length_m += std::abs(nodes[n].length);
            }
            std::reverse(e.moves.begin(), e.moves.end());
            e.exit_rear = p;
            e.ok = true;
            return e;
          }
          if (closed.count(key(p))) continue;
          open.push({g + h(p), child});
        }
      }
    }
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
  s->setYaw(wrapAngle(p.yaw_rad));
}

// OMPL: Reeds-Shepp RRTConnect from start to goal (rear-axle poses), then a deterministic greedy
// shortcut. Appends the motions to `moves`.
bool planReedsShepp(const OccupancyGrid& grid, const FootprintChecker& checker, const CarGeometry& car,
                    const ParkingPlanner::Options& opt, const Pose2D& start, const Pose2D& goal,
                    double time_left_s, std::vector<Move>& moves, std::string& message) {
  const double radius = car.min_turn_radius_m;
  auto space = std::make_shared<ob::ReedsSheppStateSpace>(radius);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, grid.originX_m());
  bounds.setHigh(0, grid.originX_m() + grid.width() * grid.resolution_m());
  bounds.setLow(1, grid.originY_m());
  bounds.setHigh(1, grid.originY_m() + grid.height() * grid.resolution_m());
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

  ob::ScopedState<> s(space), g(space);
  setState(s.get(), start);
  setState(g.get(), goal);

  std::vector<ob::State*> states;  // owned by `path` or the scoped states
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
    const ob::PlannerStatus status = planner->solve(ob::timedPlannerTerminationCondition(std::max(0.0, time_left_s)));
    if (status != ob::PlannerStatus::EXACT_SOLUTION) {
      message = std::string("RRTConnect: ") + status.asString();
      return false;
    }
    path = *pdef->getSolutionPath()->as<og::PathGeometric>();
  }

  // Greedy shortcut: from each kept state jump to the farthest state reachable by a valid
  // Reeds-Shepp motion. Deterministic (OMPL's PathSimplifier draws from its own unseeded RNG).
  const auto& ps = path.getStates();
  std::vector<const ob::State*> kept{ps.front()};
  size_t i = 0;
  while (i + 1 < ps.size()) {
    size_t j = ps.size() - 1;
    for (; j > i + 1; --j) {
      if (si->checkMotion(ps[i], ps[j])) break;
    }
    kept.push_back(ps[j]);
    i = j;
  }
  for (size_t k = 0; k + 1 < kept.size(); ++k) appendReedsShepp(*space, radius, kept[k], kept[k + 1], moves);
  return true;
}

}  // namespace

ParkingPlanner::ParkingPlanner(CarGeometry car, Options options) : car_(car), options_(options) {}

PlannedPath ParkingPlanner::plan(const OccupancyGrid& grid, const Pose2D& start_centre,
                                 const Pose2D& goal_centre) const {
  const auto t0 = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  if (options_.quiet) ompl::msg::setLogLevel(ompl::msg::LOG_WARN);

  PlannedPath out;
  auto finish = [&](const std::string& why) {
    out.solved = false;
    out.poses.clear();
    out.direction.clear();
    out.curvature_per_m.clear();
    out.message = why;
    out.planning_time_s = elapsed();
    return out;
  };
  if (grid.width() <= 0 || grid.height() <= 0) return finish("empty grid");
  const FootprintChecker checker(grid, car_, options_.clearance_m);
  const Pose2D start = centreToRearAxle(start_centre, car_);
  const Pose2D goal = centreToRearAxle(goal_centre, car_);
  if (!checker.freeRearAxle(start)) return finish("start pose in collision (with clearance)");
  const double goal_clearance = options_.use_escape ? std::min(options_.clearance_m, options_.min_slot_clearance_m) : options_.clearance_m;
  if (!checker.freeRearAxle(goal) && !checker.freeCentre(goal_centre, goal_clearance)) {
    return finish("goal pose in collision (with clearance)");
  }
  out.escape_clearance_m = options_.clearance_m;

  std::vector<Move> moves;
  Pose2D ompl_goal = goal;
  std::vector<Move> tail;
  if (options_.use_escape) {
    const auto deadline = t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options_.time_limit_s));
    // Passes: full clearance with coarse then fine duplicate cells; then the in-slot clearance is
    // lowered step by step down to min_slot_clearance_m (tight slots, see docs/planner.md).
    Escape escape;
    for (double clearance = options_.clearance_m; !escape.ok && clearance >= options_.min_slot_clearance_m - 1e-9;
         clearance -= options_.slot_clearance_step_m) {
      if (!checker.freeCentre(goal_centre, clearance)) break;
      for (const double scale : {2.0, 1.0}) {
        escape = EscapeSearch(checker, car_, options_, goal, deadline, clearance, scale * options_.escape_cell_m,
                              scale * options_.escape_cell_yaw_rad).run();
        if (escape.ok) {
          out.escape_clearance_m = clearance;
          break;
        }
      }
      if (options_.slot_clearance_step_m <= 0) break;
    }
    if (!escape.ok) return finish("no escape manoeuvre out of the slot");
    ompl_goal = escape.exit_rear;
    for (auto it = escape.moves.rbegin(); it != escape.moves.rend(); ++it) tail.push_back({it->kappa, -it->length_m});
    out.escape_moves = static_cast<int>(escape.moves.size());
    out.escape_time_s = elapsed();
  }
  std::string why;
  if (!planReedsShepp(grid, checker, car_, options_, start, ompl_goal, options_.time_limit_s - elapsed(), moves, why)) {
    return finish(why);
  }
  moves.insert(moves.end(), tail.begin(), tail.end());

  // Merge consecutive motions of the same curvature and direction.
  std::vector<Move> merged;
  for (const Move& m : moves) {
    if (!merged.empty() && std::abs(merged.back().kappa - m.kappa) < 1e-12 &&
        sign(merged.back().length_m) == sign(m.length_m)) {
      merged.back().length_m += m.length_m;
    } else {
      merged.push_back(m);
    }
  }

  // Dense sampling of the rear axle, output as centre poses.
  Pose2D p = start;
  out.poses.push_back(start_centre);
  out.direction.push_back(merged.empty() ? 1 : sign(merged.front().length_m));
  out.curvature_per_m.push_back(merged.empty() ? 0.0 : merged.front().kappa);
  for (size_t k = 0; k < merged.size(); ++k) {
    const Move& m = merged[k];
    if (k > 0 && sign(m.length_m) != sign(merged[k - 1].length_m)) ++out.cusps;
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(m.length_m) / options_.output_step_m)));
    for (int j = 1; j <= n; ++j) {
      const Pose2D q = integrate(p, m.kappa, m.length_m * j / n);
      out.poses.push_back(rearAxleToCentre(q, car_));
      out.direction.push_back(sign(m.length_m));
      out.curvature_per_m.push_back(m.kappa);
    }
    p = integrate(p, m.kappa, m.length_m);
    out.length_m += std::abs(m.length_m);
  }
  // Verify the dense path (motions were checked at motion_check_step_m / escape_step_m; samples in
  // between may graze by a few mm, hence the half-clearance tolerance here).
  for (const Pose2D& c : out.poses) {
    if (!checker.freeCentre(c, 0.5 * std::min(options_.clearance_m, out.escape_clearance_m))) {
      return finish("dense path check failed");
    }
  }
  const Pose2D end = centreToRearAxle(out.poses.back(), car_);
  if (std::hypot(end.x_m - goal.x_m, end.y_m - goal.y_m) > 1e-3 ||
      std::abs(wrapAngle(end.yaw_rad - goal.yaw_rad)) > 1e-3) {
    return finish("internal: path does not end at the goal");
  }
  out.poses.back() = goal_centre;
  out.solved = true;
  out.planning_time_s = elapsed();
  return out;
}

}  // namespace aula::autopark
