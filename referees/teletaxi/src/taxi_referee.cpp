#include "aula/teletaxi/taxi_referee.hpp"

#include <cmath>
#include <limits>

namespace aula::teletaxi {

TaxiRefereeSettings taxiRefereeSettings(const config::Config& cfg) {
  TaxiRefereeSettings s;
  s.rubric = cfg.getString("TeleTaxi.Referee.Rubric");
  s.timeout_s = cfg.getDouble("TeleTaxi.Referee.Timeout");
  s.stop_speed_mps = cfg.getDouble("TeleTaxi.Referee.StopSpeed");
  s.stop_hold_s = cfg.getDouble("TeleTaxi.Referee.StopHold");
  s.scale.arrival_radius_m = cfg.getDouble("TeleTaxi.Referee.ArrivalRadius");
  s.scale.reference_speed_mps = cfg.getDouble("TeleTaxi.Referee.FullMarkSpeed");
  s.scale.full_mark_time_s = cfg.getDouble("TeleTaxi.Referee.FullMarkTime");
  s.scale.min_travel_m = cfg.getDouble("TeleTaxi.Referee.MinTravel");
  return s;
}

void TaxiReferee::setGoal(double x_m, double y_m) {
  if (started()) return;  // the destination is fixed once the taxi leaves
  goal_set_ = true;
  goal_x_ = x_m;
  goal_y_ = y_m;
}

void TaxiReferee::start(int64_t utime) {
  if (started() || !goal_set_) return;
  start_utime_ = utime;
  path_length_m_ = 0;
  if (have_pose_) trail_.add(x_, y_);  // where the taxi stood at GO!
  straight_distance_m_ = distanceToGoalM();
}

void TaxiReferee::onPose(int64_t utime, double x_m, double y_m, double yaw_rad) {
  if (finished_) return;
  if (have_pose_ && utime > last_utime_) {
    const double step_m = std::hypot(x_m - x_, y_m - y_);
    const double dt_s = (utime - last_utime_) / 1e6;
    speed_mps_ = step_m / dt_s;
    if (started() && utime > *start_utime_) path_length_m_ += step_m;
    const double t_s = utime / 1e6;
    if (speed_mps_ < settings_.stop_speed_mps) {
      if (still_since_s_ < 0) still_since_s_ = t_s;
    } else {
      still_since_s_ = -1;
    }
  }
  have_pose_ = true;
  last_utime_ = utime;
  x_ = x_m;
  y_ = y_m;
  yaw_rad_ = yaw_rad;
  if (started() && utime >= *start_utime_) trail_.add(x_m, y_m);
  if (started() && straight_distance_m_ == 0 && path_length_m_ == 0) {
    straight_distance_m_ = distanceToGoalM();  // GO! came before the first pose
  }
}

double TaxiReferee::distanceToGoalM() const {
  return goal_set_ && have_pose_ ? std::hypot(goal_x_ - x_, goal_y_ - y_)
                                 : std::numeric_limits<double>::infinity();
}

double TaxiReferee::elapsedS() const {
  if (!started()) return 0.0;
  const int64_t end = end_utime_ ? *end_utime_ : now_utime_;
  return end > *start_utime_ ? (end - *start_utime_) / 1e6 : 0.0;
}

TaxiGradeInput TaxiReferee::gradeInput(bool timed_out) const {
  TaxiGradeInput in;
  in.final_distance_m = distanceToGoalM();
  in.path_length_m = path_length_m_;
  in.driving_time_s = elapsedS();
  in.timed_out = timed_out;
  in.stopped = still_since_s_ >= 0 && now_utime_ / 1e6 - still_since_s_ >= settings_.stop_hold_s;
  return in;
}

TaxiGrade TaxiReferee::provisionalGrade() const {
  if (finished_) return grade_;
  TaxiGradeInput in = gradeInput(false);
  in.stopped = true;  // as if the taxi stopped now
  return gradeTaxi(in, settings_.scale);
}

void TaxiReferee::onTick(int64_t utime) {
  now_utime_ = utime;
  if (finished_ || !started() || !have_pose_) return;
  const TaxiGradeInput in = gradeInput(false);
  if (in.stopped && in.final_distance_m <= settings_.scale.arrival_radius_m) {
    // Arrival: the clock stops when the taxi came to rest, not when we noticed.
    end_utime_ = static_cast<int64_t>(std::llround(still_since_s_ * 1e6));
    TaxiGradeInput at_rest = gradeInput(false);
    at_rest.stopped = true;
    grade_ = gradeTaxi(at_rest, settings_.scale);
    finished_ = true;
  } else if (elapsedS() >= settings_.timeout_s) {
    end_utime_ = utime;
    grade_ = gradeTaxi(gradeInput(true), settings_.scale);
    finished_ = true;
  }
}

}  // namespace aula::teletaxi
