#pragma once
// bumper: the body's true contact state from DART's collision result (aula::bumper_t),
// like JdeRobot's Bumper. Published at rate_hz and at once whenever the state changes.
// Parameters: channel (required), rate_hz (default 20),
//   side_threshold_rad (default 0.35): contacts beyond +-threshold of straight ahead are LEFT/RIGHT.

#include "aula/drivers/driver.hpp"
#include "periodic.hpp"

namespace aula::drivers {

// Which side a contact bearing (body frame, + is left) falls on.
int8_t bumperSide(double bearing_rad, double side_threshold_rad);

class BumperDriver : public Driver {
 public:
  void attach(DriverContext& context, int robot, const world::PluginSpec& plugin) override;
  void step(int64_t sim_time_us) override;
  void reset() override;

 private:
  DriverContext* context_ = nullptr;
  int robot_ = -1;
  std::string channel_;
  double side_threshold_rad_ = 0.35;
  Periodic schedule_;
  int8_t last_state_ = -1;
  int8_t last_side_ = -1;
};

}  // namespace aula::drivers
