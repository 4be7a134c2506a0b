#pragma once
// A laser scan from a formula, for tests of what reads scans (maps, matchers): `beams` beams
// evenly over [min_angle_rad, max_angle_rad] (both ends included, as the laser driver spaces
// them), each range_m(beam angle) long, and the roomba laser's 0.08-10 m limits.

#include <aula/component/devices.hpp>

#include <functional>

namespace aula::test {

inline component::LaserData syntheticScan(int beams, double min_angle_rad, double max_angle_rad,
                                          const std::function<double(double)>& range_m) {
  component::LaserData scan;
  scan.numLaser = beams;
  scan.minAngle = min_angle_rad;
  scan.maxAngle = max_angle_rad;
  scan.angleIncrement = (max_angle_rad - min_angle_rad) / (beams - 1);
  scan.minRange = 0.08;
  scan.maxRange = 10;
  for (int i = 0; i < beams; ++i) scan.values_m.push_back(static_cast<float>(range_m(scan.angle(i))));
  return scan;
}

}  // namespace aula::test
