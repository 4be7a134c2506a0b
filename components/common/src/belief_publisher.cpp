#include "aula/component/belief_publisher.hpp"

#include <aula/belief_t.hpp>

namespace aula::component {

void BeliefPublisher::publish(int64_t utime) {
  if (!belief_.hasPose() && belief_.mapVersion() == 0) return;
  aula::belief_t msg{};
  msg.utime = utime;
  msg.x_m = belief_.x_m();
  msg.y_m = belief_.y_m();
  msg.yaw_rad = belief_.yaw_rad();
  msg.map_version = belief_.mapVersion();
  const BeliefMap& map = belief_.map();
  if (belief_.mapVersion() != map_sent_version_ && utime - map_sent_utime_ >= map_period_us_) {
    map_sent_version_ = belief_.mapVersion();
    map_sent_utime_ = utime;
    msg.map_width = map.width;
    msg.map_height = map.height;
    msg.map_resolution_m = map.resolution_m;
    msg.map_origin_x_m = map.origin_x_m;
    msg.map_origin_y_m = map.origin_y_m;
    msg.map_cells.assign(map.cells.begin(), map.cells.end());
    msg.map_cells_count = static_cast<int32_t>(msg.map_cells.size());
  }
  bus_.publish(channel_, &msg);
}

}  // namespace aula::component
