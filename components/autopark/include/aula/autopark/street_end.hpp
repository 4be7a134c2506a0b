#pragma once
// Where StreetSearch turns back: the street's end is what blocks the lane, whatever the car's yaw.
// Plain data (a scan and a pose), so it is tested alone; not part of the plugin API (the search
// calls it inside the component).

#include <aula/autopark/autopark_algorithm.hpp>

namespace aula::autopark {

// The band either side of the car's width that counts as the lane.
constexpr double kLaneBandMarginM = 0.3;

// Something across the lane ahead in the direction of travel (+1: +x), within `within_m` of the
// car's centre along the street: an echo of `scan` (a laser at `mount` on a car at x, y, yaw)
// inside the band the car's body sweeps along the lane, lane_y_m +- half_band_m. Parked cars and
// curbs lie outside that band, so a car yawed towards them does not take them for the street's end.
bool laneBlockedAhead(double x_m, double y_m, double yaw_rad, const LaserMount& mount, const component::LaserData& scan,
                      int direction, double lane_y_m, double half_band_m, double within_m);

}  // namespace aula::autopark
