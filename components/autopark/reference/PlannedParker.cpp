// Autopark reference solution, planned (Autopark.Algorithm = planner):
//   TURN     a start facing the wrong way: turn round first (TurnRound, as the reactive reference).
//   SEARCH   drive down the street (StreetSearch) while every laser echo goes into an occupancy
//            grid of the street, 0.05 m cells; the SlotDetector finds the free slot.
//   SURVEY   drive on until the car ahead of the slot is well in view, then stop.
//   PLAN     ParkingPlanner (OMPL Reeds-Shepp RRTConnect to a searched escape pose; see
//            docs/planner.md) from the stopped pose to the slot's centre, on the lasers' grid; its
//            budgets are counts, never the wall clock, so a loaded machine plans the same path.
//   TRACK    PathTracker drives the path, forward and reverse moves split at the cusps. A car that
//            drifts off the path stops and plans again from where it is.
//   PARKED   stop.
//   FAILED   stop and say why (the API's status and the log): no slot on the whole street, no plan
//            after the replans, or the car outside the street the lasers mapped. It never drives
//            on blind: the planning grid is only what the lasers mapped, and a plan that would
//            leave it is refused.
// The car model comes from the world through the API: its turning radius and the point it turns
// about (rear axle for a car-like car, centre for one that turns in place).
#include <aula/geometry/angles.hpp>
#include <aula/autopark/references.hpp>
#include <aula/autopark/autopark_algorithm.hpp>
#include <aula/autopark/occupancy_grid.hpp>
#include <aula/autopark/parking_planner.hpp>
#include <aula/autopark/path_tracker.hpp>
#include <aula/autopark/reference_steps.hpp>
#include <aula/autopark/street_search.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

namespace aula::autopark {
namespace {

class PlannedParker : public AutoparkAlgorithm {
 public:
  explicit PlannedParker(uint64_t seed) : seed_(static_cast<unsigned>(seed % 1000003 + 1)) {}

  // One control period: read the pose, map what the lasers see while searching, run the present
  // phase, say when the phase changes, drive.
  void execute(AutoparkApi& api) override {
    t_ += api.period_s;
    if (!sensorsReady(api)) return;
    const Pose2D pose{api.pose3d.getX(), api.pose3d.getY(), api.pose3d.getYaw()};
    if (!search_) start(api, pose);
    if (mode_ == Mode::Turn || mode_ == Mode::Search || mode_ == Mode::Survey) mapScans(api, pose);
    PathTracker::Command command;
    step(api, pose, command);
    logPhase(api, pose);
    api.motors.sendV(command.v_mps);
    api.motors.sendW(command.w_radps);
  }

 private:
  enum class Mode { Turn, Search, Survey, Plan, Track, Settle, Parked, Failed };
  static const char* name(Mode m) {
    static const char* const names[] = {"TURN", "SEARCH", "SURVEY", "PLAN", "TRACK", "SETTLE", "PARKED", "FAILED"};
    return names[static_cast<int>(m)];
  }
  static constexpr double kSlotMarginM = 0.6;     // shortest slot: the car plus this
  static constexpr double kCurbClearanceM = 0.3;  // the parked car's side from the curb
  static constexpr double kSurveyPastM = 2.0;     // drive this far past the slot's end before planning
  static constexpr double kSurveyMps = 1.0;
  static constexpr double kSurveyStopM = 2.0;     // ... unless something is this close ahead
  static constexpr double kSettleS = 0.5;         // standing still before planning
  static constexpr double kReplanErrorM = 0.4;    // off the path by this much: stop and plan again
  static constexpr int kMaxReplans = 3;
  static constexpr double kGridResolutionM = 0.025;
  static constexpr double kGridHalfLengthM = 70, kGridHalfWidthM = 15;
  static constexpr double kOffStreetToleranceM = 0.5;  // tracking: the body this far outside the mapped street stops the car

  // The present phase's command for this period (and the next phase, when it ends).
  void step(AutoparkApi& api, const Pose2D& pose, PathTracker::Command& c) {
    switch (mode_) {
      case Mode::Turn:
        if (turn_.step(api, pose.yaw_rad, c.v_mps, c.w_radps)) mode_ = Mode::Search;
        break;
      case Mode::Search:
        searchStep(api, pose, c);
        break;
      case Mode::Survey:
        surveyStep(api, pose, c);
        break;
      case Mode::Plan:
        plan(api, pose);
        break;
      case Mode::Track:
        trackStep(api, pose, c);
        break;
      case Mode::Settle:
        if ((still_s_ += api.period_s) >= kSettleS) mode_ = Mode::Plan;
        break;
      case Mode::Parked:
      case Mode::Failed:
        break;
    }
  }

