#pragma once
// Rasterises a world's static geometry into a strictly binary occupancy image (CV_8UC1,
// 0 = obstacle, 255 = free) on a MapTransform grid. A pixel is an obstacle when its centre lies
// inside a primitive's footprint (boxes rotated by their yaw, cylinders as discs); only the
// primitives whose vertical extent overlaps [z_min_m, z_max_m] count. Robots are not drawn.

#include <aula/geometry/map_transform.hpp>
#include <aula/world/world_spec.hpp>

#include <opencv2/core.hpp>

#include <optional>
#include <string>

namespace aula::world {

cv::Mat rasterizeOccupancy(const WorldSpec& world, const geometry::MapTransform& transform, double z_min_m,
                           double z_max_m);

// Axis-aligned bounds (x_min, y_min, x_max, y_max) of the static geometry's footprints.
Eigen::Vector4d staticBounds(const WorldSpec& world);

// A grid of `resolution_m` over the static geometry's bounds exactly (WorldError if the world
// has no static geometry).
geometry::MapTransform fitTransform(const WorldSpec& world, double resolution_m);

// What an exercise draws from a world: the resolution and the heights that count.
struct MapParams {
  double resolution_m = 0.05;
  double z_min_m = 0.01;
  double z_max_m = 100.0;
};

struct OccupancyMap {
  cv::Mat image;            // CV_8UC1, 0 obstacle, 255 free
  geometry::MapTransform transform;
};

// The occupancy map of `world` over its bounds (fitTransform), from the per-user cache
// (config::cacheDir()/maps) when it is there, else rasterised and stored. The cache key is a
// hash of the static geometry and the parameters, so an edited world never gets a stale map.
OccupancyMap occupancyMapOf(const WorldSpec& world, const MapParams& params);

// Why a point is no place for a robot on this map ("(x, y) is off the map (x in [..], y in
// [..] m)", "(x, y) is inside a building or obstacle"), or nothing when its cell is free.
std::optional<std::string> pointProblem(const OccupancyMap& map, double x_m, double y_m);

}  // namespace aula::world
