#pragma once
// The trace's layers: what the run's player can draw over the graded run besides what the
// referee graded, each switched on and off by the student (player.js). None of it is graded:
//   - "lasers": each of the robot's lasers (its mount on the robot), a scan every kScanPeriodS,
//     every kBeamStep-th beam, its ranges in steps of kRangeStepM ("range_step_m"), delta-encoded
//     along the beams (neighbours differ little: half the bytes); a 900 s vacuum run's scans are
//     about 18 KB deflated (a scan a second in 1 cm steps: 43 KB);
//   - "belief": what the algorithm said it believes (belief_t, the vacuum's api.belief): its pose
//     every kBeliefPeriodS and its map every kBeliefMapPeriodS, put on the world where the truth
//     was when it first spoke (as its window does);
//   - "plans": each field and path the algorithm planned (plan_t, TeleTaxi's generatePath());
//   - "console": what the student's program printed (console_t), line by line with its time, the
//     first and the last kConsoleHalfBytes kept, and how much was left out between them.
// Each keeps what is stamped inside the graded episode (RunTrace: from its start, to its stop
// exclusive; a plan or a map from before the start counts from the start), on sim time only: a
// message stamped before the stop reached the referee before the tick that stopped it (lockstep),
// so a live run and `aula regrade` of its log give the same bytes.

#include <aula/belief_t.hpp>
#include <aula/config/config.hpp>
#include <aula/console_t.hpp>
#include <aula/laser_t.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/plan_t.hpp>
#include <aula/referee/report.hpp>
#include <aula/referee/run_trace.hpp>
#include <aula/world/world_spec.hpp>

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace aula::referee {

class TraceLayers {
 public:
  // A scan every 2 s: at 1 s the lasers were two thirds of a vacuum run's trace (issue 58).
  static constexpr double kScanPeriodS = 2.0;
  static constexpr size_t kBeamStep = 2;  // every other beam: 2 degrees apart on a 1-degree laser
  // A drawn hit lands on the pixel of the trace's 2 cm map or its neighbour: finer is bytes no
  // page shows (issue 58, a class's size).
  static constexpr double kRangeStepM = 0.02;
  static constexpr double kBeliefPeriodS = 0.5;
  static constexpr double kBeliefMapPeriodS = 120;
  static constexpr size_t kConsoleHalfBytes = 32 * 1024;

  // Listens to the robot's lasers and SECTION.Console.Channel, and to SECTION.Belief.Channel and
  // SECTION.Plan.Channel where the referee's settings have them. `trace` says the episode's window.
  TraceLayers(lcmbus::Bus& bus, const config::Config& cfg, const world::RobotSpec& robot, const std::string& section,
              const RunTrace& trace);
  // Headless: these no longer wake the referee (read in order at its own tick).
  void deferWakeUps(lcmbus::Bus& bus) const;
  // A run whose trace nobody writes: these channels are no longer read (nor queued: the socket
  // filter drops them); the layers stay empty.
  void leave(lcmbus::Bus& bus);

  // One message each, as the bus hands them over (tests call them with plain messages).
  void onLaser(size_t laser, const aula::laser_t& msg);
  void onConsole(const aula::console_t& msg);
  void onBelief(const aula::belief_t& msg);
  void onPlan(const aula::plan_t& msg);

  // "layers": {"lasers", "belief", "plans", "console"}, each only when the run has it.
  void addTo(Report& trace) const;

 private:
  struct Laser {
    std::string name, channel;
    double mount_x_m = 0, mount_y_m = 0, mount_yaw_rad = 0;
    double min_angle_rad = 0, increment_rad = 0, max_range_m = 0;
    std::vector<int64_t> utimes;
    std::vector<std::vector<int64_t>> ranges_steps;  // of kRangeStepM; a beam with no hit: its max range
    int64_t next_us = 0;
  };
  struct BeliefMapShot {
    int64_t utime = 0;
    bool periodic = false;  // the period's map, kept; else the latest, replaced by the next
    std::string json;       // resolution, origin (placed on the world), size, runs
  };
  struct Plan {
    int64_t utime = 0;
    std::string json;
  };
  struct Line {
    int64_t utime = 0;
    std::string text;
  };

  void onLaserMessage(const lcm::ReceiveBuffer*, const std::string& channel, const aula::laser_t* msg);
  void onConsoleMessage(const lcm::ReceiveBuffer*, const std::string& channel, const aula::console_t* msg);
  void onBeliefMessage(const lcm::ReceiveBuffer*, const std::string& channel, const aula::belief_t* msg);
  void onPlanMessage(const lcm::ReceiveBuffer*, const std::string& channel, const aula::plan_t* msg);
  // A new episode since the layers last heard: nothing of the last one stays.
  void followEpisode();
  bool inEpisode(int64_t utime) const { return trace_.started() && trace_.beforeStop(utime) && utime >= trace_.originUtime(); }
  void keepLine(Line line);

  const RunTrace& trace_;
  int64_t episode_origin_ = -1;
  std::vector<Laser> lasers_;
  std::vector<std::string> deferred_;
  std::vector<lcm::Subscription*> subscriptions_;
  // The belief, in the algorithm's frame; offset: where its frame sits on the world.
  bool belief_placed_ = false;
  double belief_dx_m_ = 0, belief_dy_m_ = 0;
  std::vector<int64_t> belief_utimes_, belief_x_mm_, belief_y_mm_, belief_yaw_mrad_;
  int64_t belief_next_us_ = 0;
  std::vector<BeliefMapShot> belief_maps_;
  int64_t belief_map_version_ = 0, belief_map_periodic_utime_ = 0;
  std::vector<Plan> plans_;
  std::vector<Line> console_head_;
  std::deque<Line> console_tail_;
  size_t console_head_bytes_ = 0, console_tail_bytes_ = 0;
  uint64_t console_dropped_bytes_ = 0, console_dropped_lines_ = 0;
};

}  // namespace aula::referee