  // SEARCH: drive down the street (StreetSearch) until the detector reports a slot.
  void searchStep(AutoparkApi& api, const Pose2D& pose, PathTracker::Command& c) {
    if (search_->exhausted()) {
      fail(api, "no free slot of %.1f m or more on the street", search_->detector().minLengthM());
      return;
    }
    const StreetSearch::Step found = search_->search(api, pose.x_m, pose.y_m, pose.yaw_rad);
    c.v_mps = found.v_mps;
    c.w_radps = found.w_radps;
    if (found.slot) {
      slot_ = *found.slot;
      direction_ = search_->direction();
      mode_ = Mode::Survey;
    }
  }

  // SURVEY: the slot's far end must be mapped before planning: drive on (in the search direction)
  // until the car is past it, then stop for a moment so the planner starts from rest.
  void surveyStep(AutoparkApi& api, const Pose2D& pose, PathTracker::Command& c) {
    search_->addScans(api, pose.x_m, pose.y_m, pose.yaw_rad);
    if (auto slot = search_->detector().slot(slot_.centreXM())) slot_ = *slot;
    const double past = pastSlotM(slot_, direction_, pose.x_m);
    // Never into something: whatever is ahead in the direction of travel ends the survey.
    const double clear = rangeAhead(direction_ > 0 ? api.laser1.getLaserData() : api.laser2.getLaserData(), 0.3);
    if (past < kSurveyPastM && clear > kSurveyStopM) {
      c.v_mps = direction_ > 0 ? kSurveyMps : -kSurveyMps;
      c.w_radps = search_->keepLane(c.v_mps, pose.y_m, pose.yaw_rad);
    } else if ((still_s_ += api.period_s) >= kSettleS) {
      mode_ = Mode::Plan;
    }
  }

  // TRACK: follow the path; off the mapped street, stop; drifted off the path, stop and plan again.
  void trackStep(AutoparkApi& api, const Pose2D& pose, PathTracker::Command& c) {
    if (!mapped_.contains(footprint(pose, car_, -kOffStreetToleranceM))) {
      fail(api, "off the mapped street at x %.2f y %.2f", pose.x_m, pose.y_m);
      return;
    }
    c = tracker_->update(pose);
    if (c.done) {
      mode_ = Mode::Parked;
    } else if (std::abs(tracker_->lateralError_m()) > kReplanErrorM && replans_ < kMaxReplans) {
      ++replans_;
      c.v_mps = c.w_radps = 0;
      still_s_ = 0;
      mode_ = Mode::Settle;
    }
  }

  // One line per phase, so a student can follow the run in the terminal.
  void logPhase(const AutoparkApi& api, const Pose2D& pose) {
    if (mode_ == logged_mode_) return;
    std::fprintf(stderr, "planner [%.2f s]: %s at x %.2f y %.2f yaw %.1f deg%s%s\n", t_, name(mode_), pose.x_m, pose.y_m,
                 geometry::headingDeg(pose.yaw_rad), mode_ == Mode::Failed ? ": " : "",
                 mode_ == Mode::Failed ? api.status.c_str() : "");
    logged_mode_ = mode_;
  }

  // Stop for good and say why (printf-style).
  template <class... Args>
  void fail(AutoparkApi& api, const char* format, Args... args) {
    char why[200];
    std::snprintf(why, sizeof why, format, args...);
    api.status = why;
    mode_ = Mode::Failed;
  }

  void start(const AutoparkApi& api, const Pose2D& pose) {
    car_.length_m = api.car_length_m;
    car_.width_m = api.car_width_m;
    car_.rear_axle_from_centre_m = -api.turn_centre_x_m;
    car_.min_turn_radius_m = std::max(api.min_turn_radius_m, 5.0);
    StreetSearch::Settings settings;
    settings.min_slot_length_m = api.car_length_m + kSlotMarginM;
    settings.turn_radius_m = car_.min_turn_radius_m;
    search_.emplace(api, settings);
    // The map is anchored where the car starts; the street runs along x.
    const auto cells = [](double m) { return static_cast<int>(std::lround(2 * m / kGridResolutionM)); };
    map_ = OccupancyGrid(pose.x_m - kGridHalfLengthM, pose.y_m - kGridHalfWidthM, kGridResolutionM,
                         cells(kGridHalfLengthM), cells(kGridHalfWidthM));
    mapped_ = {pose.x_m, pose.x_m, pose.y_m, pose.y_m};
    // Facing the other way (the parked cars on its left): turn round first.
    if (TurnRound::needed(pose.yaw_rad)) mode_ = Mode::Turn;
  }

