#pragma once
// motors: subscribes to aula::motors_t velocity commands, like JdeRobot's Motors.
// Parameters (units in names):
//   channel      required
//   max_v        m/s, default 1     |v| is clamped to it
//   max_w        rad/s, default 1   |w| is clamped to it
//   holonomic    bool, default false: the lateral speed l is honoured (clamped to max_v)
//   kinematics   "diff" (default: turns in place) or "ackermann" (car-like: |w| <= |v| / R)
//   wheelbase    m, default 2.6 (ackermann)
//   max_steer_rad  rad, default 0.48 (ackermann); minimum turning radius R = wheelbase / tan(max_steer)
//   rear_axle_x  m along the body x axis from the centre, default -wheelbase / 2 (ackermann).
//                The car turns about a point on its rear axle line, as a real car does, so the
//                centre gets the lateral speed l = -rear_axle_x * w (the rear axle never slides).
//   watchdog_s   s of sim time, default 0.5: with no command for that long the robot stops
// With the run's Simulator.Noise.WheelSlip, each command's v and w are delivered scaled by
// 1 + N(0, slip), drawn when it arrives (from this device's own stream), within the limits (a car's
// v and w by one factor: its curvature stays).
// Non-finite commands are rejected (counted, logged); the previous command stays.

#include "aula/drivers/driver.hpp"

#include <aula/motors_t.hpp>

#include <random>

namespace lcm { class ReceiveBuffer; class Subscription; }

namespace aula::drivers {

// The pure command filter, testable without LCM or physics.
struct MotorLimits {
  double max_v_mps = 1.0;
  double max_w_radps = 1.0;
  bool holonomic = false;
  bool ackermann = false;
  double min_turn_radius_m = 0.0;  // ackermann only: of the rear axle centre
  double rear_axle_x_m = 0.0;      // ackermann only: body-frame x of the rear axle
};

struct VelocityCommand {
  double v_mps = 0.0;
  double w_radps = 0.0;
  double l_mps = 0.0;
};

// Clamps to the limits and, for an Ackermann car, limits |w| to |v| / R and replaces l by the
// lateral speed of the centre that keeps the rear axle from sliding.
// Returns false (and leaves `out` alone) when any component is NaN or infinite.
bool filterCommand(const MotorLimits& limits, double v, double w, double l, VelocityCommand& out);

class MotorsDriver : public Driver {
 public:
  ~MotorsDriver() override;
  void attach(DriverContext& context, int robot, const world::PluginSpec& plugin) override;
  void step(int64_t sim_time_us) override;
  void reset() override;

  const MotorLimits& limits() const { return limits_; }
  long long rejectedCommands() const { return rejected_; }

 private:
  void onCommand(const lcm::ReceiveBuffer*, const std::string& channel, const aula::motors_t* msg);

  DriverContext* context_ = nullptr;
  lcm::Subscription* subscription_ = nullptr;
  int robot_ = -1;
  std::string channel_;
  MotorLimits limits_;
  int64_t watchdog_us_ = 500000;
  VelocityCommand command_;
  bool have_command_ = false;
  bool fresh_command_ = false;
  int64_t last_command_us_ = 0;
  int64_t now_us_ = 0;
  long long rejected_ = 0;
  std::mt19937_64 slip_rng_;  // the wheel slip's draws (deviceSeed)
};

}  // namespace aula::drivers
