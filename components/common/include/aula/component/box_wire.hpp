#pragma once
// The bytes that cross between a component and its algorithm's own process (algorithm_box.hpp):
// one archive that either writes or reads, so that an exercise says once what crosses (its
// exchange functions, called with a writing wire at one end and a reading wire at the other) and
// both ends agree by construction. Plain little-endian bytes of one machine: both ends are the
// same binary. Reading is bounded: a short message, a count past its cap or bytes left over throw
// BoxWireError naming what was being read.

#include <aula/component/devices.hpp>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace aula::component {

class BoxWireError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class BoxWire {
 public:
  static BoxWire writing() { return BoxWire(std::string(), false); }
  static BoxWire reading(std::string bytes) { return BoxWire(std::move(bytes), true); }

  bool isReading() const { return reading_; }

  // Numbers and flags: written from, or read into, `value`.
  template <class T, class = std::enable_if_t<std::is_arithmetic_v<T>>>
  void io(T& value, const char* what) {
    ioBytes(&value, sizeof value, what);
  }
  // Text of at most `max_bytes` (a longer one is cut when written, refused when read).
  void io(std::string& text, size_t max_bytes, const char* what);
  // Plain values, at most `max_count` of them.
  template <class T>
  void ioVector(std::vector<T>& values, size_t max_count, const char* what) {
    static_assert(std::is_trivially_copyable_v<T>);
    uint64_t count = values.size();
    io(count, what);
    if (count > max_count) throw BoxWireError(std::string(what) + ": " + std::to_string(count) + " values, at most " +
                                              std::to_string(max_count));
    if (reading_) values.resize(count);
    if (count > 0) ioBytes(values.data(), count * sizeof(T), what);
  }
  void ioBytes(void* data, size_t n, const char* what);

  // The bytes written so far (a writing wire).
  const std::string& bytes() const { return bytes_; }
  // A reading wire read to its end; else BoxWireError (`what`: the message).
  void expectEnd(const char* what) const;

 private:
  BoxWire(std::string bytes, bool reading) : bytes_(std::move(bytes)), reading_(reading) {}
  std::string bytes_;
  size_t at_ = 0;
  bool reading_;
};

// The devices every exercise's API is made of. Sensors cross to the algorithm, commands and
// beliefs back.
void ioPose(BoxWire& wire, Pose3d& pose);
void ioLaser(BoxWire& wire, Laser& laser);
void ioBumper(BoxWire& wire, Bumper& bumper);
void ioClock(BoxWire& wire, SimClock& clock);
// The commands as they stand (v, w, l): what the algorithm may read back, and what it sent.
// Never non-finite here: the end that received a non-finite command counted and zeroed it.
void ioMotorCommands(BoxWire& wire, Motors& motors);
// What the algorithm believes: its pose every time, its map only when it set a new one since
// `map_version_sent` (updated at both ends, so the map crosses once per setMap).
void ioBelief(BoxWire& wire, Belief& belief, int64_t& map_version_sent);

}  // namespace aula::component
