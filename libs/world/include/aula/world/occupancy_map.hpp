#pragma once
// Rasterises a world's static geometry into a strictly binary occupancy image (CV_8UC1,
// 0 = obstacle, 255 = free) on a MapTransform grid. A pixel is an obstacle when its centre lies
// inside a primitive's footprint (boxes rotated by their yaw, cylinders as discs); only the
// primitives whose vertical extent overlaps [z_min_m, z_max_m] count. Robots are not drawn.

#include <aula/world/map_transform.hpp>
#include <aula/world/world_spec.hpp>

#include <opencv2/core.hpp>

namespace aula::world {

cv::Mat rasterizeOccupancy(const WorldSpec& world, const MapTransform& transform, double z_min_m,
                           double z_max_m);

// Axis-aligned bounds (x_min, y_min, x_max, y_max) of the static geometry's footprints.
Eigen::Vector4d staticBounds(const WorldSpec& world);

}  // namespace aula::world
