#pragma once
// The student's robot, as plain data: what an algorithm reads (pose, laser, bumper) and writes
// (motor commands). No LCM and no Qt here, so an algorithm can be unit-tested on synthetic or
// recorded scans, and built as a plugin against nothing but these headers. The component's
// proxies (proxies.hpp) are these devices fed from the bus; the names are the original
// JdeRobot API's (getLaserData, sendV, getRobotTheta...), kept for students.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace aula::component {
/// The robot's pose in the world frame (x east, y north, z up; the world's origin), on the ground plane.
class Pose3d {
 public:
  /** the robot's centre, world frame, metres */ double getX() const { return x_m_; }
  /** the robot's centre, world frame, metres */ double getY() const { return y_m_; }
  /** heading, radians, counter-clockwise from +x, in (-pi, pi] */ double getYaw() const { return yaw_rad_; }
  /// TeleTaxi's original names of getX(), getY(), getYaw().
  double getRobotX() const { return getX(); }
  double getRobotY() const { return getY(); }
  double getRobotTheta() const { return getYaw(); }
  /** false until the first reading came */ bool received() const { return received_; }
  /** sim time of the reading, microseconds */ int64_t utime() const { return utime_; }

  void set(double x_m, double y_m, double yaw_rad, int64_t utime) {
    x_m_ = x_m;
    y_m_ = y_m;
    yaw_rad_ = yaw_rad;
    utime_ = utime;
    received_ = true;
  }

 private:
  double x_m_ = 0, y_m_ = 0, yaw_rad_ = 0;
  int64_t utime_ = 0;
  bool received_ = false;
};

/// The simulator's clock as the algorithm sees it: the sim time of the control period now running
/// (the component sets it before every call). Sim time is what the referee grades on; a headless
/// run goes many times faster than the wall clock, so time an algorithm's manoeuvres with this.
class SimClock {
 public:
  /// Seconds since the simulation started (>= 0).
  double time_s() const { return static_cast<double>(utime_) / 1e6; }
  /// The same, microseconds (the sensors' timeStamp is on this clock).
  int64_t utime() const { return utime_; }
  void set(int64_t utime) { utime_ = utime; }

 private:
  int64_t utime_ = 0;
};

/// One scan, like JdeRobot's LaserData: ranges in metres, plus the original's millimetre view.
struct LaserData {
  std::vector<float> values_m;    ///< range of beam i, metres, in [minRange, maxRange] (maxRange: no echo)
  std::vector<int> distanceData;  ///< the same ranges in millimetres (the original's ints)
  int numLaser = 0;               ///< beams in the scan (0 before the first)
  double minAngle = 0, maxAngle = 0, angleIncrement = 0;  ///< radians, in the laser's frame (0 ahead, CCW)
  double minRange = 0, maxRange = 0;                      ///< metres
  int64_t timeStamp = 0;                                  ///< sim time of the scan, microseconds
  /// Beam i's angle, radians in the laser's frame (0 ahead, counter-clockwise): minAngle + i * angleIncrement.
  double angle(int i) const { return minAngle + i * angleIncrement; }
};
/// A laser range finder: its latest scan.
class Laser {
 public:
  /** the latest scan (the control period's) */ const LaserData& getLaserData() const { return data_; }
  /** false until the first scan came */ bool received() const { return data_.numLaser > 0; }

  // A scan in metres; the millimetre view is derived here, once. The values go into the buffers
  // this laser already has (while the beam count stays): a view of them that the algorithm
  // keeps (a Python numpy array) then shows the latest scan, never freed memory.
  void set(LaserData data) {
    std::vector<float> values_m = std::move(data_.values_m);
    values_m.assign(data.values_m.begin(), data.values_m.end());
    data.values_m.swap(values_m);
    std::vector<int> distance_mm = std::move(data_.distanceData);
    distance_mm.resize(data.values_m.size());
    for (size_t i = 0; i < data.values_m.size(); ++i) {
      distance_mm[i] = static_cast<int>(std::lround(data.values_m[i] * 1000.0));
    }
    data.distanceData = std::move(distance_mm);
    data_ = std::move(data);
  }

 private:
  LaserData data_;
};
/// The bumper's state.
struct BumperData {
  int bumper = 1;         ///< which side touched: 0 left, 1 centre, 2 right
  int state = 0;          ///< 1 while pressed, else 0
  int64_t timeStamp = 0;  ///< sim time of the reading, microseconds
};
/// The robot's front bumper.
class Bumper {
 public:
  /** its state this control period */ const BumperData& getBumperData() const { return data_; }
  void set(const BumperData& data) { data_ = data; }

 private:
  BumperData data_;
};

