#include "run_recorder.hpp"

#include <aula/config/config.hpp>
#include <aula/lcm/bus.hpp>
#include <aula/config/paths.hpp>
#include <aula/lcm/log_replay.hpp>
#include <aula/world/world_spec.hpp>

#include <csignal>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <thread>

#include <unistd.h>

namespace aula::launcher {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

constexpr auto kStartTimeout = 5s;      // lcm-logger creates its file and hears the record by then
constexpr auto kRepublishPeriod = 300ms;  // longer than lcm-logger's 100 ms flush: rarely a duplicate
constexpr auto kDrain = 200ms;          // the last datagrams of the run reach the logger

// lcm-logger's own receive buffer: a lockstep run as fast as possible sends bursts.
std::string withLargeReceiveBuffer(const std::string& url) {
  if (url.rfind("udpm://", 0) != 0 || url.find("recv_buf_size=") != std::string::npos) return url;
  return url + (url.find('?') == std::string::npos ? "?" : "&") + "recv_buf_size=4194304";
}

}  // namespace

aula::run_record_t runRecord(const settings::Exercise& exercise, const std::string& world_path, int64_t seed,
                             const config::Config& referee_settings) {
  aula::run_record_t record;
  record.exercise = exercise.name;
  record.referee = exercise.referee;
  record.world = fs::path(world_path).filename().string();
  record.world_path = fs::absolute(world_path).string();
  record.world_sha256 = world::sha256OfFile(world_path);
  record.seed = seed;
  for (const std::string& key : referee_settings.keys()) {
    // The world and the bus are the run's, not the grading's: regrade names its own.
    if (key == exercise.section + ".World" || key == "Aula.LcmUrl") continue;
    if (exercise.referee_settings->declares(key)) record.settings.push_back(key + "=" + referee_settings.getString(key));
  }
  record.num_settings = static_cast<int32_t>(record.settings.size());
  return record;
}

int regrade(const std::string& log_path, const std::string& report_path, const std::string& bin_dir) {
  const aula::run_record_t record = lcmbus::readRunRecord(log_path);
  const settings::Exercise* exercise = settings::exerciseNamed(record.exercise);
  if (exercise == nullptr || exercise->referee != record.referee) {
    throw config::ConfigError(log_path + ": recorded for exercise '" + record.exercise + "' graded by '" +
                              record.referee + "', which this Aula does not have");
  }
  // The recorded path, else the world of that name in the data folder; the referee refuses a
  // world whose SHA-256 is not the recorded simulator's.
  std::error_code error;
  const std::string world = fs::is_regular_file(record.world_path, error)
                                ? record.world_path
                                : config::resolveWorldPath(record.world, log_path + ": world");
  std::vector<std::string> args = {bin_dir + "/" + exercise->referee, "--headless",
                                   "--replay=" + fs::absolute(log_path).string(),
                                   "--" + exercise->section + ".World=" + world};
  for (const std::string& setting : record.settings) args.push_back("--" + setting);
  if (!report_path.empty()) args.push_back("--report=" + report_path);
  process::ChildProcess referee(args);
  return referee.wait(std::chrono::hours(24 * 365)).value_or(1);
}

void RunRecorder::checkPath(const std::string& path) {
  const fs::path file = fs::absolute(path);
  const fs::path folder = file.parent_path();
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    throw config::ConfigError("--record=" + path + ": the folder " + folder.string() + " does not exist");
  }
  if (access(folder.c_str(), W_OK) != 0) {
    throw config::ConfigError("--record=" + path + ": the folder " + folder.string() + " is not writable");
  }
  if (fs::is_directory(file, error)) throw config::ConfigError("--record=" + path + ": is a folder, not a file");
}

RunRecorder::RunRecorder(const std::string& path, const std::string& url, const aula::run_record_t& record)
    : path_(path) {
  // A file left from before would look like a logger that is already writing.
  std::error_code ignored;
  fs::remove(path_, ignored);
  try {
    logger_ = std::make_unique<process::ChildProcess>(
        std::vector<std::string>{"lcm-logger", "--quiet", "--force", "--lcm-url=" + withLargeReceiveBuffer(url), path_},
        "/dev/null", "/dev/null");
  } catch (const std::runtime_error& e) {
    throw config::ConfigError(std::string("--record needs lcm-logger (Debian package liblcm-bin): ") + e.what());
  }
  const auto deadline = std::chrono::steady_clock::now() + kStartTimeout;
  auto checkLogger = [&](const char* waiting_for) {
    if (const auto code = logger_->poll()) {
      throw std::runtime_error("lcm-logger ended (exit code " + std::to_string(*code) + ") before " + waiting_for);
    }
    if (std::chrono::steady_clock::now() > deadline) {
      throw std::runtime_error("lcm-logger did not " + std::string(waiting_for) + " within 5 s");
    }
    std::this_thread::sleep_for(10ms);
  };
  while (!fs::exists(path_)) checkLogger(("creating " + path_).c_str());
  // The file exists before lcm-logger subscribes: the record counts only once it is in the log.
  const auto bus = lcmbus::openBus(url);
  auto published = std::chrono::steady_clock::time_point{};
  while (!lcmbus::findRunRecord(path_)) {
    if (std::chrono::steady_clock::now() - published >= kRepublishPeriod) {
      bus->publish(lcmbus::kRunChannel, &record);
      published = std::chrono::steady_clock::now();
    }
    checkLogger(("recording the run's " + std::string(lcmbus::kRunChannel) + " message on " + url).c_str());
  }
}

RunRecorder::~RunRecorder() { stop(); }

void RunRecorder::stop() {
  if (!logger_) return;
  std::this_thread::sleep_for(kDrain);
  kill(logger_->pid(), SIGINT);  // lcm-logger writes what it holds and closes the file
  const auto code = logger_->wait(5s);
  if (!code) logger_->stop();
  logger_.reset();
  std::error_code error;
  const auto bytes = fs::file_size(path_, error);
  if (code && *code == 0 && !error) {
    std::cerr << "aula: run recorded in " << path_ << " (" << bytes / 1024 << " KiB); grade it again with `aula regrade "
              << path_ << "`\n";
  } else {
    std::cerr << "aula: lcm-logger did not end cleanly (" << (code ? "exit code " + std::to_string(*code) : "killed")
              << "): " << path_ << " may be incomplete\n";
  }
}

}  // namespace aula::launcher
