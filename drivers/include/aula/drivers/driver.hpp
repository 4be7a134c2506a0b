#pragma once
// A simulator-side device attached to one robot, declared in the world as an SDF
// <plugin filename="TYPE">. Drivers mirror JdeRobot's ICE drivers: each publishes or
// subscribes on its configured LCM channel, stamped with simulated time.
//
// Life cycle: the simulator creates drivers with makeDriver(), calls attach() once, then
// step(sim_time_us) after every physics step. Drivers read parameters in attach() and
// document them at the top of their source file (Stage style).

#include <aula/auth/run_key.hpp>
#include <aula/world/world_spec.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace aula::lcmbus { class Bus; }
namespace aula::physics { class PhysicsWorld; }
namespace aula::geometry { class Raycaster2D; }

namespace aula::drivers {

// Sensor realism for a whole run (Simulator.Noise.*, off by default), on top of what each plugin
// declares; drawn from each device's own stream of the run's seed (deviceSeed), so the same seed
// gives the same run.
struct SensorNoise {
  double laser_stddev_m = 0.0;  // Gaussian noise on every laser hit
  double laser_dropout = 0.0;   // the share of beams that get no echo (read max_range)
  double wheel_slip = 0.0;      // relative stddev of the speed the wheels deliver, drawn per command
};

// What a driver may touch. Owned by the simulator; outlives every driver.
struct DriverContext {
  lcmbus::Bus* bus = nullptr;
  physics::PhysicsWorld* physics = nullptr;
  // Static world geometry cut at a height (lasers ask for their mount height).
  std::function<const geometry::Raycaster2D*(double z_m)> raycaster_at;
  uint64_t seed = 0;                                 // run seed (noise)
  SensorNoise noise;                                 // the run's sensor realism
  // Numbers (and in a graded run signs) what the referee grades: the pose and the bumper.
  auth::Stamper* stamper = nullptr;
};

class Driver {
 public:
  virtual ~Driver() = default;
  // Reads the plugin's parameters and subscribes; throws world::WorldError on bad parameters.
  virtual void attach(DriverContext& context, int robot, const world::PluginSpec& plugin) = 0;
  // Called after every physics step with the new simulated time.
  virtual void step(int64_t sim_time_us) = 0;
  // World reset: forget held commands and schedules.
  virtual void reset() {}
};

// A device's own noise stream: the run seed mixed with its robot's and plugin's names.
uint64_t deviceSeed(uint64_t run_seed, const world::PluginSpec& plugin);

// The driver types this build knows, by the name used in <plugin filename="...">.
std::vector<std::string> driverTypes();
// Throws world::WorldError naming the type when it is unknown.
std::unique_ptr<Driver> makeDriver(const std::string& type);

}  // namespace aula::drivers
