#pragma once
// The parsed world, cached per user ($XDG_CACHE_HOME/aula/worlds), like the occupancy maps:
// libsdformat takes 200-300 ms to parse a world (most of it its own schema), and every process
// of a run parses the same world. An entry names every file that went into it (the world and the
// files of each included model) with its SHA-256, and is used only while they all still match.

#include <aula/world/world_spec.hpp>

#include <optional>
#include <string>
#include <vector>

namespace aula::world {

// The entry's name for this world file and model search path.
std::string worldCacheKey(const std::string& path, const std::vector<std::string>& model_folders);
// The cached spec, or nothing (no entry, an unreadable or stale one: then parse the world).
std::optional<WorldSpec> readCachedWorld(const std::string& key);
// The files entry `key` lists as its inputs (empty when there is no such entry).
std::vector<std::string> cachedInputs(const std::string& key);
// The entry's path relative to the cache folder.
std::string entryName(const std::string& key);
// Writes the entry (aside, then renamed, so a parallel process never reads half of it). `inputs`
// are the files the spec was read from. A cache that cannot be written only costs the next parse.
void writeCachedWorld(const std::string& key, const WorldSpec& spec, const std::vector<std::string>& inputs);

}  // namespace aula::world
