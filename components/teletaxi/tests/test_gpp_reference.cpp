// TeleTaxi's reference (Gradient Path Planning and its pilot) on plain data: the city's map as
// the component draws it, the taxi moving on planar kinematics against the buildings
// (tests/unit/support/plain_robot.hpp), no LCM, no DART, no process.
#include "support/plain_robot.hpp"
#include <aula/teletaxi/references.hpp>

#include <aula/teletaxi/grid.hpp>
#include <aula/teletaxi/taxi_algorithm.hpp>
#include <aula/world/occupancy_map.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace aula::teletaxi;

namespace {

constexpr double kPeriodS = 0.08;  // TeleTaxi.Period

struct City {
  aula::test::PlainRobot taxi{"cityLarge.world", "taxi_holo", 20, 2};
  aula::world::OccupancyMap map;
  std::unique_ptr<Grid> grid;
  City() {
    // TeleTaxi.Map.Resolution and ZBand, as the component draws its map.
    map = aula::world::occupancyMapOf(aula::world::loadWorld(std::string(AULA_SOURCE_DIR) + "/worlds/cityLarge.world"),
                                      {1.25, 0.01, 100});
    grid = std::make_unique<Grid>(map.image, map.transform);
  }
  void placeTaxiOnGrid() {
    const auto [px, py] = grid->worldToGrid(taxi.x(), taxi.y());
    grid->setPose(px, py);
  }
};

}  // namespace

TEST(GppReference, GeneratePathMarksAFreePathFromTheTaxiToTheDestination) {
  City city;
  const auto [dx, dy] = city.grid->worldToGrid(120, -40);  // TeleTaxi.Destination
  city.grid->setDestiny(dx, dy);
  city.placeTaxiOnGrid();
  TaxiApi api(city.taxi.pose, city.taxi.motors, *city.grid);
  auto reference = makeReferenceAlgorithm();
  reference->generatePath(api);
  ASSERT_TRUE(city.grid->isPathFinded());
  int cells = 0;
  for (int y = 0; y < city.grid->getHeight(); ++y) {
    for (int x = 0; x < city.grid->getWidth(); ++x) {
      if (city.grid->getPathVal(x, y) == 0) continue;
      ++cells;
      EXPECT_TRUE(city.grid->isFree(x, y)) << "path cell (" << x << ", " << y << ") is in a building";
    }
  }
  EXPECT_GT(cells, 10);
  EXPECT_NE(city.grid->getPathVal(dx, dy), 0) << "the path reaches the destination";
}

TEST(GppReference, DrivesToTheDestinationWithoutTouchingABuilding) {
  City city;
  const double goal_x = 120, goal_y = -40;
  const auto [dx, dy] = city.grid->worldToGrid(goal_x, goal_y);
  city.grid->setDestiny(dx, dy);
  city.placeTaxiOnGrid();
  TaxiApi api(city.taxi.pose, city.taxi.motors, *city.grid);
  auto reference = makeReferenceAlgorithm();
  reference->generatePath(api);
  const double start_distance_m = std::hypot(goal_x - city.taxi.x(), goal_y - city.taxi.y());
  double arrived_s = -1;
  const int periods = static_cast<int>(60 / kPeriodS);  // a minute of driving
  for (int i = 1; i <= periods; ++i) {
    city.placeTaxiOnGrid();  // as the component does at every tick
    reference->execute(api);
    city.taxi.step(kPeriodS, static_cast<int64_t>(i * kPeriodS * 1e6));
    if (arrived_s < 0 && std::hypot(goal_x - city.taxi.x(), goal_y - city.taxi.y()) < 2.0) arrived_s = i * kPeriodS;
  }
  const double distance_m = std::hypot(goal_x - city.taxi.x(), goal_y - city.taxi.y());
  std::printf("from %.1f m away: within 2 m after %.1f s; %.2f m away after 60 s, %d contacts\n", start_distance_m,
              arrived_s, distance_m, city.taxi.contacts());
  EXPECT_GT(arrived_s, 0) << "the taxi reaches the destination";
  EXPECT_LT(distance_m, 2.0) << "and stays there";
  EXPECT_EQ(city.taxi.motors.getV(), 0) << "stopped";
  EXPECT_EQ(city.taxi.contacts(), 0);
}
