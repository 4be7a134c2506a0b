#pragma once
// The Autopark referee's logic on simulated time, fed by the process's LCM handlers (true pose,
// contacts from the bumper driver, which reads DART's contacts, the component's Run, clock
// ticks). No LCM or Qt here, so it is unit-testable.
//
// The clock starts at Run and stops when the car is parked: stationary inside the slot for
// still_hold_s. A run that has not parked timeout_s after Run ends "not parked".
// Mark = 0.025 * (A + T + D + C), each 0-100 (the original's formula, its bugs fixed):
//   A  orientation to the curb: 100 within +-15 deg, 50 within +-45, else 0 (symmetric bands)
//   T  100 when parked in under full_time_s, else 100 * full_time_s / t; 0 if not parked
//   D  mean of front gap, rear gap and curb scores: a gap in [gap_full_from, gap_full_to) m is
//      100, in [gap_half_from, gap_full_from) 50; curb distance <= curb_full 100, < curb_half 50
//   C  100 without a collision, else 0

#include <aula/referee/run_picture.hpp>
#include <aula/scoring/parking_geometry.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace aula::autopark {

struct ParkingRefereeSettings {
  double timeout_s = 300.0;
  double still_hold_s = 3.0;
  double still_speed_mps = 0.05;
  double full_time_s = 170.0;
  double gap_half_from_m = 1.0, gap_full_from_m = 1.5, gap_full_to_m = 3.5;
  double curb_full_m = 0.75, curb_half_m = 1.5;
};

struct ParkingScores {
  double angle = 0, time = 0, distance = 0, collision = 0;
  double mark = 0;  // 0-10
};

ParkingScores scoreParking(const ParkingMeasures& m, bool parked, double park_time_s, long long collisions,
                           const ParkingRefereeSettings& s);
// The D terms: 100, 50 or 0 for one gap to a parked car, and for the curb distance.
double gapScore(double gap_m, const ParkingRefereeSettings& s);
double curbScore(double gap_m, const ParkingRefereeSettings& s);

class ParkingReferee {
 public:
  ParkingReferee(ParkingScene scene, ParkingRefereeSettings settings) : scene_(scene), settings_(settings) {}

  void start(int64_t utime);  // Run
  void onPose(int64_t utime, double x_m, double y_m, double yaw_rad);
  void onContact(int64_t utime, bool pressed);  // the car touches anything (DART contact)
  void onTick(int64_t utime);  // checks parked and timeout

  bool started() const { return start_utime_.has_value(); }
  bool finished() const { return finished_; }
  bool parked() const { return parked_; }
  ParkingScores scores() const;  // provisional until finished ("Show me my mark")

  const ParkingScene& scene() const { return scene_; }
  const ParkingRefereeSettings& settings() const { return settings_; }
  const ParkingMeasures& measures() const { return measures_; }
  double elapsedS() const;  // sim seconds since Run, frozen when parked or at the timeout
  long long collisions() const { return collisions_; }
  double contactS() const;  // total time in contact since Run
  double x() const { return x_; }
  double y() const { return y_; }
  double yawRad() const { return yaw_; }
  double speedMps() const { return speed_mps_; }
  bool hasPose() const { return have_pose_; }
  // Where the car drove until the end, for the picture.
  const referee::Trail& trail() const { return trail_; }

 private:
  ParkingScene scene_;
  ParkingRefereeSettings settings_;
  ParkingMeasures measures_;
  std::optional<int64_t> start_utime_, end_utime_;
  bool have_pose_ = false, finished_ = false, parked_ = false;
  int64_t last_pose_utime_ = 0, now_utime_ = 0;
  double x_ = 0, y_ = 0, yaw_ = 0, speed_mps_ = 0;
  std::optional<int64_t> still_since_utime_;
  long long collisions_ = 0;
  bool in_contact_ = false;
  int64_t contact_since_utime_ = 0, contact_us_ = 0;
  referee::Trail trail_{0.1};  // a point per 10 cm: 300 s at 3 m/s keeps 9000
};

}  // namespace aula::autopark
