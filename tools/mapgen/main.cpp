// aula-mapgen WORLD --out DIR/NAME.png --resolution M_PER_PX [--size WxH] [--center X,Y]
//             [--z-band MIN,MAX]
// Rasterises a world's static geometry into a binary occupancy PNG (0 obstacle, 255 free) and
// writes NAME.yaml beside it: the one world-to-map transform of every GUI and referee.
#include <aula/config/config.hpp>
#include <aula/process/exit_codes.hpp>
#include <aula/process/guarded_main.hpp>
#include <aula/world/occupancy_map.hpp>
#include <aula/world/world_spec.hpp>

#include <aula/image/png.hpp>

#include <cmath>
#include <iostream>

namespace {

constexpr const char* kUsage =
    "usage: aula-mapgen WORLD --out DIR/NAME.png --resolution M_PER_PX [--size WxH] [--center X,Y]\n"
    "                   [--z-band MIN,MAX]\n"
    "  default size/centre: the bounding box of the static geometry; default z-band: 0.01,100 m\n";

std::pair<double, double> pairOf(const std::string& text, char sep, const std::string& option) {
  const auto at = text.find(sep);
  try {
    if (at == std::string::npos) throw std::invalid_argument(text);
    size_t used1 = 0, used2 = 0;
    const double a = std::stod(text.substr(0, at), &used1);
    const double b = std::stod(text.substr(at + 1), &used2);
    if (used1 != at || used2 != text.size() - at - 1) throw std::invalid_argument(text);
    return {a, b};
  } catch (const std::exception&) {
    throw aula::config::ConfigError("command line: --" + option + "=" + text + " is malformed");
  }
}

// The map's pixels and placement: by default the bounding box of the static geometry, resized
// by --size and moved by --center (both keep the other's default).
aula::geometry::MapTransform mapTransform(const aula::config::CommandLine& cl, const aula::world::WorldSpec& spec,
                                       double resolution) {
  using namespace aula;
  geometry::MapTransform t = world::fitTransform(spec, resolution);
  double cx = t.origin_x_m + t.width_px * resolution / 2, cy = t.origin_y_m - t.height_px * resolution / 2;
  if (cl.flag("center")) std::tie(cx, cy) = pairOf(cl.option("center"), ',', "center");
  if (cl.flag("size")) {
    const auto [w, h] = pairOf(cl.option("size"), 'x', "size");
    t.width_px = static_cast<int>(w);
    t.height_px = static_cast<int>(h);
  }
  if (t.width_px <= 0 || t.height_px <= 0 || t.width_px > 20000 || t.height_px > 20000) {
    throw config::ConfigError("command line: map size must be 1..20000 px per side");
  }
  t.origin_x_m = cx - t.width_px * resolution / 2;
  t.origin_y_m = cy + t.height_px * resolution / 2;
  return t;
}

int generateMap(int argc, char** argv) {
  using namespace aula;
  const auto cl = config::CommandLine::parse(argc, argv, {"out", "resolution", "size", "center", "z-band"});
  cl.requireKnown({"out", "resolution", "size", "center", "z-band", "help"});
  if (cl.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  if (cl.positional.size() != 1 || !cl.flag("out") || !cl.flag("resolution")) {
    std::cerr << kUsage;
    return process::kExitUsage;
  }
  const std::string out = cl.option("out");
  if (out.size() < 5 || out.substr(out.size() - 4) != ".png") {
    throw config::ConfigError("command line: --out must name a .png file");
  }
  const double resolution = pairOf(cl.option("resolution") + ",0", ',', "resolution").first;
  if (!(resolution > 0)) throw config::ConfigError("command line: --resolution must be > 0");
  const world::WorldSpec spec = world::loadWorld(cl.positional[0]);
  const geometry::MapTransform t = mapTransform(cl, spec, resolution);
  double z_min = 0.01, z_max = 100.0;
  if (cl.flag("z-band")) std::tie(z_min, z_max) = pairOf(cl.option("z-band"), ',', "z-band");

  const cv::Mat map = world::rasterizeOccupancy(spec, t, z_min, z_max);
  if (!aula::image::writePng(out, map)) throw std::runtime_error(out + ": cannot write the map image");
  const auto slash = out.rfind('/');
  const std::string file = slash == std::string::npos ? out : out.substr(slash + 1);
  t.save(out.substr(0, out.size() - 4) + ".yaml", file);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // A command-line mistake also shows the usage.
  return aula::process::guardedMain("aula-mapgen", [&] { return generateMap(argc, argv); }, kUsage);
}
