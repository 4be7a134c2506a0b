#pragma once
// The mapping reference's map, built from the student API alone: an occupancy grid drawn from
// the laser at the known yaw, and the translation found by matching each scan against it.
//
// Frame: the map's origin is where the robot started, its axes the world's (the yaw sensor is
// absolute), so only x and y are unknown. With the yaw exact, matching a scan is a search over
// translations only: correlative (a grid of candidates over the window, then a hill climb down
// to millimetres) on a match field that is 1 on every hit drawn into the map and falls linearly
// to 0 at field_radius_m from it. One field per way the beams look (side()): a scan's point
// counts only against walls seen from its own side, never a thin wall's other face.
//
// Plain data on the standard library and the API's devices (aula/component/devices.hpp), so it
// builds in a student's plugin against an installed Aula.

#include <aula/component/devices.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace aula::vacuum::mapping {

struct Point2 {
  double x_m = 0, y_m = 0;
};

// A scan's end point relative to the laser (the map's axes), and the side (ScanMap::side) of the
// surface it fell on: the way a beam square to that surface would look at it.
struct ScanPoint {
  double x_m = 0, y_m = 0;
  int side = 0;
};

struct ScanMapSettings {
  double cell_m = 0.025;          // a wall is placed within half a cell: the match's bias bound
  double size_m = 40;             // the square mapped, centred on the start
  double field_radius_m = 0.3;    // the match field falls to 0 this far from an occupied cell
  double free_max_m = 6.0;        // free space is carved along each beam up to this range
  double hit_max_m = 8.0;         // a beam longer than this marks no wall (grazing, far)
  double join_max_m = 0.3;        // neighbouring beams' hits this far apart on one surface are joined
  double hit_margin_m = 0.05;     // a hit's beam carves free space only up to this short of it
  int hit_logodds = 4, free_logodds = 1, occupied_logodds = 4;  // per beam; clamped to +-100
};

struct ScanMatch {
  Point2 laser_m;     // where the laser was, in the map
  double score = 0;   // mean match field over the scan's points, 0..1 (1: every point on a wall)
  int points = 0;
  // How much the score drops kSharpnessStepM away along x and along y: near 0 along a corridor
  // (or a single wall), where the scan cannot tell where along it the laser is.
  double sharpness_x = 0, sharpness_y = 0;
  static constexpr double kSharpnessStepM = 0.05;
};

class ScanMap {
 public:
  explicit ScanMap(const ScanMapSettings& settings = {});

  const ScanMapSettings& settings() const { return s_; }

  // A scan's end points relative to the laser, in the map's axes (rotated by the laser's yaw):
  // every `stride`-th beam that hit something nearer than max_range_m.
  static std::vector<ScanPoint> endpoints(const component::LaserData& scan, double laser_yaw_rad, double max_range_m,
                                       int stride = 1);

  // Draws a scan taken at `laser_m` (the map's frame) with the laser facing laser_yaw_rad.
  void insert(const component::LaserData& scan, double laser_yaw_rad, Point2 laser_m);

  // The laser's position that best fits `points` (endpoints()) to the map, searched within
  // +-search_half_m of `predicted_m` (then refined by a hill climb that may leave the window,
  // unless `bounded`: then the best fit within it).
  ScanMatch match(const std::vector<ScanPoint>& points, Point2 predicted_m, double search_half_m,
                  bool bounded = false) const;
  // match() on the points seen(): chosen at the prediction first, then again from where they
  // fit (a prediction 0.3 m off keeps the points that happen to land near walls from there).
  // ScanMatch::points: how many were matched.
  ScanMatch matchSeen(const std::vector<ScanPoint>& points, Point2 predicted_m, double search_half_m,
                      bool bounded = false) const;
  double score(const std::vector<ScanPoint>& points, Point2 laser_m) const;
  // The points that, from laser_m, end near a wall the map has seen from their side: only they
  // can say where the laser is; the rest is new (a wall's other face, a room not seen yet).
  std::vector<ScanPoint> seen(const std::vector<ScanPoint>& points, Point2 laser_m) const;

