#pragma once
// Parsing an SDF world: libaula_world_sdf.so (world_sdf.cpp, libsdformat) does it, loaded by
// loadWorld only on a miss of the parsed-world cache. See world_sdf.cpp for why a module.

#include <aula/world/world_spec.hpp>

#include <string>
#include <vector>

// In the module: fills `spec` from the world at `path` (models found in `folders`; everything but
// the SHA-256) and `inputs` with the files it read; throws aula::world::WorldError.
extern "C" void aula_world_parse_sdf(const std::string& path, const std::vector<std::string>& folders,
                                     aula::world::WorldSpec& spec, std::vector<std::string>& inputs);

namespace aula::world {

// Loads the module (beside the program: <bin>/../lib/aula/libaula_world_sdf.so) and calls it.
void parseSdfWorld(const std::string& path, const std::vector<std::string>& folders, WorldSpec& spec,
                   std::vector<std::string>& inputs);

}  // namespace aula::world
