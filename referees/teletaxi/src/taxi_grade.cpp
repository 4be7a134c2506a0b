#include "aula/teletaxi/taxi_grade.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aula::teletaxi {

TaxiGrade gradeTaxi(const TaxiGradeInput& in, const TaxiGradeScale& scale) {
  TaxiGrade g;
  g.average_speed_mps = in.driving_time_s > 0 ? in.path_length_m / in.driving_time_s : 0.0;
  g.reached = !in.timed_out && in.stopped && std::isfinite(in.final_distance_m) &&
              in.final_distance_m <= scale.arrival_radius_m;
  char line[160];
  if (!g.reached) {
    std::snprintf(line, sizeof line, "not reached: %.2f m from the destination%s",
                  in.final_distance_m, in.timed_out ? " at the timeout" : "");
    g.verdict = line;
    return g;
  }
  const bool drove = in.path_length_m >= scale.min_travel_m;
  g.base_mark = !drove ? 0.0 : in.final_distance_m <= 2.0 ? 8.0 : in.final_distance_m <= 4.0 ? 7.5 : 7.0;
  g.speed_mark = scale.full_mark_time_s <= 0 ? std::min(10.0, 10.0 * g.average_speed_mps / scale.reference_speed_mps)
                 : in.driving_time_s > 0     ? std::min(10.0, 10.0 * scale.full_mark_time_s / in.driving_time_s)
                                             : 0.0;
  g.mark = std::min(10.0, g.base_mark + 0.2 * g.speed_mark);
  if (drove) {
    std::snprintf(line, sizeof line, "reached: %.2f m from the destination, %.2f m/s average",
                  in.final_distance_m, g.average_speed_mps);
  } else {
    std::snprintf(line, sizeof line, "at the destination without driving: %.2f m travelled, under the %.2f m a distance mark needs",
                  in.path_length_m, scale.min_travel_m);
  }
  g.verdict = line;
  return g;
}

}  // namespace aula::teletaxi
