#pragma once
// The one world-to-grid transform of Aula: map images, occupancy grids, coverage grids. Grids
// are north-up: column grows with world x, row grows with -world y. Pixel (col, row) covers the
// square whose top-left corner is at world (origin_x_m + col * resolution, origin_y_m - row * resolution).

#include <cmath>
#include <string>

namespace aula::geometry {

struct MapTransform {
  double resolution_m = 1.0;   // metres per pixel
  double origin_x_m = 0.0;     // world x of the left edge of column 0
  double origin_y_m = 0.0;     // world y of the top edge of row 0
  int width_px = 0;
  int height_px = 0;

  // Continuous map coordinates (pixel centres at +0.5).
  double worldToColF(double x_m) const { return (x_m - origin_x_m) / resolution_m; }
  double worldToRowF(double y_m) const { return (origin_y_m - y_m) / resolution_m; }
  int worldToCol(double x_m) const { return static_cast<int>(std::floor(worldToColF(x_m))); }
  int worldToRow(double y_m) const { return static_cast<int>(std::floor(worldToRowF(y_m))); }
  // World coordinates of a pixel centre.
  double colToWorldX(int col) const { return origin_x_m + (col + 0.5) * resolution_m; }
  double rowToWorldY(int row) const { return origin_y_m - (row + 0.5) * resolution_m; }
  bool contains(int col, int row) const {
    return col >= 0 && row >= 0 && col < width_px && row < height_px;
  }

  // Metadata file (YAML-like, ROS map_server style: image, resolution, origin ...).
  // Throws std::runtime_error naming file and line on malformed content.
  static MapTransform load(const std::string& yaml_path, std::string* image_path = nullptr);
  void save(const std::string& yaml_path, const std::string& image_file) const;
};

}  // namespace aula::geometry