  // Cells: (i, j) = (column along x, row along y).
  int width() const { return n_; }
  double cellM() const { return s_.cell_m; }
  bool inside(int i, int j) const { return i >= 0 && j >= 0 && i < n_ && j < n_; }
  int col(double x_m) const;
  int row(double y_m) const;
  Point2 centre(int i, int j) const;
  bool occupied(int i, int j) const { return inside(i, j) && occupied_[idx(i, j)] != 0; }
  bool knownFree(int i, int j) const { return inside(i, j) && logodds_[idx(i, j)] < 0 && !occupied_[idx(i, j)]; }
  bool known(int i, int j) const { return inside(i, j) && (logodds_[idx(i, j)] != 0 || occupied_[idx(i, j)]); }
  // Distance to the nearest occupied cell's centre, capped at field_radius_m.
  double clearanceM(int i, int j) const;
  // The robot stands here: its footprint is floor (the laser, ahead of the centre, never sees it).
  void markFree(Point2 centre_m, double radius_m);
  // The cells ever observed, as a box (for the window and the planner's searches).
  int minCol() const { return min_i_; }
  int maxCol() const { return max_i_; }
  int minRow() const { return min_j_; }
  int maxRow() const { return max_j_; }
  int occupiedCells() const { return occupied_count_; }

 private:
  size_t idx(int i, int j) const { return static_cast<size_t>(j) * n_ + i; }
  // Which way a beam (dx, dy) looks: 0 +x, 1 +y, 2 -x, 3 -y, by its larger component. A
  // scan's point is matched only to hits seen looking the same way: a wall's two faces are
  // 0.2 m apart, and a scan of a face not drawn yet fits the other one otherwise.
  static int side(double dx, double dy);
  // Per beam, the way a beam square to the surface it hit would look (from its neighbours' hits
  // on the same surface; its own direction where it has none); (0, 0) where it hit nothing.
  // A thin wall's two faces then never share a side, whatever the beams' angles: by the beams'
  // own directions a face seen at 50 degrees counted as seen along the other axis, and a scan
  // fitted a wall's other face 0.2 m away (h2 seeds 2 and 9).
  static bool neighbours(const component::LaserData& scan, int k, int m);
  void joinHits(Point2 a_m, Point2 b_m, Point2 look);
  static std::vector<Point2> surfaceLooks(const component::LaserData& scan, double laser_yaw_rad, double max_range_m);
  static constexpr int kSides = 4;
  static constexpr uint8_t kOccupiedBit = 0x10;  // occupied_: this bit, and one bit per side stamped
  void occupy(int i, int j, Point2 hit_m, double beam_x, double beam_y);
  void stamp(int i, int j, Point2 hit_m, int side_index);
  void ray(int i0, int j0, Point2 end_m);
  void touch(int i, int j);
  double field(double x_m, double y_m, int side_index) const;  // 1 on a hit, 0 from field_radius_m away

  ScanMapSettings s_;
  int n_ = 0;
  double origin_m_ = 0;  // the x (and y) of cell 0's lower edge
  double unit_m_ = 0;
  std::vector<int8_t> logodds_;
  std::vector<uint8_t> occupied_;
  std::vector<uint8_t> distance_;  // to the nearest hit, in units of unit_m_ (field_radius_m / 250); 255 = beyond
  std::array<std::vector<uint8_t>, kSides> side_distance_;  // the same, per side: hits seen looking that way
  std::vector<std::pair<int, int>> stamp_;  // cell offsets a hit in the centre cell may reach
  // The nearest hit itself, from the cell's centre (units of kOffsetUnitM): the match field is the
  // distance to it, exact where bilinear interpolation of cell values would pull every wall onto
  // the cells' centres, up to half a cell off.
  static constexpr double kOffsetUnitM = 0.0005;
  std::array<std::vector<std::array<int16_t, 2>>, kSides> side_nearest_;
  int min_i_, max_i_, min_j_, max_j_;
  int occupied_count_ = 0;
};

}  // namespace aula::vacuum::mapping
