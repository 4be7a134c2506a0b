#pragma once
// The TeleTaxi student's grid: the original exercise's Grid API over the generated city map,
// with consistent indexing. A cell is addressed (x, y) = (column, row) of the map image in
// every call; gridToWorld/worldToGrid go through the one MapTransform of the map's metadata.

#include <aula/geometry/map_transform.hpp>

#include <opencv2/core.hpp>

#include <functional>
#include <utility>

namespace aula::teletaxi {

class Grid {
 public:
  // map: CV_8UC1, 0 = obstacle, 255 = free (the generated occupancy PNG).
  Grid(cv::Mat map, geometry::MapTransform transform);

  int getWidth() const { return map_.cols; }
  int getHeight() const { return map_.rows; }
  const cv::Mat& getMap() const { return map_; }  // CV_8UC1, 0 obstacle, 255 free
  bool isFree(int x, int y) const;

  // Destination and robot cell (x = column, y = row); (-1, -1) before they are known.
  std::pair<int, int> getDestiny() const { return destiny_; }
  std::pair<int, int> getPose() const { return pose_; }
  void setDestiny(int x, int y) { destiny_ = {x, y}; }
  void setPose(int x, int y) { pose_ = {x, y}; }

  // The student's field: floats, all 0 until set. Out-of-map reads give +inf.
  void setVal(int x, int y, float value);
  float getVal(int x, int y) const;
  const cv::Mat& field() const { return field_; }  // CV_32FC1

  // The path: non-zero cells are drawn in green once setPathFinded() is called.
  void setPathVal(int x, int y, float value);
  float getPathVal(int x, int y) const;
  const cv::Mat& path() const { return path_; }  // CV_32FC1
  void setPathFinded() { path_found_ = true; }
  bool isPathFinded() const { return path_found_; }

  // Clears field and path (a new destination).
  void resetPath();

  // Asks the GUI to open the "Grid Field" window (no-op headless).
  void showGrid() const {
    if (on_show_grid_) on_show_grid_();
  }
  void setShowGridHandler(std::function<void()> handler) { on_show_grid_ = std::move(handler); }
  // The field as a picture: dark near the target, light far away, obstacles black, unreached white.
  cv::Mat fieldImage() const;

  // Cell centre in world metres, and the cell containing a world point.
  std::pair<double, double> gridToWorld(int x, int y) const;
  std::pair<int, int> worldToGrid(double x_m, double y_m) const;
  const geometry::MapTransform& transform() const { return transform_; }

 private:
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < map_.cols && y < map_.rows; }

  cv::Mat map_;
  geometry::MapTransform transform_;
  cv::Mat field_;
  cv::Mat path_;
  std::pair<int, int> destiny_{-1, -1};
  std::pair<int, int> pose_{-1, -1};
  bool path_found_ = false;
  std::function<void()> on_show_grid_;
};

}  // namespace aula::teletaxi
