#pragma once
// The Autopark referee's logic on simulated time, fed by the process's LCM handlers (true pose,
// contacts from the bumper driver, which reads DART's contacts, the component's Run, clock
// ticks). No LCM or Qt here, so it is unit-testable.
//
// The clock starts at Run and stops when the car is parked: stationary inside the slot for
// still_hold_s. A run that has not parked timeout_s after Run ends "not parked", and the report
// says which case it was (ParkingCase): stayed still, drove off the street, parked elsewhere (the
// free curb at the street's end, another gap), or gave up (anything else).
// Terms, each 0-100 (the original's formula, its bugs fixed):
//   A  orientation to the curb: 100 within +-15 deg, 50 within +-45, else 0 (symmetric bands)
//   T  100 when parked in under full_time_s, else 100 * full_time_s / t; 0 if not parked
//   D  mean of front gap, rear gap and curb scores; curb distance <= curb_full 100, < curb_half 50.
//      A gap to a parked car, by the rubric's gap rule:
//        slot (default): with g* = (slot length - car length) / 2, the gap of a centred car,
//          100 from slot_gap_full_fraction x g*, 50 from slot_gap_half_fraction x g*: a car whose
//          centre is within (1 - full fraction) x g* of the slot's centre has both gaps at 100,
//          in a slot of any length;
//        absolute (the original): 100 in [gap_full_from, gap_full_to) m, 50 in [gap_half_from,
//          gap_full_from)
//   C  100 without a contact, else 0 (scale thesis); 100 x (1 - the contacts' cost) (scale parked)
// Mark, by the rubric's scale:
//   parked (default): parked in the slot, 0.025 * (A + T + D + 100) x (1 - cost); not parked,
//     not_parked_mark x (1 - cost), whatever the case. cost = min(1, sum over contacts of
//     contact_share + share_per_s x its duration + share_per_cm x its depth).
//   thesis (the original): 0.025 * (A + T + D + C), A and D wherever the car stopped in the slot.

#include <aula/config/config.hpp>
#include <aula/referee/run_picture.hpp>
#include <aula/referee/run_trace.hpp>
#include <aula/scoring/parking_geometry.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace aula::autopark {

// The street's geometry (libs/scoring), by its names here.
using scoring::ParkingScene;
using scoring::SceneNames;
using scoring::sceneNamesOf;
using scoring::ParkingMeasures;
using scoring::measureParking;
using scoring::contactDepthM;
using scoring::offStreet;
using scoring::parkedElsewhere;

struct ParkingRefereeSettings {
  std::string rubric = "default";  // the preset of Autopark.Referee.Rubric, for the reports
  double timeout_s = 300.0;
  double still_hold_s = 3.0;
  double still_speed_mps = 0.05;
  double full_time_s = 170.0;
  bool gaps_relative_to_slot = true;  // GapRule slot; false: absolute
  double slot_gap_half_fraction = 0.25, slot_gap_full_fraction = 0.5;
  double gap_half_from_m = 1.0, gap_full_from_m = 1.5, gap_full_to_m = 3.5;
  double curb_full_m = 0.75, curb_half_m = 1.5;
  bool thesis_scale = false;  // Scale thesis; false: parked
  double not_parked_mark = 1.0;
  double contact_share = 0.1, contact_share_per_s = 0.1, contact_share_per_cm = 0.05;
};

// How a run ended, for the mark and the report.
enum class ParkingCase { Parked, ParkedElsewhere, DroveOff, StayedStill, GaveUp };
const char* caseName(ParkingCase c);  // "parked", "parked_elsewhere", "drove_off", "stayed_still", "gave_up"
std::string caseText(ParkingCase c);  // "parked", "NOT parked: drove off the street", ...

// Every contact since Run: how many, how long in all, and the sum of each one's deepest depth.
struct ParkingContacts {
  long long count = 0;
  double duration_s = 0;
  double depth_m = 0;
};
// The share of the mark they cost (scale parked), 0-1.
double contactCost(const ParkingContacts& c, const ParkingRefereeSettings& s);

