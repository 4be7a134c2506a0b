#pragma once
// The Autopark referee's geometry, from the true world: the slot (the two parked cars around
// the largest gap on the parking side), the curb line, and the car's real footprint, rotated
// about its own centre. Distances are minimum distances between footprints (the original used
// corners rotated about the world origin and maximum distances).

#include <aula/config/config.hpp>
#include <aula/geometry/oriented_box.hpp>
#include <aula/world/world_spec.hpp>

#include <limits>
#include <string>
#include <vector>

namespace aula::scoring {

// What names the street's parts when its geometry alone cannot say (Autopark.Referee.Curb: a
// collision's name, last part or whole; Autopark.Referee.CarPrefix: the start of the parked cars'
// model names); empty: found from the geometry (ParkingScene::fromWorld).
struct SceneNames {
  std::string curb;
  std::string car_prefix;
};

// The slot as the world builds it.
struct ParkingScene {
  geometry::OrientedBox rear_car;   // the parked car before the slot (smaller x: the car drives along +x)
  geometry::OrientedBox front_car;  // the parked car after it
  double curb_y_m = 0;  // the parking-side curb face (the curb is at y < curb_y_m)
  double ideal_x_m = 0, ideal_y_m = 0, ideal_yaw_rad = 0;
  double car_length_m = 4, car_width_m = 2;
  // The whole street, for contacts and for a car that leaves it: every parked car, the road's
  // ends (the parking-side curb's length) and the far curb's face (+inf when the world has none).
  std::vector<geometry::OrientedBox> parked_cars;
  double street_west_x_m = -std::numeric_limits<double>::infinity();
  double street_east_x_m = std::numeric_limits<double>::infinity();
  double far_curb_y_m = std::numeric_limits<double>::infinity();
  double slotLengthM() const;  // free gap between the two parked cars
  double idealGapM() const;    // to each parked car from a car centred in the slot: (slot - car length) / 2

  // The street runs along x with its parking side at lower y than the car's start. Unless
  // `names` says otherwise: the parking-side curb is the static box along the street (at least
  // three times as long as wide) nearest below the car's start, the far curb the nearest above
  // it, and the parked cars every other static box between the curb's face and the car's start.
  // Throws world::WorldError naming the world and what is missing (and the setting that names it).
  static ParkingScene fromWorld(const world::WorldSpec& world, const std::string& robot_name,
                                const SceneNames& names = {});
  std::string curb_name;  // the parking-side curb's collision, as the world names it
};

// Autopark.Referee.Curb and Autopark.Referee.CarPrefix of the referee's configuration.
SceneNames sceneNamesOf(const config::Config& referee);

struct ParkingMeasures {
  double front_gap_m = 0;      // car footprint to the front car
  double rear_gap_m = 0;       // car footprint to the rear car
  double ideal_gap_m = 0;      // either gap of a car centred in the slot (ParkingScene::idealGapM)
  double curb_gap_m = 0;       // nearest footprint corner to the curb face
  double yaw_error_deg = 0;    // heading relative to the curb, in (-90, 90]
  double position_error_m = 0; // car centre to the ideal pose
  bool inside_slot = false;    // centre between the two cars, in the parking lane, within 45 deg
};

ParkingMeasures measureParking(const ParkingScene& scene, double x_m, double y_m, double yaw_rad);

// How far the car's footprint goes into the street's obstacles (any parked car, the curb), m; 0
// when it touches nothing. Physics keeps it to millimetres; pushing harder goes deeper.
double contactDepthM(const ParkingScene& scene, double x_m, double y_m, double yaw_rad);
// The car's centre is off the mapped street: beyond the road's ends or over a curb.
bool offStreet(const ParkingScene& scene, double x_m, double y_m);
// Standing at the parking-side curb, parallel to it, in the parked cars' line, but not in the slot:
// the free curb at the street's end, or another gap.
bool parkedElsewhere(const ParkingScene& scene, const ParkingMeasures& m, double y_m);

}  // namespace aula::scoring