  // Every echo of the three lasers marks its cell, and the street mapped so far grows to hold it
  // (and the car: where it drove is street too).
  void mapScans(const AutoparkApi& api, const Pose2D& pose) {
    const std::pair<const LaserMount*, const component::Laser*> lasers[] = {
        {&api.mount1, &api.laser1}, {&api.mount2, &api.laser2}, {&api.mount3, &api.laser3}};
    for (const auto& [mount, laser] : lasers) {
      forEachEcho(pose.x_m, pose.y_m, pose.yaw_rad, *mount, laser->getLaserData(), [this](double x_m, double y_m) {
        map_.markOccupied(x_m, y_m);
        grow(x_m, y_m);
      });
    }
    for (const auto& corner : footprint(pose, car_, 0.0).corners()) grow(corner.x(), corner.y());
  }
  void grow(double x_m, double y_m) {
    mapped_.min_x_m = std::min(mapped_.min_x_m, x_m);
    mapped_.max_x_m = std::max(mapped_.max_x_m, x_m);
    mapped_.min_y_m = std::min(mapped_.min_y_m, y_m);
    mapped_.max_y_m = std::max(mapped_.max_y_m, y_m);
  }

  // The planning grid: the street around the slot, cut from the map, and never beyond what the
  // lasers mapped. Above the lane, where the lasers may not have reached, the grid ends a few
  // metres out (outside counts as occupied).
  OccupancyGrid planningGrid(const Pose2D& pose) const {
    const MappedStreet e = planningExtent(mapped_, slot_, pose.x_m, pose.y_m, search_->laneY(), car_.width_m);
    const double x0 = e.min_x_m, x1 = e.max_x_m, y0 = e.min_y_m, y1 = e.max_y_m;
    const double res = map_.resolution_m();
    OccupancyGrid grid(x0, y0, res, static_cast<int>(std::ceil((x1 - x0) / res)), static_cast<int>(std::ceil((y1 - y0) / res)));
    for (int row = 0; row < grid.height(); ++row) {
      for (int col = 0; col < grid.width(); ++col) {
        double x, y;
        grid.cellCentre(col, row, x, y);
        int map_col, map_row;
        if (map_.worldToCell(x, y, map_col, map_row) && map_.occupied(map_col, map_row)) grid.markCell(col, row);
      }
    }
    return grid;
  }

  // PLAN: a path from where the car stands to the slot's centre, on the lasers' grid; a plan that
  // leaves the mapped street is refused. No path: settle and try again, a few times, then fail.
  void plan(AutoparkApi& api, const Pose2D& pose) {
    const Pose2D goal{slot_.centreXM(), slot_.curb_y_m + kCurbClearanceM + api.car_width_m / 2, 0.0};
    const OccupancyGrid grid = planningGrid(pose);
    PlannedPath path = ParkingPlanner(car_, planOptions(seed_, attempts_)).plan(grid, pose, goal);
    ++attempts_;
    if (path.solved) {
      // The grid holds only the mapped street; a plan that leaves it anyway is refused.
      const std::string leaves = pathLeavesStreet(path, car_, {grid.minX_m(), grid.maxX_m(), grid.minY_m(), grid.maxY_m()});
      if (!leaves.empty()) {
        path.solved = false;
        path.message = "refused: " + leaves;
      }
    }
    logPlan(grid, goal, path);
    if (!path.solved) {
      still_s_ = 0;
      if (attempts_ < kMaxReplans + 1) {
        mode_ = Mode::Settle;
      } else {
        fail(api, "no path into the %.1f m slot after %d plans: %s", slot_.lengthM(), attempts_, path.message.c_str());
      }
      return;
    }
    path_ = path;
    tracker_.emplace(path_, car_);
    mode_ = Mode::Track;
  }

  // The plan in one line, with where the car's body would go, so a log shows it stays on the street.
  void logPlan(const OccupancyGrid& grid, const Pose2D& goal, const PlannedPath& path) const {
    char within[120] = "";
    if (!path.poses.empty()) {
      const MappedStreet body = bodyExtent(path, car_, {grid.maxX_m(), grid.minX_m(), grid.maxY_m(), grid.minY_m()});
      std::snprintf(within, sizeof within, ", body within x %.2f to %.2f, y %.2f to %.2f", body.min_x_m, body.max_x_m,
                    body.min_y_m, body.max_y_m);
    }
    std::fprintf(stderr, "planner: %s to (%.2f, %.2f) in %.1f ms wall, %d cusps, %.1f m%s%s%s\n",
                 path.solved ? "path" : "no path", goal.x_m, goal.y_m, path.planning_time_s * 1e3, path.cusps,
                 path.length_m, within, path.message.empty() ? "" : ": ", path.message.c_str());
  }

  unsigned seed_;
  CarGeometry car_;
  std::optional<StreetSearch> search_;
  TurnRound turn_;
  OccupancyGrid map_;
  MappedStreet mapped_;
  Slot slot_;
  int direction_ = 1;
  PlannedPath path_;
  std::optional<PathTracker> tracker_;
  Mode mode_ = Mode::Search, logged_mode_ = Mode::Failed;
  double t_ = 0, still_s_ = 0;
  int replans_ = 0, attempts_ = 0;
};

}  // namespace

std::unique_ptr<AutoparkAlgorithm> makePlannedAlgorithm(uint64_t seed) { return std::make_unique<PlannedParker>(seed); }

}  // namespace aula::autopark
