// Parking planner success table: slots of 1.6, 1.4, 1.3, 1.2 car lengths (and the default world's
// 9 m gap) x N seeds, escape + RRTConnect (the planner) vs plain Reeds-Shepp RRTConnect to the goal.
// Plain main() printing a table (numbers go to docs/planner.md). Columns: successes/seeds, median
// and max plan() time, median escape-search time (successful runs), median cusps and rear-axle path
// length, smallest in-slot clearance the escape needed, last failure message.
//   bench_parking_planner [seeds=20] [plain_seeds=10] [plain_time_limit_s=1.0] [plain]   (plain: only the plain rows)
#include <aula/autopark/parking_planner.hpp>
#include <aula/autopark/street_scenario.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace aula::autopark;

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void row(const char* method, const char* slot, double gap_m, const CarGeometry& car,
         ParkingPlanner::Options opt, int seeds) {
  const StreetScenario street = makeParallelParkingStreet(gap_m);
  const OccupancyGrid grid = street.makeGrid(0.05);
  std::vector<double> times_ms, cusps, lengths, escape_ms;
  double min_slot_clearance = 1e9;
  int ok = 0;
  double max_ms = 0.0;
  std::string last_failure;
  for (int seed = 1; seed <= seeds; ++seed) {
    opt.seed = static_cast<unsigned>(seed);
    const ParkingPlanner planner(car, opt);
    const PlannedPath path = planner.plan(grid, street.start_centre, street.goal_centre);
    const double ms = 1e3 * path.planning_time_s;
    times_ms.push_back(ms);
    max_ms = std::max(max_ms, ms);
    if (path.solved) {
      ++ok;
      cusps.push_back(path.cusps);
      escape_ms.push_back(1e3 * path.escape_time_s);
      if (opt.use_escape) min_slot_clearance = std::min(min_slot_clearance, path.escape_clearance_m);
      lengths.push_back(path.length_m);
    } else {
      last_failure = path.message;
    }
  }
  char clearance[16] = "-";
  if (min_slot_clearance < 1e9) std::snprintf(clearance, sizeof clearance, "%.2f", min_slot_clearance);
  std::printf("| %-26s | %-6s | %5.2f | %3d/%-3d | %8.1f | %8.1f | %8.1f | %5.0f | %6.1f | %-8s | %s\n", method, slot,
              gap_m, ok, seeds, median(times_ms), max_ms, median(escape_ms), median(cusps), median(lengths), clearance,
              last_failure.empty() ? "" : last_failure.c_str());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const int seeds = argc > 1 ? std::atoi(argv[1]) : 20;
  const int plain_seeds = argc > 2 ? std::atoi(argv[2]) : 10;
  const double plain_limit_s = argc > 3 ? std::atof(argv[3]) : 1.0;
  const bool plain_only = argc > 4 && std::string(argv[4]) == "plain";
  const CarGeometry car;  // 4 x 2 m, rear axle 1.3 m behind the centre, R = 5 m
  struct Slot {
    const char* name;
    double gap_m;
  };
  const std::vector<Slot> slots = {{"1.6 L", 6.4}, {"1.4 L", 5.6}, {"1.3 L", 5.2}, {"1.2 L", 4.8}, {"9 m", 9.0}};

  std::printf("car %.1f x %.1f m, rear axle %.1f m behind centre, R = %.1f m, clearance 0.15 m, grid 0.05 m\n",
              car.length_m, car.width_m, car.rear_axle_from_centre_m, car.min_turn_radius_m);
  std::printf("| %-26s | %-6s | gap m | success | med ms   | max ms   | med esc. | cusps | len m  | slot clr | last failure\n",
              "method", "slot");
  std::printf("|----------------------------|--------|-------|---------|----------|----------|----------|-------|--------|----------|\n");
  ParkingPlanner::Options opt;  // defaults: time limit 1 s, clearance 0.15 m
  if (!plain_only) {
    for (const Slot& s : slots) row("escape + RRTConnect", s.name, s.gap_m, car, opt, seeds);
  }

  ParkingPlanner::Options plain = opt;
  plain.use_escape = false;
  plain.deterministic_nn = false;  // OMPL's default GNAT: faster on big trees (not repeatable)
  plain.time_limit_s = plain_limit_s;
  char name[64];
  std::snprintf(name, sizeof name, "plain RRTConnect (%.0f s)", plain_limit_s);
  for (const Slot& s : slots) row(name, s.name, s.gap_m, car, plain, plain_seeds);

  if (plain_only) return 0;
  // Reference point at the body centre (what a centre-referenced kinematic model allows).
  CarGeometry centre_ref = car;
  centre_ref.rear_axle_from_centre_m = 0.0;
  for (const Slot& s : slots) row("escape+RRTC, centre ref.", s.name, s.gap_m, centre_ref, opt, std::min(seeds, 5));
  return 0;
}
