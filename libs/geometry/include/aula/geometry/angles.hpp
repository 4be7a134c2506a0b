#pragma once
// Angle wrapping: one definition for the physics, the planners, the referees and the algorithms.

#include <cmath>

namespace aula::geometry {

// An angle in [-pi, pi). fmod rounds a + pi, so an angle already in range may come back a few
// 1e-16 rad off; the planners' and reference algorithms' recorded runs depend on exactly this
// rounding (std::remainder, exact, changes the Ackermann reactive runs), so it stays.
inline double wrapAngle(double a_rad) {
  double r = std::fmod(a_rad + M_PI, 2 * M_PI);
  if (r < 0) r += 2 * M_PI;
  return r - M_PI;
}

// A heading as every window, log and report shows it: degrees, counter-clockwise from +x, in
// (-180, 180] (so facing -y is -90, never 270).
inline double headingDeg(double yaw_rad) {
  const double deg = std::remainder(yaw_rad * 180.0 / M_PI, 360.0);
  return deg <= -180.0 ? deg + 360.0 : deg;
}

// The angle between two undirected lines, in [-pi/2, pi/2]: a car parked backwards is as
// aligned with the curb as one parked forwards.
inline double wrapLineAngle(double a_rad) { return std::remainder(a_rad, M_PI); }

}  // namespace aula::geometry
