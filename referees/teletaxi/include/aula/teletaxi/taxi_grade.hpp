#pragma once
// TeleTaxi's mark: the original's scale with its bugs fixed (sim time, Euclidean arrival,
// speed along the travelled path, no division by zero).
//   reached:  Euclidean distance to the destination <= 5 m with the taxi stopped
//   base:     8 (<= 2 m), 7.5 (<= 4 m), 7 (<= 5 m)
//   speed:    average speed along the path = path length / driving time (sim)
//   speed mark = min(10, 10 * speed / 2.6);  mark = min(10, base + 0.2 * speed mark)
//   with a world's calibration (full_mark_time_s > 0: the reference's driving time to this
//   destination on this world), the speed mark is on time instead:
//   speed mark = min(10, 10 * full_mark_time_s / driving time), so a taxi 30 % slower than the
//   reference, whatever path it took, gets 7.7
//   not reached (timeout or stopped farther than 5 m): mark 0
//   the base counts only when the taxi travelled at least min_travel_m (default rubric 2 m; the
//   original's 0 gave 8 to a taxi that never moved)

#include <string>

namespace aula::teletaxi {

struct TaxiGradeInput {
  double final_distance_m = 0.0;  // Euclidean, taxi centre to destination
  double path_length_m = 0.0;     // travelled since GO!
  double driving_time_s = 0.0;    // sim time from GO! to arrival (or timeout)
  bool stopped = false;           // the taxi was at rest when graded
  bool timed_out = false;
};

struct TaxiGrade {
  bool reached = false;
  double base_mark = 0.0;
  double average_speed_mps = 0.0;
  double speed_mark = 0.0;
  double mark = 0.0;
  std::string verdict;  // one line for humans
};

struct TaxiGradeScale {
  double arrival_radius_m = 5.0;
  double reference_speed_mps = 2.6;  // average speed worth a speed mark of 10
  double full_mark_time_s = 0.0;     // > 0: the driving time worth a speed mark of 10 (instead of the speed)
  double min_travel_m = 2.0;         // the base mark needs at least this path since GO!
};

TaxiGrade gradeTaxi(const TaxiGradeInput& in, const TaxiGradeScale& scale = {});

}  // namespace aula::teletaxi
