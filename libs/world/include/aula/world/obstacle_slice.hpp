#pragma once
// A world's static geometry cut by a horizontal plane, for the laser drivers' ray caster.

#include <aula/geometry/raycaster2d.hpp>
#include <aula/world/world_spec.hpp>

namespace aula::world {

// The static primitives of a world whose vertical extent contains height z_m (upright boxes
// and cylinders; a tilted primitive is approximated by its footprint), and the meshes'
// cross-sections at z_m as segments.
geometry::Obstacles2D sliceAtHeight(const WorldSpec& world, double z_m);

}  // namespace aula::world
