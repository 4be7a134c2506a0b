#pragma once
// What an attacker forges, shared by the attack client (a process of its own on the run's bus)
// and the cheating plugin (the same attack from inside the student's execute()).

#include <aula/pose3d_t.hpp>

#include <cstdint>
#include <vector>

namespace aula::attacks {

// The house of worlds/vacuum.world inside its walls (`aula check-world`), in metres.
constexpr double kHouseMinX = -3.8, kHouseMaxX = 5.2, kHouseMinY = -3.4, kHouseMaxY = 5.8;

// Poses every 25 cm over the whole house, stamped `utime`: graded, they would mark nearly all
// of its floor cleaned (the do-nothing template's 0.2 % coverage became 99 % this way).
inline std::vector<aula::pose3d_t> houseSweep(int64_t utime) {
  constexpr double kStepM = 0.25;
  std::vector<aula::pose3d_t> poses;
  for (double y = kHouseMinY; y <= kHouseMaxY; y += kStepM) {
    for (double x = kHouseMinX; x <= kHouseMaxX; x += kStepM) {
      aula::pose3d_t msg{};
      msg.utime = utime;
      msg.x = x;
      msg.y = y;
      msg.q0 = 1.0;
      msg.auth_seq = static_cast<int64_t>(poses.size()) + 1000000;  // "newer" than the simulator's
      poses.push_back(msg);
    }
  }
  return poses;
}

}  // namespace aula::attacks
