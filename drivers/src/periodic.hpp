#pragma once
// A publication schedule on simulated time: due at every multiple of the period.

#include <cmath>
#include <cstdint>

namespace aula::drivers {

class Periodic {
 public:
  Periodic() = default;
  explicit Periodic(double rate_hz)
      : period_us_(rate_hz > 0 ? static_cast<int64_t>(std::llround(1e6 / rate_hz)) : 0) {}
  // True once per period; the first call (t = 0) is due.
  bool due(int64_t sim_time_us) {
    if (period_us_ <= 0 || sim_time_us < next_us_) return false;
    next_us_ = (sim_time_us / period_us_ + 1) * period_us_;
    return true;
  }
  void reset() { next_us_ = 0; }
  int64_t periodUs() const { return period_us_; }

 private:
  int64_t period_us_ = 0;
  int64_t next_us_ = 0;
};

}  // namespace aula::drivers
