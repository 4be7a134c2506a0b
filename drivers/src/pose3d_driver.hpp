#pragma once
// pose3d: publishes the robot's true pose (aula::pose3d_t), like JdeRobot's Pose3D.
// Parameters: channel (required), rate_hz (default 50).

#include "aula/drivers/driver.hpp"
#include "periodic.hpp"

namespace aula::drivers {

class Pose3dDriver : public Driver {
 public:
  void attach(DriverContext& context, int robot, const world::PluginSpec& plugin) override;
  void step(int64_t sim_time_us) override;
  void reset() override { schedule_.reset(); }

 private:
  DriverContext* context_ = nullptr;
  int robot_ = -1;
  std::string channel_;
  Periodic schedule_;
};

}  // namespace aula::drivers
