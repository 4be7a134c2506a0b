#pragma once
// TeleTaxi's referee logic on simulated time, fed by the process's LCM handlers (true pose,
// episode events, clock ticks). No LCM or Qt here, so it is unit-testable.
//
// The clock starts at GO! (the component's first start) and stops at arrival: the taxi at rest
// (speed below stop_speed for stop_hold_s) within the arrival radius. A run that has not
// arrived timeout_s after GO! is "not reached".

#include <aula/config/config.hpp>
#include <aula/referee/run_picture.hpp>
#include <aula/teletaxi/taxi_grade.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace aula::teletaxi {

struct TaxiRefereeSettings {
  std::string rubric = "default";  // the preset of TeleTaxi.Referee.Rubric, for the reports
  double timeout_s = 600.0;
  double stop_speed_mps = 0.05;
  double stop_hold_s = 1.0;
  TaxiGradeScale scale;
};

// The referee's settings from its effective configuration (TeleTaxi.Referee.*).
TaxiRefereeSettings taxiRefereeSettings(const config::Config& cfg);

class TaxiReferee {
 public:
  explicit TaxiReferee(TaxiRefereeSettings settings) : settings_(settings) {}

  void setGoal(double x_m, double y_m);
  void start(int64_t utime);               // GO!
  void onPose(int64_t utime, double x_m, double y_m, double yaw_rad);
  void onTick(int64_t utime);              // checks arrival and timeout

  bool hasGoal() const { return goal_set_; }
  bool started() const { return start_utime_.has_value(); }
  bool finished() const { return finished_; }
  const TaxiGrade& grade() const { return grade_; }
  TaxiGrade provisionalGrade() const;      // "Show me my mark" before the end

  // For the GUI and the report.
  double elapsedS() const;                 // sim seconds since GO!, frozen at the end
  double straightDistanceM() const { return straight_distance_m_; }  // start -> goal
  double pathLengthM() const { return path_length_m_; }              // travelled since GO!
  double distanceToGoalM() const;
  double speedMps() const { return speed_mps_; }
  double yawRad() const { return yaw_rad_; }
  double goalX() const { return goal_x_; }
  double goalY() const { return goal_y_; }
  bool hasPose() const { return have_pose_; }
  double x() const { return x_; }
  double y() const { return y_; }
  const TaxiRefereeSettings& settings() const { return settings_; }
  // Where the taxi drove from GO! to the end (its first point: the start), for the picture.
  const referee::Trail& trail() const { return trail_; }

 private:
  TaxiGradeInput gradeInput(bool timed_out) const;

  TaxiRefereeSettings settings_;
  bool goal_set_ = false;
  double goal_x_ = 0, goal_y_ = 0;
  std::optional<int64_t> start_utime_;
  std::optional<int64_t> end_utime_;
  bool have_pose_ = false;
  int64_t last_utime_ = 0, now_utime_ = 0;
  double x_ = 0, y_ = 0, yaw_rad_ = 0;
  double speed_mps_ = 0;
  double still_since_s_ = -1;
  double straight_distance_m_ = 0;
  double path_length_m_ = 0;
  bool finished_ = false;
  TaxiGrade grade_;
  referee::Trail trail_{0.25};  // a point per 25 cm: a 10 km drive keeps 40000
};

}  // namespace aula::teletaxi
