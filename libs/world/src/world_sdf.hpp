#pragma once
// Reading an SDF world (world_sdf.cpp, on tinyxml2): what loadWorld does on a miss of the
// parsed-world cache.

#include <aula/world/world_spec.hpp>

#include <string>
#include <vector>

namespace aula::world {

// Fills `spec` from the world at `path` (models found in `folders`; everything but the SHA-256)
// and `inputs` with every file it read. Throws WorldError naming the file and line.
void parseSdfWorld(const std::string& path, const std::vector<std::string>& folders, WorldSpec& spec,
                   std::vector<std::string>& inputs);

// What an <include><uri> in `file` names, on the model path `folders` (the folder of a model://
// URI, or an absolute path). Throws WorldError naming `file` and what is missing.
std::string resolveInclude(const std::string& uri, const std::string& file, const std::vector<std::string>& folders);

}  // namespace aula::world
