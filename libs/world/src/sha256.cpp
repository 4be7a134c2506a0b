#include "aula/world/world_spec.hpp"

#include <glib.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

namespace aula::world {

std::string sha256Hex(const std::string& bytes) {
  std::unique_ptr<gchar, decltype(&g_free)> hex(
      g_compute_checksum_for_data(G_CHECKSUM_SHA256, reinterpret_cast<const guchar*>(bytes.data()), bytes.size()),
      &g_free);
  return hex ? std::string(hex.get()) : std::string();
}

std::string sha256OfFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw WorldError(path + ": cannot read the file");
  std::stringstream content;
  content << in.rdbuf();
  return sha256Hex(content.str());
}

std::string worldSha256(const std::string& world_path, const std::vector<std::string>& inputs) {
  const std::string world = sha256OfFile(world_path);
  std::vector<std::string> included;
  const auto canonical = std::filesystem::weakly_canonical(world_path);
  for (const auto& input : inputs) {
    if (std::filesystem::weakly_canonical(input) != canonical) included.push_back(sha256OfFile(input));
  }
  if (included.empty()) return world;
  std::sort(included.begin(), included.end());
  std::string all = world + "\n";
  for (const auto& hash : included) all += hash + "\n";
  return sha256Hex(all);
}

}  // namespace aula::world
