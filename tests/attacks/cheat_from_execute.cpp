// A student's vacuum algorithm that cheats from inside execute(): it stays still, and at 10 s of
// sim time it opens the run's bus itself (the URL from its own command line, as a cheater would
// find it) and sends forged poses sweeping the whole house, then a SIM_CONTROL teleport. In a
// graded run neither may count: it is graded as the still robot it is, and the report says
// what it tried.
#include "forgery.hpp"

#include <aula/sim_control_t.hpp>
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <lcm/lcm-cpp.hpp>

#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

namespace aula::vacuum {
namespace {

// --lcm-url=... from /proc/self/cmdline, else LCM's default.
// The run's bus, from this process's command line, or its parent's (the component's, when the
// algorithm runs in a process of its own: any process may read it).
std::string runUrl(const std::string& process = "self") {
  std::ifstream in("/proc/" + process + "/cmdline", std::ios::binary);
  const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string flag = "--lcm-url=";
  for (size_t at = 0; at < all.size(); at = all.find('\0', at) + 1) {
    if (all.compare(at, flag.size(), flag) == 0) return all.substr(at + flag.size(), all.find('\0', at) - at - flag.size());
    if (all.find('\0', at) == std::string::npos) break;
  }
  return process == "self" ? runUrl(std::to_string(::getppid())) : "";
}

class CheatFromExecute : public VacuumAlgorithm {
 public:
  void execute(VacuumApi& api) override {
    api.motors.sendV(0.0);
    api.motors.sendW(0.0);
    sim_time_s_ += api.period_s;
    if (cheated_ || sim_time_s_ < 10.0) return;
    cheated_ = true;
    lcm::LCM bus(runUrl());
    const auto utime = static_cast<int64_t>(sim_time_s_ * 1e6) + 100000;
    for (const auto& pose : aula::attacks::houseSweep(utime)) bus.publish("ROOMBA_POSE", &pose);
    aula::sim_control_t teleport{};
    teleport.command = aula::sim_control_t::SET_POSE;
    teleport.robot = "roomba";
    teleport.x = 3.0;
    teleport.y = 3.0;
    teleport.auth_seq = 1;
    bus.publish("SIM_CONTROL", &teleport);
  }

 private:
  double sim_time_s_ = 0;
  bool cheated_ = false;
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<CheatFromExecute>(); }

}  // namespace aula::vacuum
