#pragma once
// Reading an SDF world (world_sdf.cpp, on tinyxml2): what loadWorld does on a miss of the
// parsed-world cache.

#include <aula/world/world_spec.hpp>

#include <string>
#include <vector>

namespace aula::world {

// Fills `spec` from the world at `path` (models found in `folders`; everything but the SHA-256)
// and `inputs` with every file it read. Throws WorldError naming the file and line of every
// problem found (one pass: WorldError::problems()).
void parseSdfWorld(const std::string& path, const std::vector<std::string>& folders, WorldSpec& spec,
                   std::vector<std::string>& inputs);
// The same, with the problems added to `problems` instead of thrown: `spec` then holds what could
// be read (a model with a problem is left out).
void readSdfWorld(const std::string& path, const std::vector<std::string>& folders, WorldSpec& spec,
                  std::vector<std::string>& inputs, std::vector<std::string>& problems);

// What an <include><uri> in `file` names, on the model path `folders` (the folder of a model://
// URI, or an absolute path). Throws WorldError naming `file` and what is missing.
std::string resolveInclude(const std::string& uri, const std::string& file, const std::vector<std::string>& folders);

// The file a <mesh><uri> in `file` names: model://NAME/FILE on the model path, file:///PATH, an
// absolute path, or a path relative to `file`'s folder. Throws WorldError saying what is missing.
std::string resolveMeshUri(const std::string& uri, const std::string& file, const std::vector<std::string>& folders);

// The problems of the robots' plugins: a driver type or key Aula does not have (world_spec.cpp).
void checkPluginKeys(const WorldSpec& spec, std::vector<std::string>& problems);

// One mesh read once: its file, scale and sub-mesh, as text.
std::string meshKey(const MeshSource& source);

}  // namespace aula::world
