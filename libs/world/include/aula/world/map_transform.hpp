#pragma once
// The map transform lives in libs/geometry now (aula/geometry/map_transform.hpp). This header
// stays, installed, for student plugins written against its old path (world::MapTransform);
// nothing in the tree includes it.

#include <aula/geometry/map_transform.hpp>

namespace aula::world {
using geometry::MapTransform;
}  // namespace aula::world
