// aula replay FILE.lcmlog: aula-replay (a Qt program; `aula` links no Qt), with the same arguments.
#include "commands.hpp"
#include "run_settings.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <unistd.h>

namespace aula::commands {
namespace {

int replayLog(const cli::Arguments& args) {
  const std::string program = binDir() + "/aula-replay";
  std::vector<std::string> words = {program, args.positional(0)};
  for (const std::string& option : args.givenOptions()) words.push_back(args.spelled(option));
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  execv(program.c_str(), argv.data());
  throw std::runtime_error("cannot start " + program + ": " + std::strerror(errno));
}

}  // namespace

cli::Command replay() {
  cli::Command c("replay", "play a recorded run back into the exercise's windows (pause, speed, time slider)");
  c.positionals = {{"FILE.lcmlog", "the recorded run (`aula run --record`)"}};
  c.options.add(cli::numberOption("speed", config::SettingType::Double, "", 0, 1000, "playback speed (x real time, default 1)", true))
      .add(cli::valueOption("lcm-url", "URL", "the bus the windows listen on (default: a private one)"))
      .add(cli::valueOption("report", "FILE.json", "the referee window's report at the end of the log"))
      .add(cli::valueOption("screenshot", "FILE.png", "a picture of the windows at --screenshot-at, then quit"))
      .add(cli::numberOption("screenshot-at", config::SettingType::Double, "s", 0, 1e7, "the sim time of --screenshot"));
  c.run = replayLog;
  return c;
}

}  // namespace aula::commands
