// aula-replay FILE.lcmlog [--speed=X] [--lcm-url=URL] [--report=FILE.json] [--screenshot=FILE.png --screenshot-at=S]
// (`aula replay FILE.lcmlog` runs it.) Plays a run recorded with `aula run --record` back into
// the exercise's component and referee windows, view-only, with pause, a speed factor and a
// time slider. The log says which exercise, world and settings it was (run_record_t).
#include "log_player.hpp"
#include "replay_window.hpp"

#include <aula/app/main_window.hpp>
#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>
#include <aula/desktop/window_layout.hpp>
#include <aula/desktop/work_area.hpp>
#include <aula/lcm/log_replay.hpp>
#include <aula/process/child_process.hpp>
#include <aula/process/guarded_main.hpp>
#include <aula/settings/tables.hpp>

#include <QApplication>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <random>
#include <sstream>

#include <unistd.h>

namespace {

using aula::config::ConfigError;

constexpr const char* kUsage =
    "usage: aula replay FILE.lcmlog [--speed=X] [--lcm-url=URL] [--report=FILE.json]\n"
    "                   [--screenshot=FILE.png --screenshot-at=SIM_SECONDS]\n"
    "  plays a run recorded with `aula run --record=FILE.lcmlog` into the exercise's windows (view only);\n"
    "  `aula regrade FILE.lcmlog` grades it again, headless\n";

// Where the recorded component said which algorithm ran: the referee's recorded setting, else its default.
std::string episodeChannel(const aula::run_record_t& record, const aula::settings::Exercise& ex) {
  const std::string key = ex.section + ".Episode.Channel";
  for (const std::string& setting : record.settings) {
    if (setting.rfind(key + "=", 0) == 0) return setting.substr(key.size() + 1);
  }
  return ex.referee_settings->find(key)->default_value;
}

std::string selfDir() {
  std::error_code error;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? "." : self.parent_path().string();
}

// A viewer's effective settings, as it will resolve them: the exercise's .cfg and its command line.
aula::config::Config viewerSettings(const aula::settings::Exercise& ex, const aula::config::SettingsTable& table,
                                    const std::vector<std::string>& argv) {
  aula::config::Config file = aula::config::Config::fromFile(aula::config::dataPath(ex.config_file));
  for (const std::string& arg : argv) {
    const auto equals = arg.find('=');
    if (arg.rfind("--", 0) == 0 && equals != std::string::npos && arg.find('.') < equals) {
      file.set(arg.substr(2, equals - 2), arg.substr(equals + 1), "aula replay");
    }
  }
  std::vector<const aula::config::SettingsTable*> siblings;
  for (const auto* other : ex.tables()) {
    if (other != &table) siblings.push_back(other);
  }
  return table.resolve(file, siblings);
}

// The viewers' windows and then the player's, in one layout on the screen (aula/desktop): each
// viewer's command line gets its windows' places; the player's frame corner is returned.
std::optional<aula::desktop::Point> layOutWindows(const aula::settings::Exercise& ex,
                                                  std::vector<std::vector<std::string>>& lines) {
  const auto work_area = aula::desktop::workArea();
  if (!work_area) return std::nullopt;
  std::vector<aula::desktop::WindowedProcess> viewers;
  for (const auto& line : lines) {
    const auto& table = aula::settings::tableOf(std::filesystem::path(line.front()).filename().string());
    viewers.push_back({&table, viewerSettings(ex, table, line)});
  }
  const auto layout = aula::desktop::layOutRun(
      *work_area, viewers, {{aula::replay::ReplayWindow::kWidthPx, aula::replay::ReplayWindow::kHeightPx}});
  for (size_t i = 0; i < lines.size(); ++i) lines[i].insert(lines[i].end(), layout.arguments[i].begin(), layout.arguments[i].end());
  return layout.extras.front();
}

// The component and the referee of the recorded run, as view-only windows on the replay's bus.
class Viewers {
 public:
  // `report`: where the referee window writes its report at the end of the replayed episode;
  // `algorithm`: the recorded one, which the component's window names.
  Viewers(const aula::run_record_t& record, const aula::settings::Exercise& ex, const std::string& url,
          const std::string& report, const std::string& algorithm) {
    const std::string bin = selfDir();
    std::string world = record.world_path;
    if (!std::filesystem::is_regular_file(world)) world = record.world;
    for (const std::string& program : {ex.component, ex.referee}) {
      std::vector<std::string> argv = {bin + "/" + program, "--" + ex.section + ".World=" + world, "--lcm-url=" + url};
      const auto& table = aula::settings::tableOf(program);
      for (const std::string& setting : record.settings) {
        const auto equals = setting.find('=');
        if (equals != std::string::npos && table.declares(setting.substr(0, equals))) argv.push_back("--" + setting);
      }
      if (program == ex.referee && !report.empty()) argv.push_back("--report=" + report);
      // The viewer shows the replayed referee's clock, not the recorded one's (which the log
      // also plays, and older logs lack): the two talk on a channel of their own.
      argv.push_back("--" + ex.section + ".RefereeStatus.Channel=AULA_REPLAY_REFEREE_STATUS");
      // Both view a replay: neither ends when the replay's clock pauses (LockstepClient::simulatorGone).
      argv.push_back("--view-only=" + algorithm);
      if (program == ex.component) {
        // The viewer's own episode messages must not reach the referee, which grades the
        // recorded ones: they go to a channel nobody listens to.
        argv.push_back("--" + ex.section + ".Episode.Channel=AULA_REPLAY_VIEWER_EPISODE");
      }
      lines_.push_back(argv);
    }
    player_corner_ = layOutWindows(ex, lines_);
    start();
  }
  // Where the player's window goes, after the viewers' (nullopt: no display to lay out).
  std::optional<aula::desktop::Point> playerCorner() const { return player_corner_; }
  void start() {
    for (const auto& argv : lines_) children_.push_back(std::make_unique<aula::process::ChildProcess>(argv));
  }
  void restart() {
    children_.clear();  // each stops its process
    start();
  }

