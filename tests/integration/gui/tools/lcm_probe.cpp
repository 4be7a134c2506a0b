// aula-test-lcm-probe URL WALL_SECONDS: what the GUI tests read off the bus, as text lines.
//   CLOCK <wall_s> <sim_s>                      every SIM_CLOCK tick
//   STATUS <channel> <wall_s> sim=<s> gen=<g> started=<0|1> elapsed=<s> left=<s> finished=<0|1> ending=<...>; summary=<...>
//   POSE <channel> <wall_s> <sim_s> <x_m> <y_m>  the first pose of each sim second
// It ends after WALL_SECONDS (or SIGTERM). The windows under test are driven with xdotool;
// this is how the test sees what the processes tell each other.
#include <aula/lcm/bus.hpp>
#include <aula/pose3d_t.hpp>
#include <aula/referee_status_t.hpp>
#include <aula/sim_clock_t.hpp>

#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

namespace {

volatile std::sig_atomic_t stop_requested = 0;
const auto started = std::chrono::steady_clock::now();

double wallS() { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); }

bool endsWith(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

class Probe {
 public:
  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    if (channel == aula::lcmbus::kClockChannel) {
      aula::sim_clock_t clock;
      if (clock.decode(buffer->data, 0, buffer->data_size) < 0) return;
      std::printf("CLOCK %.3f %.3f\n", wallS(), clock.utime / 1e6);
    } else if (endsWith(channel, "_REFEREE")) {
      aula::referee_status_t s;
      if (s.decode(buffer->data, 0, buffer->data_size) < 0) return;
      std::printf("STATUS %s %.3f sim=%.3f gen=%d started=%d elapsed=%.3f left=%.3f finished=%d ending=%s; summary=%s\n",
                  channel.c_str(), wallS(), s.utime / 1e6, s.generation, s.started ? 1 : 0, s.elapsed_s, s.time_left_s,
                  s.finished ? 1 : 0, s.ending.c_str(), s.summary.c_str());
    } else if (endsWith(channel, "_POSE")) {
      aula::pose3d_t pose;
      if (pose.decode(buffer->data, 0, buffer->data_size) < 0) return;
      const long long second = pose.utime / 1'000'000;
      auto seen = last_second_.find(channel);
      if (seen != last_second_.end() && seen->second == second) return;
      last_second_[channel] = second;
      std::printf("POSE %s %.3f %.3f %.4f %.4f\n", channel.c_str(), wallS(), pose.utime / 1e6, pose.x, pose.y);
    } else {
      return;
    }
    std::fflush(stdout);
  }

 private:
  std::map<std::string, long long> last_second_;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: aula-test-lcm-probe URL WALL_SECONDS\n");
    return 2;
  }
  const double duration_s = std::atof(argv[2]);
  std::signal(SIGTERM, [](int) { stop_requested = 1; });
  lcm::LCM bus(argv[1]);  // a stock client: it sees every channel of the run's URL
  if (!bus.good()) {
    std::fprintf(stderr, "aula-test-lcm-probe: cannot open %s\n", argv[1]);
    return 1;
  }
  Probe probe;
  bus.subscribe(".*", &Probe::onMessage, &probe)->setQueueCapacity(aula::lcmbus::kQueueCapacity);
  while (!stop_requested && wallS() < duration_s) bus.handleTimeout(50);
  return 0;
}