// The referee's settings from its effective configuration; bands out of order are a ConfigError
// naming where the values came from.
ParkingRefereeSettings parkingRefereeSettings(const config::Config& cfg);

struct ParkingScores {
  double angle = 0, time = 0, distance = 0, collision = 0;
  double mark = 0;  // 0-10
};

ParkingScores scoreParking(const ParkingMeasures& m, ParkingCase c, double park_time_s, const ParkingContacts& contacts,
                           const ParkingRefereeSettings& s);
// The mark's formula with its numbers: "0.025 x (angle 100 + time 100 + distances 100.0 + 100) x
// (1 - contacts 0.12)", "not parked 1.00 x (1 - contacts 0.00)", or the thesis's.
std::string markFormula(const ParkingScores& s, ParkingCase c, double contact_cost, const ParkingRefereeSettings& settings);
// The mark's rows for the player (referee::MarkTerm), in the rubric's own arithmetic: angle, time,
// distances and, scale parked, "parked" (2.5 when parked, not_parked_mark when not, the other terms
// then 0) then the contacts' factor (1 - cost); scale thesis, the four terms. Their total
// (referee::breakdownTotal) is scoreParking's mark.
std::vector<referee::MarkTerm> parkingMarkTerms(const ParkingMeasures& m, ParkingCase c, double park_time_s,
                                                const ParkingContacts& contacts, const ParkingRefereeSettings& s);
// The distances term's measure: each gap with its score, or why none is graded ("not inside the
// slot", "not parked"): what the player writes over the map.
std::string distancesText(const ParkingMeasures& m, ParkingCase c, const ParkingRefereeSettings& s);
// The D terms: 100, 50 or 0 for one gap to a parked car (`ideal_gap_m`: the slot's g*), and for
// the curb distance.
double gapScore(double gap_m, double ideal_gap_m, const ParkingRefereeSettings& s);
double curbScore(double gap_m, const ParkingRefereeSettings& s);
// The gap rule in words: "gaps of at least 50 % of a centred car's (half marks from 25 %); ..."
std::string gapRuleText(const ParkingRefereeSettings& s);

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
  long long collisions() const { return contacts_.count; }
  double contactS() const;  // total time in contact since Run
  ParkingContacts contacts() const;  // so far, the contact under way included
  double deepestContactM() const { return deepest_m_; }
  ParkingCase parkingCase() const;  // provisional until finished
  bool leftStreet() const { return left_street_; }
  double x() const { return x_; }
  double y() const { return y_; }
  double yawRad() const { return yaw_; }
  double speedMps() const { return speed_mps_; }
  bool hasPose() const { return have_pose_; }
  // Where the car drove until the end, for the picture.
  const referee::Trail& trail() const { return trail_; }

 private:
  static constexpr double kMovedM = 0.5;  // further than this from where it was at Run: it moved
  void endContact(int64_t utime);

  ParkingScene scene_;
  ParkingRefereeSettings settings_;
  ParkingMeasures measures_;
  std::optional<int64_t> start_utime_, end_utime_;
  bool have_pose_ = false, finished_ = false, parked_ = false;
  int64_t last_pose_utime_ = 0, now_utime_ = 0;
  double x_ = 0, y_ = 0, yaw_ = 0, speed_mps_ = 0;
  std::optional<int64_t> still_since_utime_;
  ParkingContacts contacts_;  // duration_s and depth_m of the finished contacts
  bool in_contact_ = false;
  int64_t contact_since_utime_ = 0, contact_us_ = 0;
  double contact_depth_m_ = 0;  // the deepest of the contact under way
  double deepest_m_ = 0;        // of all contacts
  bool left_street_ = false, moved_ = false;
  std::optional<std::pair<double, double>> start_xy_;  // where the car was at Run
  referee::Trail trail_{0.1};  // a point per 10 cm: 300 s at 3 m/s keeps 9000
};

}  // namespace aula::autopark