 private:
  std::vector<std::vector<std::string>> lines_;
  std::vector<std::unique_ptr<aula::process::ChildProcess>> children_;
  std::optional<aula::desktop::Point> player_corner_;
};

}  // namespace

int main(int argc, char** argv) {
  return aula::process::guardedMain("aula replay", [&]() -> int {
    const auto cl = aula::config::CommandLine::parse(argc, argv, {});
    cl.requireKnown({"speed", "lcm-url", "screenshot", "screenshot-at", "report", "help"});
    if (cl.flag("help")) {
      std::cout << kUsage;
      return 0;
    }
    if (cl.positional.size() != 1) throw ConfigError(std::string("expected one log file\n") + kUsage);
    const std::string log = cl.positional[0];
    const aula::run_record_t record = aula::lcmbus::readRunRecord(log);
    const aula::settings::Exercise* ex = aula::settings::exerciseNamed(record.exercise);
    if (ex == nullptr || ex->referee_settings == nullptr) {
      throw ConfigError(log + ": recorded exercise '" + record.exercise + "' is not one this Aula has");
    }
    const char* display = std::getenv("DISPLAY");
    if (display == nullptr || *display == '\0') {
      throw ConfigError("no display (DISPLAY is not set): a replay needs windows; `aula regrade " + log +
                        "` grades the log headless");
    }
    const double speed = cl.optionDouble("speed", 1.0);
    if (!(speed > 0)) throw ConfigError("--speed=" + cl.option("speed") + ": a factor > 0");
    // A private port: the replayed truth must never reach a live run (engineering.md: ports, not groups).
    std::random_device random;
    const std::string url = cl.option("lcm-url", "udpm://239.255.76.67:" + std::to_string(40000 + random() % 20000) +
                                                     "?ttl=0&recv_buf_size=4194304");
    aula::lcmbus::Bus bus(url);
    aula::replay::LogPlayer player(log, [&](const lcm::LogEvent& e) { bus.publish(e.channel, e.data, e.datalen); },
                                   episodeChannel(record, *ex));
    const std::string algorithm = player.algorithm().empty() ? "an algorithm never started" : player.algorithm();
    std::ostringstream recorded;
    recorded << record.exercise << " on " << record.world << ", seed " << record.seed << ", algorithm " << algorithm;
    std::cerr << "aula replay: " << log << ": " << recorded.str() << ", " << player.durationUs() / 1e6 << " s of sim time\n";
    Viewers viewers(record, *ex, url, cl.option("report"), algorithm);
    QApplication app(argc, argv);
    const std::string file = std::filesystem::path(log).filename().string();
    aula::replay::ReplayWindow window(player, [&] { viewers.restart(); }, QString::fromStdString(file + " - " + algorithm),
                                      QString::fromStdString("Recorded: " + recorded.str()), speed);
    aula::app::placeWindow(window, {{aula::replay::ReplayWindow::kWidthPx, aula::replay::ReplayWindow::kHeightPx},
                                    viewers.playerCorner()}, "aula replay");
    window.show();
    if (cl.flag("screenshot")) {
      window.screenshotAt(QString::fromStdString(cl.option("screenshot")), cl.optionDouble("screenshot-at", 10.0));
    }
    return app.exec();
  });
}
