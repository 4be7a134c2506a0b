#pragma once
// libsdformat 12 reading a world into a WorldSpec: the oracle of Aula's own reader (Debian 12 only).

#include <aula/world/world_spec.hpp>

#include <string>
#include <vector>

namespace aula::world::oracle {

// What Aula's reader did with libsdformat 12 until issue 40: `spec` (everything but the SHA-256)
// and the files read. Throws WorldError.
void parseWithSdformat(const std::string& path, const std::vector<std::string>& folders, WorldSpec& spec,
                       std::vector<std::string>& inputs);

}  // namespace aula::world::oracle