/// Motor commands in the robot's frame (x forward, y left), held until the next; clamped to the
/// exercise's limits. A non-finite command (NaN, inf) stops that axis and is counted.
class Motors {
 public:
  Motors(double max_v_mps, double max_w_radps) : max_v_(max_v_mps), max_w_(max_w_radps) {}
  /// Forward speed, m/s, clamped to [-maxV(), maxV()] (negative: backwards).
  void sendV(double v_mps) { v_ = accept(v_mps, max_v_, non_finite_v_); }
  /** turn rate, rad/s, CCW, in [-maxW(), maxW()] */ void sendW(double w_radps) { w_ = accept(w_radps, max_w_, non_finite_w_); }
  /** sideways speed, m/s (left), where the robot has it */ void sendL(double l_mps) { l_ = accept(l_mps, max_v_, non_finite_l_); }
  /// TeleTaxi's original names of sendV(), sendW().
  void setV(double v_mps) { sendV(v_mps); }
  void setW(double w_radps) { sendW(w_radps); }
  /** every axis to 0 */ void stop() { v_ = w_ = l_ = 0.0; }
  /// The commands now in force: m/s, rad/s, m/s.
  double getV() const { return v_; }
  double getW() const { return w_; }
  double getL() const { return l_; }
  /** the exercise's limit (SECTION.MaxV), m/s */ double maxV() const { return max_v_; }
  /** the exercise's limit (SECTION.MaxW), rad/s */ double maxW() const { return max_w_; }

  // How many commands were not finite, per axis, since the start.
  int64_t nonFiniteV() const { return non_finite_v_; }
  int64_t nonFiniteW() const { return non_finite_w_; }
  int64_t nonFiniteL() const { return non_finite_l_; }
  int64_t nonFiniteTotal() const { return non_finite_v_ + non_finite_w_ + non_finite_l_; }

 private:
  static double accept(double value, double limit, int64_t& non_finite) {
    if (!std::isfinite(value)) {
      ++non_finite;
      return 0.0;
    }
    return std::clamp(value, -limit, limit);
  }

  double max_v_, max_w_;
  double v_ = 0, w_ = 0, l_ = 0;
  int64_t non_finite_v_ = 0, non_finite_w_ = 0, non_finite_l_ = 0;
};

/// An occupancy grid an algorithm built: `width` x `height` cells of `resolution_m`, row-major
/// from the cell whose corner is (origin_x_m, origin_y_m); each cell 0 (free) to 255 (occupied),
/// 128 for unknown.
struct BeliefMap {
  int width = 0, height = 0;                                ///< cells, > 0
  double resolution_m = 0, origin_x_m = 0, origin_y_m = 0;  ///< metres, in the algorithm's own frame
  std::vector<uint8_t> cells;                               ///< width * height, row y = 0 first
};

/// What the algorithm believes, when it says: where it is (its own estimate, in its own frame: a
/// robot that is not told its position starts where it likes, usually at 0, 0) and the map it
/// built. Never graded and never fed back to the algorithm: the window draws it beside the truth
/// and the run's log keeps it (the component publishes it), so a student sees what their
/// localization gives. Bad values throw std::invalid_argument.
class Belief {
 public:
  /** metres, metres, radians (CCW), finite */ void setPose(double x_m, double y_m, double yaw_rad) {
    if (!std::isfinite(x_m) || !std::isfinite(y_m) || !std::isfinite(yaw_rad)) {
      throw std::invalid_argument("Belief::setPose: x, y and yaw must be finite numbers");
    }
    x_m_ = x_m;
    y_m_ = y_m;
    yaw_rad_ = yaw_rad;
    has_pose_ = true;
  }
  /** the map it built (see BeliefMap) */ void setMap(BeliefMap map) {
    if (map.width <= 0 || map.height <= 0 || map.cells.size() != static_cast<size_t>(map.width) * map.height) {
      throw std::invalid_argument("Belief::setMap: " + std::to_string(map.cells.size()) + " cells for a " +
                                  std::to_string(map.width) + " x " + std::to_string(map.height) + " map");
    }
    if (!(map.resolution_m > 0) || !std::isfinite(map.origin_x_m) || !std::isfinite(map.origin_y_m)) {
      throw std::invalid_argument("Belief::setMap: the resolution must be > 0 and the origin finite");
    }
    map_ = std::move(map);
    ++map_version_;
  }

  bool hasPose() const { return has_pose_; }
  double x_m() const { return x_m_; }
  double y_m() const { return y_m_; }
  double yaw_rad() const { return yaw_rad_; }
  const BeliefMap& map() const { return map_; }
  int64_t mapVersion() const { return map_version_; }  // 0: no map yet; +1 at each setMap

 private:
  double x_m_ = 0, y_m_ = 0, yaw_rad_ = 0;
  bool has_pose_ = false;
  BeliefMap map_;
  int64_t map_version_ = 0;
};

}  // namespace aula::component
