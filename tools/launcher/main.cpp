// aula run EXERCISE [--headless] [--world=FILE] [--lockstep] [--rtf=X] [--seed=N]
//                   [--duration=S] [--lcm-url=URL] [--Key=value ...]
// Starts the simulator and the exercise's processes (like the original's three terminals),
// waits for the run to end and stops everything cleanly: it never leaves a process behind
// (children die with it: PR_SET_PDEATHSIG) and exits non-zero if any process failed.
#include <aula/config/config.hpp>
#include <aula/process/child_process.hpp>

#include <csignal>
#include <cstdlib>
#include <iostream>
#include <filesystem>
#include <map>
#include <memory>
#include <thread>

#include <sys/signalfd.h>
#include <unistd.h>

namespace {

struct Exercise {
  std::string world;        // relative to the source tree
  std::string config;       // the exercise's .cfg, relative to the source tree
  std::string cfg_prefix;   // its keys' section, e.g. "TeleTaxi" (for --algorithm)
  std::string component;    // executable in the build's bin folder
  std::string referee;      // "" when the exercise has none
  std::string description;
};

std::map<std::string, Exercise> exercises() {
  return {
      {"demo", {"worlds/vacuum.world", "config/demo.cfg", "Demo", "aula-demo-client", "",
                "the roomba bouncing around the house (no referee)"}},
      {"teletaxi", {"worlds/cityLarge.world", "config/teleTaxi.cfg", "TeleTaxi", "teletaxi", "teletaxi-referee",
                    "global navigation with Gradient Path Planning"}},
      {"vacuum", {"worlds/vacuum.world", "config/vacuumCleaner.cfg", "Vacuum", "vacuum-cleaner",
                  "vacuum-cleaner-referee", "clean the house without localization"}},
      {"autopark", {"worlds/autopark.world", "config/autopark.cfg", "Autopark", "autopark", "autopark-referee",
                    "find the free slot and park in parallel (--world=autopark_ackermann_1.3L.world: a car-like car, a tight slot)"}},
  };
}

constexpr const char* kUsage =
    "usage: aula run EXERCISE [--headless] [--world=FILE] [--algorithm=NAME] [--seed=N]\n"
    "                [--report=FILE.json] [--lockstep] [--rtf=X] [--duration=SECONDS] [--lcm-url=URL]\n"
    "                [--Key=value ...]\n"
    "  --headless  no windows; lockstep, as fast as possible; the run ends with the referee's mark\n"
    "exercises:\n";

std::string binDir(const char* argv0) {
  std::string self = argv0;
  char buffer[4096];
  const ssize_t n = readlink("/proc/self/exe", buffer, sizeof buffer - 1);
  if (n > 0) self.assign(buffer, n);
  const auto slash = self.rfind('/');
  return slash == std::string::npos ? "." : self.substr(0, slash);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace aula;
  const auto table = exercises();
  auto usage = [&] {
    std::cerr << kUsage;
    for (const auto& [name, ex] : table) std::cerr << "  " << name << "  " << ex.description << "\n";
    return 2;
  };
  try {
    auto cl = config::CommandLine::parse(argc, argv, {});
    cl.requireKnown({"headless", "world", "algorithm", "report", "lockstep", "rtf", "seed", "duration", "lcm-url", "help"});
    if (cl.flag("help")) return usage(), 0;
    if (cl.positional.size() != 2 || cl.positional[0] != "run") return usage();
    const auto it = table.find(cl.positional[1]);
    if (it == table.end()) {
      std::cerr << "aula: unknown exercise '" << cl.positional[1] << "'\n";
      return usage();
    }
    const Exercise& ex = it->second;
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    const bool no_display = (display == nullptr || *display == '\0') && (wayland == nullptr || *wayland == '\0');
    if (!cl.flag("headless") && no_display) {
      std::cerr << "aula: no display (DISPLAY is not set): running headless; the mark is printed at the end\n";
      cl.options["headless"] = "";
    }
    const std::string bin = binDir(argv[0]);
    const std::string source = AULA_SOURCE_DIR;

    // The world: a path from here, or from the source tree, or a file name in worlds/. The
    // clients get it too (Autopark's component and referee read the slot from it).
    std::string world = source + "/" + ex.world;
    if (cl.flag("world")) {
      world = cl.option("world");
      namespace fs = std::filesystem;
      if (!fs::path(world).is_absolute()) {
        if (fs::exists(world)) world = fs::absolute(world).string();
        else if (fs::exists(source + "/" + world)) world = source + "/" + world;
        else if (fs::exists(source + "/worlds/" + world)) world = source + "/worlds/" + world;
      }
      if (!fs::exists(world)) throw config::ConfigError("--world=" + cl.option("world") + ": no such world file");
    }

    std::vector<std::string> shared;  // options every process understands
    if (cl.flag("lcm-url")) shared.push_back("--lcm-url=" + cl.option("lcm-url"));
    for (const auto& [key, value] : cl.overrides) shared.push_back("--" + key + "=" + value);
    if (cl.flag("algorithm")) shared.push_back("--" + ex.cfg_prefix + ".Algorithm=" + cl.option("algorithm"));
    if (cl.flag("headless")) shared.push_back("--" + ex.cfg_prefix + ".Autostart=true");
    if (cl.flag("world")) shared.push_back("--" + ex.cfg_prefix + ".World=" + world);

    const size_t clients = ex.referee.empty() ? 1 : 2;
    std::vector<std::string> sim_args = {bin + "/aula-sim", world};
    if (cl.flag("lockstep") || cl.flag("headless")) {
      sim_args.push_back("--lockstep");
      sim_args.push_back("--Simulator.Lockstep.WaitForClients=" + std::to_string(clients));
    }
    if (cl.flag("headless") && !cl.flag("rtf")) sim_args.push_back("--rtf=0");
    if (cl.flag("rtf")) sim_args.push_back("--rtf=" + cl.option("rtf"));
    if (cl.flag("seed")) sim_args.push_back("--seed=" + cl.option("seed"));
    if (cl.flag("lcm-url")) sim_args.push_back("--lcm-url=" + cl.option("lcm-url"));
    for (const auto& [key, value] : cl.overrides) {
      if (key.rfind("Simulator.", 0) == 0 || key.rfind("Aula.", 0) == 0) sim_args.push_back("--" + key + "=" + value);
    }

    sigset_t mask;
    sigemptyset(&mask);
    sigaddset(&mask, SIGINT);
    sigaddset(&mask, SIGTERM);
    sigprocmask(SIG_BLOCK, &mask, nullptr);
    const int signal_fd = signalfd(-1, &mask, SFD_NONBLOCK | SFD_CLOEXEC);

    auto client_args = [&](const std::string& program) {
      std::vector<std::string> args = {bin + "/" + program, "--config=" + source + "/" + ex.config};
      if (cl.flag("headless")) args.push_back("--headless");
      args.insert(args.end(), shared.begin(), shared.end());
      return args;
    };
    std::vector<std::unique_ptr<process::ChildProcess>> children;
    children.push_back(std::make_unique<process::ChildProcess>(sim_args));
    auto component_args = client_args(ex.component);
    if (ex.referee.empty() && cl.flag("duration")) component_args.push_back("--duration=" + cl.option("duration"));
    children.push_back(std::make_unique<process::ChildProcess>(component_args));
    if (!ex.referee.empty()) {
      auto referee_args = client_args(ex.referee);
      if (cl.flag("report")) referee_args.push_back("--report=" + cl.option("report"));
      children.push_back(std::make_unique<process::ChildProcess>(referee_args));
    }

    // The run ends when the primary process (the last one: referee or client) ends, when any
    // process fails, or on Ctrl-C.
    int result = 0;
    signalfd_siginfo info;
    for (;;) {
      if (read(signal_fd, &info, sizeof info) == static_cast<ssize_t>(sizeof info)) {
        std::cerr << "aula: stopping\n";
        break;
      }
      bool finished = false;
      for (size_t i = 0; i < children.size(); ++i) {
        if (const auto code = children[i]->poll()) {
          if (*code != 0) {
            std::cerr << "aula: " << children[i]->name() << " exited with code " << *code << "\n";
            result = *code == 2 ? 2 : 1;
          }
          finished = finished || *code != 0 || i + 1 == children.size() || i == 0;
        }
      }
      if (finished) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    // Stop clients first (they send their last commands and leave lockstep), then the simulator.
    for (auto c = children.rbegin(); c != children.rend(); ++c) {
      const int code = (*c)->stop();
      if (code != 0 && code != 128 + SIGTERM && code != 128 + SIGINT && result == 0 && (*c)->name() != sim_args[0]) {
        std::cerr << "aula: " << (*c)->name() << " stopped with code " << code << "\n";
      }
    }
    return result;
  } catch (const config::ConfigError& e) {
    std::cerr << "aula: " << e.what() << "\n";
    return usage();
  } catch (const std::exception& e) {
    std::cerr << "aula: " << e.what() << "\n";
    return 1;
  }
}
