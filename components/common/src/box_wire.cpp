#include "aula/component/box_wire.hpp"

namespace aula::component {

namespace {
// A laser of any exercise has a few hundred beams; a belief's map, a house at 1 cm.
constexpr size_t kMaxBeams = 1 << 16;
constexpr size_t kMaxMapCells = size_t{1} << 28;
}  // namespace

void BoxWire::ioBytes(void* data, size_t n, const char* what) {
  if (!reading_) {
    bytes_.append(static_cast<const char*>(data), n);
    return;
  }
  if (bytes_.size() - at_ < n) {
    throw BoxWireError(std::string(what) + ": the message ends " + std::to_string(n - (bytes_.size() - at_)) +
                       " bytes short");
  }
  std::memcpy(data, bytes_.data() + at_, n);
  at_ += n;
}

void BoxWire::io(std::string& text, size_t max_bytes, const char* what) {
  if (!reading_ && text.size() > max_bytes) {
    std::string cut = text.substr(0, max_bytes);
    uint64_t count = cut.size();
    io(count, what);
    ioBytes(cut.data(), cut.size(), what);
    return;
  }
  uint64_t count = text.size();
  io(count, what);
  if (count > max_bytes) {
    throw BoxWireError(std::string(what) + ": " + std::to_string(count) + " bytes, at most " + std::to_string(max_bytes));
  }
  if (reading_) text.resize(count);
  if (count > 0) ioBytes(text.data(), count, what);
}

void BoxWire::expectEnd(const char* what) const {
  if (reading_ && at_ != bytes_.size()) {
    throw BoxWireError(std::string(what) + ": " + std::to_string(bytes_.size() - at_) + " bytes left over");
  }
}

void ioPose(BoxWire& wire, Pose3d& pose) {
  bool received = pose.received();
  double x_m = pose.getX(), y_m = pose.getY(), yaw_rad = pose.getYaw();
  int64_t utime = pose.utime();
  wire.io(received, "pose");
  wire.io(x_m, "pose");
  wire.io(y_m, "pose");
  wire.io(yaw_rad, "pose");
  wire.io(utime, "pose");
  if (wire.isReading() && received) pose.set(x_m, y_m, yaw_rad, utime);
}

void ioLaser(BoxWire& wire, Laser& laser) {
  LaserData data;
  if (!wire.isReading()) {
    const LaserData& now = laser.getLaserData();
    data.values_m = now.values_m;  // the millimetre view is derived again at the other end
    data.numLaser = now.numLaser;
    data.minAngle = now.minAngle;
    data.maxAngle = now.maxAngle;
    data.angleIncrement = now.angleIncrement;
    data.minRange = now.minRange;
    data.maxRange = now.maxRange;
    data.timeStamp = now.timeStamp;
  }
  wire.ioVector(data.values_m, kMaxBeams, "laser");
  wire.io(data.numLaser, "laser");
  wire.io(data.minAngle, "laser");
  wire.io(data.maxAngle, "laser");
  wire.io(data.angleIncrement, "laser");
  wire.io(data.minRange, "laser");
  wire.io(data.maxRange, "laser");
  wire.io(data.timeStamp, "laser");
  if (wire.isReading() && data.numLaser > 0) laser.set(std::move(data));
}

void ioBumper(BoxWire& wire, Bumper& bumper) {
  BumperData data = bumper.getBumperData();
  wire.io(data.bumper, "bumper");
  wire.io(data.state, "bumper");
  wire.io(data.timeStamp, "bumper");
  if (wire.isReading()) bumper.set(data);
}

void ioClock(BoxWire& wire, SimClock& clock) {
  int64_t utime = clock.utime();
  wire.io(utime, "clock");
  if (wire.isReading()) clock.set(utime);
}

void ioMotorCommands(BoxWire& wire, Motors& motors) {
  double v = motors.getV(), w = motors.getW(), l = motors.getL();
  wire.io(v, "motors");
  wire.io(w, "motors");
  wire.io(l, "motors");
  if (!wire.isReading()) return;
  motors.sendV(v);
  motors.sendW(w);
  motors.sendL(l);
}

void ioBelief(BoxWire& wire, Belief& belief, int64_t& map_version_sent) {
  bool has_pose = belief.hasPose();
  double x_m = belief.x_m(), y_m = belief.y_m(), yaw_rad = belief.yaw_rad();
  wire.io(has_pose, "belief");
  wire.io(x_m, "belief");
  wire.io(y_m, "belief");
  wire.io(yaw_rad, "belief");
  if (wire.isReading() && has_pose) belief.setPose(x_m, y_m, yaw_rad);
  bool new_map = !wire.isReading() && belief.mapVersion() != map_version_sent;
  wire.io(new_map, "belief");
  if (!new_map) return;
  BeliefMap map = wire.isReading() ? BeliefMap{} : belief.map();
  wire.io(map.width, "belief map");
  wire.io(map.height, "belief map");
  wire.io(map.resolution_m, "belief map");
  wire.io(map.origin_x_m, "belief map");
  wire.io(map.origin_y_m, "belief map");
  wire.ioVector(map.cells, kMaxMapCells, "belief map");
  if (wire.isReading()) {
    belief.setMap(std::move(map));  // what the algorithm's end accepted, so valid here too
  } else {
    map_version_sent = belief.mapVersion();
  }
}

}  // namespace aula::component
