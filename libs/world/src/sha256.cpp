#include "aula/world/world_spec.hpp"

#include <glib.h>

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

}  // namespace aula::world
